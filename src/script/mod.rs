//! Lua automation (mlua, Lua 5.4): `plcsh run SCRIPT.lua`, and `lua …` / `:…` in the shell.
//! Devices are Lua objects (`device.rs`), every shell helper is a method through one bridge
//! (`bridge.rs`), the command language is `plcsh.exec` (`api.rs`).
//!
//! Ownership: the shell owns the session; while a chunk runs, the shell is moved into the Lua
//! state's app data and moved back afterwards ([`Engine::with_shell`]), so Lua callbacks reach
//! the session without locks or raw pointers and the Lua state can persist across REPL lines.
//!
//! Safety: Ctrl-C raises the session's interrupt flag (the cli registers it for SIGINT); a
//! Lua hook checks it every [`HOOK_EVERY`] instructions, and every wait checks it too. A chunk
//! that ends with an error or an interrupt runs its `plcsh.on_abort` handlers (last registered
//! first) before the error is reported.

mod api;
pub mod bridge;
mod device;
pub mod error;
mod fleet;
pub mod memory;
pub mod paths;
pub mod report;
pub mod sandbox;
mod snapshot;
mod wire;

pub use api::ABORT_KEY;
pub use bridge::{Bridge, BRIDGE};
pub use error::Failure;

use crate::core::{Error, ErrorKind};
use crate::output::Outcome;
use crate::session::Session;
use crate::shell::{ScriptHook, Shell};
use mlua::{HookTriggers, Lua, MultiValue, Table, Value, VmState};
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// A Lua file's text as the stock `lua` reads it (`luaL_loadfilex`): without a UTF-8 byte-order
/// mark (Notepad's old default), and with a first line that starts with `#`
/// (`#!/usr/bin/env plcsh run`) left empty, so line numbers stay those of the file. Every
/// place plcsh loads Lua from a file reads it through this: `plcsh run`, graders and
/// submissions, `require`d modules (`loadfile` and `dofile` are Lua's own, which do the same).
pub fn file_chunk(code: &[u8]) -> &[u8] {
    let code = code.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(code);
    if code.first() == Some(&b'#') {
        return code.iter().position(|&b| b == b'\n').map_or(&[], |i| &code[i..]);
    }
    code
}

/// Lua instructions between two checks of the interrupt flag.
pub const HOOK_EVERY: u32 = 1000;

/// The Lua modules, registered in this order (the design's "one explicit list").
const MODULES: &[fn(&Lua) -> mlua::Result<()>] = &[plcsh, device::register, paths::register, fleet::register];

/// The `plcsh` table: the API's own functions ([`api::plcsh_table`]), then wiring and
/// snapshots, set as a global.
fn plcsh(lua: &Lua) -> mlua::Result<()> {
    let p = api::plcsh_table(lua)?;
    wire::register(lua, &p)?;
    snapshot::register(lua, &p)?;
    report::register(lua, &p)?;
    lua.globals().set("plcsh", p)
}

/// A Lua state wired to plcsh.
pub struct Engine {
    lua: Lua,
}

impl Engine {
    /// A Lua state whose `print` writes to `out`, interrupted by `interrupt`.
    pub fn new(interrupt: Arc<AtomicBool>, out: Box<dyn Write + Send>) -> mlua::Result<Engine> {
        // Lua opens files through the platform's UTF-8 name shims where it needs them (Windows).
        std::hint::black_box(crate::core::platform::keep_c_shims());
        let lua = Lua::new();
        for register in MODULES {
            register(&lua)?;
        }
        lua.load(include_str!("prelude.lua")).set_name("=plcsh").exec()?;
        replace_os_exit(&lua)?;
        replace_os_tmpname(&lua)?;
        lua.set_app_data(api::Sink(out));
        lua.set_hook(HookTriggers::new().every_nth_instruction(HOOK_EVERY), move |_, _| {
            if interrupt.load(Ordering::Relaxed) {
                Err(error::raise(api::interrupted_error()))
            } else {
                Ok(VmState::Continue)
            }
        })?;
        Ok(Engine { lua })
    }

