//! `plcsh run SCRIPT.lua [ARGS…]`: runs a Lua script against the session the flags describe
//! (`--device`, `--time stepped`, `--model`). Exit status: 0 when the script finished, 1 when
//! it failed (the report names file:line, with a traceback), 130 when Ctrl-C stopped it
//! (after its `plcsh.on_abort` handlers ran), 143/129 for SIGTERM/SIGHUP (the same), and
//! the status `os.exit(code)` asked for (also after the handlers).

use crate::output::Style;
use crate::script::Engine;
use crate::shell::Shell;
use clap::Args;
use std::io::Write;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct RunArgs {
    /// The Lua script.
    pub script: PathBuf,
    /// Arguments for the script (`arg[1]`…, and `...`). Flags for plcsh go before `run`.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
    pub args: Vec<String>,
}

/// Runs the script; returns the exit status.
pub fn main(shell: &mut Shell, args: &RunArgs, style: Style) -> i32 {
    let engine = match Engine::for_shell(shell) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("cannot start Lua: {e}");
            return 1;
        }
    };
    match engine.run_file(shell, &args.script, &args.args) {
        Ok(()) => 0,
        // `os.exit(code)`: the handlers have run; exit with the status asked for.
        Err(_) if engine.exit_code().is_some() => engine.exit_code().unwrap_or(0),
        Err(f) => {
            let mut out = std::io::stdout().lock();
            let _ = if style.json { writeln!(out, "{}", f.json("run")) } else { write!(out, "{}", f.human()) };
            let _ = out.flush();
            if f.interrupted() {
                130
            } else {
                1
            }
        }
    }
}
