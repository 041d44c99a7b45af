//! `plcsh run SCRIPT.lua [ARGS…]`: runs a Lua script against the session the flags describe
//! (`--device`, `--time stepped`, `--model`). Exit status: 0 when the script finished, 1 when
//! it failed (the report names file:line, with a traceback), 130 when Ctrl-C stopped it
//! (after its `plcsh.on_abort` handlers ran).

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
    /// Arguments for the script (`arg[1]`…, and `...`): everything after the script, even words
    /// that look like plcsh flags (see `split_script_args`). Flags for plcsh go before the script.
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
        Err(f) => {
            // The failure report: a JSON object on stdout with --json, text on stderr otherwise.
            let _ = std::io::stdout().flush();
            let _ = if style.json {
                writeln!(std::io::stdout().lock(), "{}", f.json("run"))
            } else {
                write!(std::io::stderr().lock(), "{}", f.human())
            };
            if f.interrupted() {
                130
            } else {
                1
            }
        }
    }
}