    /// An engine for `shell`, printing to stdout.
    pub fn for_shell(shell: &Shell) -> mlua::Result<Engine> {
        Engine::new(shell.session.interrupt.clone(), Box::new(std::io::stdout()))
    }

    pub fn lua(&self) -> &Lua {
        &self.lua
    }

    /// Holds the run to a graded run's limits ([`crate::core::budget`]): Lua memory (kept by
    /// the allocator, which reports every refusal to the budget: [`memory::Watch`]), and Lua
    /// instructions and simulated time, checked by the instruction hook. A limit passed
    /// raises the interrupt flag too, so no `pcall` in the script can swallow it. The memory
    /// watch is returned, to be removed when the run is over.
    pub fn limit(
        &self,
        budget: Arc<crate::core::budget::Budget>,
        clock: crate::core::Clock,
        interrupt: Arc<AtomicBool>,
    ) -> mlua::Result<Option<memory::Watch>> {
        let mut watch = None;
        if let Some(m) = budget.memory {
            self.lua.set_memory_limit(m)?;
            watch = Some(memory::Watch::install(&self.lua, budget.clone())?);
        }
        // A global hook: every coroutine the script creates inherits it, so a loop inside a
        // coroutine is counted too (a per-thread hook would leave coroutines uncounted).
        self.lua.set_global_hook(HookTriggers::new().every_nth_instruction(HOOK_EVERY), move |_, _| {
            if let Some(verdict) = budget.tick(u64::from(HOOK_EVERY), &clock) {
                interrupt.store(true, Ordering::Relaxed);
                return Err(error::raise(Error::new(ErrorKind::Interrupted, verdict)));
            }
            if interrupt.load(Ordering::Relaxed) {
                Err(error::raise(api::interrupted_error()))
            } else {
                Ok(VmState::Continue)
            }
        })?;
        Ok(watch)
    }

    /// The status a script asked for with `os.exit`, once it has called it.
    pub fn exit_code(&self) -> Option<i32> {
        self.lua.named_registry_value::<Option<i32>>(EXIT_KEY).ok().flatten()
    }

    /// Runs `f` with `shell` moved into the Lua state (see the module doc).
    pub fn with_shell<R>(&self, shell: &mut Shell, f: impl FnOnce(&Lua) -> R) -> R {
        let placeholder = Shell::new(Session::new(shell.session.clock.clone()), shell.style);
        let owned = std::mem::replace(shell, placeholder);
        self.lua.set_app_data(owned);
        let r = f(&self.lua);
        *shell = self.lua.remove_app_data::<Shell>().expect("the shell is back");
        r
    }

    /// Calls `f`; on an error or Ctrl-C runs the abort handlers. The handler list is
    /// emptied either way: handlers belong to one run.
    fn protected(&self, f: mlua::Function, args: MultiValue) -> Result<MultiValue, Failure> {
        let r = f.call::<MultiValue>(args);
        let handlers: Table = self.lua.named_registry_value(api::ABORT_KEY).expect("abort list");
        let _ = self.lua.set_named_registry_value(api::ABORT_KEY, self.lua.create_table().expect("table"));
        let stop = api::interrupt_flag(&self.lua).ok();
        match r {
            Ok(v) => Ok(v),
            Err(e) => {
                let mut failure = error::failure(&e);
                if stop.as_ref().is_some_and(|s| s.load(Ordering::Relaxed)) {
                    failure.error.kind = ErrorKind::Interrupted;
                }
                self.run_abort_handlers(&handlers, &failure, stop.as_deref());
                // Leave the flag as the run ended: a piped shell stops after an interrupted
                // line, as it does after an interrupted command (the next command clears it).
                if let Some(s) = &stop {
                    s.store(failure.interrupted(), Ordering::Relaxed);
                }
                Err(failure)
            }
        }
    }

