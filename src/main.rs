//! The `plcsh` binary: all behaviour lives in the library (`plcsh::cli`).

fn main() {
    std::process::exit(plcsh::cli::main());
}
