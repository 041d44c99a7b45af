//! The `plcsh` binary: all behaviour lives in the library (`plcsh::cli`).

/// The process allocator: every poll allocates small values for a moment (the values read, a
/// request's frame), and mimalloc's allocate/free path is several times shorter than glibc's
/// (BENCHMARKS.md, "Simulator").
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    std::process::exit(plcsh::cli::main());
}