    /// Runs the handlers, last registered first; each may be interrupted by its own Ctrl-C.
    fn run_abort_handlers(&self, handlers: &Table, why: &Failure, stop: Option<&AtomicBool>) {
        let list: Vec<mlua::Function> = handlers.sequence_values().filter_map(|f| f.ok()).collect();
        if list.is_empty() {
            return;
        }
        let reason = if why.interrupted() {
            "interrupted"
        } else if self.exit_code().is_some() {
            "exit"
        } else {
            "failed"
        };
        let _ = api::show(
            &self.lua,
            &Outcome::new("abort")
                .text(format!("script {reason}: running {} on_abort handler(s)", list.len()))
                .with("handlers", list.len()),
        );
        for f in list.iter().rev() {
            if let Some(s) = stop {
                s.store(false, Ordering::Relaxed);
            }
            if let Err(e) = f.call::<()>(reason) {
                let fail = error::failure(&e);
                let _ = api::show(&self.lua, &Outcome::new("abort").text(format!("on_abort handler {}", fail.human())));
            }
        }
    }

    /// Runs a script file with `args` (in `arg` and `...`, as the standalone `lua` does).
    pub fn run_file(&self, shell: &mut Shell, path: &Path, args: &[String]) -> Result<(), Failure> {
        self.run_file_in(shell, path, args, None)
    }

    /// Runs a script file in environment `env` (a sandbox's, [`sandbox::student_env`]); the
    /// globals when `None`.
    pub fn run_file_in(
        &self,
        shell: &mut Shell,
        path: &Path,
        args: &[String],
        env: Option<&Table>,
    ) -> Result<(), Failure> {
        let code = std::fs::read(path).map_err(|e| Failure {
            error: Error::io(crate::msg!(
                "script-cannot-read",
                file = path.display().to_string(),
                error = e.to_string()
            )),
            location: None,
            traceback: None,
        })?;
        self.with_shell(shell, |lua| {
            let setup = || -> mlua::Result<(mlua::Function, MultiValue)> {
                device::refresh_globals(lua)?;
                paths::add_script_dir(lua, path)?;
                let arg = lua.create_table()?;
                arg.raw_set(-1, std::env::args().next().unwrap_or_else(|| "plcsh".into()))?;
                arg.raw_set(0, path.display().to_string())?;
                for (i, a) in args.iter().enumerate() {
                    arg.raw_set(i + 1, a.as_str())?;
                }
                let chunk = lua.load(file_chunk(&code)).set_name(format!("@{}", path.display()));
                let f = match env {
                    Some(env) => {
                        env.raw_set("arg", arg)?;
                        chunk.set_environment(env.clone()).set_mode(mlua::chunk::ChunkMode::Text).into_function()?
                    }
                    None => {
                        lua.globals().set("arg", arg)?;
                        chunk.into_function()?
                    }
                };
                let va = args.iter().map(|a| lua.create_string(a).map(Value::String)).collect::<mlua::Result<_>>()?;
                Ok((f, va))
            };
            let (f, va) = setup().map_err(|e| error::failure(&e).with_full_chunk_name(&path.display().to_string()))?;
            self.protected(f, va).map(|_| ()).map_err(|f| f.with_full_chunk_name(&path.display().to_string()))
        })
    }

    /// Runs one chunk typed in the shell; an expression's values are shown, as `lua` does.
    pub fn run_chunk(&self, shell: &mut Shell, code: &str) -> Result<Outcome, Failure> {
        self.with_shell(shell, |lua| {
            device::refresh_globals(lua).map_err(|e| error::failure(&e))?;
            let f = match lua.load(format!("return {code}")).set_name("=lua").into_function() {
                Ok(f) => f,
                Err(_) => lua.load(code).set_name("=lua").into_function().map_err(|e| error::failure(&e))?,
            };
            let values = self.protected(f, MultiValue::new())?;
            if values.is_empty() {
                return Ok(Outcome::new("lua").quiet());
            }
            let tostring: mlua::Function = lua.globals().get("tostring").map_err(|e| error::failure(&e))?;
            let mut shown = Vec::new();
            let mut json = Vec::new();
            for v in &values {
                shown.push(tostring.call::<String>(v.clone()).unwrap_or_else(|_| format!("{v:?}")));
                json.push(mlua::LuaSerdeExt::from_value::<serde_json::Value>(lua, v.clone()).unwrap_or_default());
            }
            Ok(Outcome::new("lua").text(shown.join("\t")).with("results", json))
        })
    }

