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
    /// Run a script someone else wrote: no os.execute, io.popen, os.remove/rename/exit, C
    /// libraries or debug library; files written only under --write-dir.
    #[arg(long)]
    pub sandbox: bool,
    /// With --sandbox: the directory the script may write files in (none without it).
    #[arg(long, value_name = "DIR", requires = "sandbox")]
    pub write_dir: Option<PathBuf>,
    /// Run the script on every device of this fleet at once, each in a Lua state of its own (docs/fleets.md).
    #[arg(short = 'f', long = "fleet", value_name = "NAME")]
    pub fleet: Option<String>,
    /// Write a commissioning report: this HTML file and its JSON twin beside it (docs/commissioning.md).
    /// The commission runner writes its checklist there; any other script gets the devices and
    /// the log of every write it made.
    #[arg(long, value_name = "FILE")]
    pub report: Option<String>,
    /// The Lua script.
    pub script: PathBuf,
    /// Arguments for the script (`arg[1]`…, and `...`): everything after the script, even words
    /// that look like plcsh flags. Flags for plcsh go before the script.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
    pub args: Vec<String>,
}

impl RunArgs {
    /// The rules of `--sandbox`: the script's folder is read, `--write-dir` written.
    pub fn confinement(&self) -> crate::confine::Confinement {
        let dir = match self.script.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        crate::confine::Confinement::new(vec![dir], self.write_dir.clone())
    }
}

/// Runs the script; returns the exit status. With `--json` the run ends with one summary
/// object: ok, the script, checks passed and failed, the duration, and the error (kind,
/// message, `where` file:line, traceback) when it failed — one line a grader can read.
pub fn main(shell: &mut Shell, args: &RunArgs, style: Style) -> i32 {
    let engine = match Engine::for_shell(shell) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("{}", crate::msg!("cli-run-no-lua", reason = e.to_string()));
            return 1;
        }
    };
    let mut env = None;
    if args.sandbox {
        // The script's folder is read, the write directory written; the session holds the
        // rules (set before any device opened, `cli::build_session`), so devices, snapshots
        // and shell commands follow them too.
        let rules = shell.session.confine.clone().unwrap_or_else(|| std::sync::Arc::new(args.confinement()));
        let setup = || -> mlua::Result<mlua::Table> {
            crate::script::sandbox::apply(engine.lua(), rules.clone())
                .map_err(|e| mlua::Error::runtime(format!("apply: {e}")))?;
            crate::script::paths::confine(engine.lua(), None)
                .map_err(|e| mlua::Error::runtime(format!("paths: {e}")))?;
            crate::script::sandbox::student_env(engine.lua(), rules.clone())
                .map_err(|e| mlua::Error::runtime(format!("env: {e}")))
        };
        match setup() {
            Ok(e) => env = Some(e),
            Err(e) => {
                eprintln!("{}", crate::msg!("cli-run-no-sandbox", reason = e.to_string()));
                return 1;
            }
        }
        shell.confine(rules);
    }
    if let Some(path) = &args.report {
        let begun = crate::script::report::begin(shell);
        let lua = engine.lua();
        if let Err(e) = crate::script::report::remember(lua, &begun)
            .and_then(|_| lua.set_named_registry_value(crate::script::report::PATH_KEY, path.as_str()))
        {
            eprintln!("{}", crate::msg!("report-cannot-write", file = path.as_str(), reason = e.to_string()));
            return 1;
        }
    }
    let start = std::time::Instant::now();
    let mut result = engine.run_file_in(shell, &args.script, &args.args, env.as_ref());
    let duration = start.elapsed();
    if let Some(path) = &args.report {
        if let Err(e) = report_if_none(&engine, shell, args, path, &result) {
            if result.is_ok() {
                result = Err(crate::script::Failure { error: e, location: None, traceback: None });
            } else {
                eprintln!("{e}");
            }
        }
        shell.session.write_log.stop();
    }
    let _ = std::io::stdout().flush();
    if style.json {
        let mut summary = match &result {
            Ok(()) => serde_json::json!({"ok": true, "cmd": "run"}),
            Err(f) => f.json("run"),
        };
        let (checks, failed) = checks(&engine);
        summary["script"] = args.script.display().to_string().into();
        summary["checks"] = serde_json::json!({"passed": checks.saturating_sub(failed), "failed": failed});
        summary["duration_ms"] = ((duration.as_secs_f64() * 1e6).round() / 1e3).into();
        summary["sandbox"] = args.sandbox.into();
        let _ = writeln!(std::io::stdout().lock(), "{summary}");
    }
    match result {
        Ok(()) => 0,
        // `os.exit(code)`: the handlers have run; exit with the status asked for.
        Err(_) if engine.exit_code().is_some() => engine.exit_code().unwrap_or(0),
        Err(f) => {
            if !style.json {
                let _ = write!(std::io::stderr().lock(), "{}", f.human());
            }
            if f.interrupted() {
                crate::core::exit::INTERRUPTED
            } else {
                crate::core::exit::FAILED
            }
        }
    }
}

/// `--report FILE` for a script that wrote no report itself (no commission runner): the
/// devices and the write log, titled by the script, with the script's failure as a note.
fn report_if_none(
    engine: &Engine,
    shell: &mut Shell,
    args: &RunArgs,
    path: &str,
    result: &Result<(), crate::script::Failure>,
) -> crate::core::Result<()> {
    let lua = engine.lua();
    if lua.named_registry_value::<Option<bool>>(crate::script::report::WRITTEN_KEY).ok().flatten() == Some(true) {
        return Ok(());
    }
    let Some(begun) = crate::script::report::begun_in(lua) else { return Ok(()) };
    let run = crate::report::Run {
        title: args.script.display().to_string(),
        notes: result.as_ref().err().map(|f| f.error.to_string()).into_iter().collect(),
        ..Default::default()
    };
    crate::script::report::write(shell, run, &begun, path).map(|_| ())
}

/// The checks the script ran and how many failed (`plcsh.checks`, `plcsh.checks_failed`).
pub(super) fn checks(engine: &Engine) -> (u64, u64) {
    let get = |k: &str| -> Option<u64> {
        let t: mlua::Table = engine.lua().globals().get("plcsh").ok()?;
        t.get::<Option<u64>>(k).ok().flatten()
    };
    (get("checks").unwrap_or(0), get("checks_failed").unwrap_or(0))
}