    /// True when `code` is an unfinished chunk (as the standalone `lua` decides: the
    /// statement does not compile and the error is at `<eof>`).
    pub fn incomplete(&self, code: &str) -> bool {
        if self.lua.load(format!("return {code}")).into_function().is_ok() {
            return false;
        }
        matches!(self.lua.load(code).into_function(), Err(mlua::Error::SyntaxError { incomplete_input: true, .. }))
    }
}

/// Registry key of the status `os.exit` asked for.
const EXIT_KEY: &str = "plcsh.exit";

/// `os.exit([code])` ends the script the way an error does — its `plcsh.on_abort`
/// handlers run (PSTOP, servo disable …) and plcsh saves its state — and plcsh then exits
/// with `code` (true → 0, false → 1, default 0), instead of killing the process on the spot.
fn replace_os_exit(lua: &Lua) -> mlua::Result<()> {
    let exit = lua.create_function(|lua, code: Value| {
        let n = match code {
            Value::Nil | Value::Boolean(true) => 0,
            Value::Boolean(false) => 1,
            Value::Integer(i) => i as i32,
            Value::Number(f) => f as i32,
            _ => 1,
        };
        lua.set_named_registry_value(EXIT_KEY, n)?;
        Err::<(), _>(error::raise(Error::new(ErrorKind::Script, crate::msg!("script-os-exit", code = n))))
    })?;
    lua.globals().get::<Table>("os")?.set("exit", exit)
}

/// `os.tmpname` that works on every system: a new empty file in the system's temporary folder,
/// as POSIX Lua's `mkstemp` gives. The C library's `tmpnam` that Lua uses on Windows returns
/// names like `\s164.` in the drive's root, where a user may not write.
fn replace_os_tmpname(lua: &Lua) -> mlua::Result<()> {
    let tmpname = lua.create_function(|_, ()| {
        use std::sync::atomic::AtomicU64;
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let dir = std::env::temp_dir();
        for _ in 0..100 {
            let n = NEXT.fetch_add(1, Ordering::Relaxed);
            let path = dir.join(format!("lua_{}_{n}", std::process::id()));
            match std::fs::OpenOptions::new().write(true).create_new(true).open(&path) {
                Ok(_) => return Ok(path.display().to_string()),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => {
                    return Err(mlua::Error::runtime(crate::msg!(
                        "script-tmpname-cannot-create",
                        dir = dir.display().to_string(),
                        error = e.to_string()
                    )))
                }
            }
        }
        Err(mlua::Error::runtime(crate::msg!("script-tmpname-no-name", dir = dir.display().to_string())))
    })?;
    lua.globals().get::<Table>("os")?.set("tmpname", tmpname)
}

/// The shell's `lua` hook: one Lua state, created on first use, persisting across lines.
struct Hook {
    engine: Option<Engine>,
    interrupt: Arc<AtomicBool>,
}

impl Hook {
    fn engine(&mut self) -> crate::core::Result<&Engine> {
        if self.engine.is_none() {
            let e = Engine::new(self.interrupt.clone(), Box::new(std::io::stdout())).map_err(|e| {
                Error::new(ErrorKind::Script, crate::msg!("lab-cannot-start-lua", error = e.to_string()))
            })?;
            self.engine = Some(e);
        }
        Ok(self.engine.as_ref().expect("engine"))
    }
}

impl ScriptHook for Hook {
    fn run(&mut self, shell: &mut Shell, code: &str) -> crate::core::Result<Outcome> {
        self.engine()?.run_chunk(shell, code).map_err(Failure::into_shell_error)
    }

    fn incomplete(&mut self, code: &str) -> bool {
        self.engine().is_ok_and(|e| e.incomplete(code))
    }
}

/// Installs Lua into the shell (`lua …`, `:…`, `lua` … `end`).
pub fn install(shell: &mut Shell) {
    shell.script = Some(Box::new(Hook { engine: None, interrupt: shell.session.interrupt.clone() }));
}

#[cfg(test)]
mod tests;
