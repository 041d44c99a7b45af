//! Errors across the Lua boundary, both ways.
//!
//! Rust → Lua: a shell error (device, operand, hint, cause chain) is raised as a Lua error
//! carrying a [`LuaFacing`] value; its message shows every field, and `plcsh.errinfo(e)`
//! gives them back as a table to a script that catches it with `pcall`.
//! Lua → Rust: a failed chunk becomes a [`Failure`]: the shell error kind (kept from the Rust
//! error underneath when there is one, `script` otherwise), the script's file:line and the
//! Lua traceback.

use crate::core::{Error, ErrorKind};
use std::fmt;

/// A shell error raised into Lua, with the command that failed (if a command did).
#[derive(Clone, Debug)]
pub struct LuaFacing {
    pub cmd: Option<String>,
    pub error: Error,
    /// The script's `file:line` that called into Rust (so a `pcall`ed error names it too).
    pub location: Option<String>,
}

impl fmt::Display for LuaFacing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(l) = &self.location {
            write!(f, "{l}: ")?;
        }
        write!(f, "error[{}]: ", self.error.kind.name())?;
        if let Some(c) = &self.cmd {
            write!(f, "`{c}`: ")?;
        }
        write!(f, "{}", self.error)?;
        if let Some(c) = self.error.column {
            write!(f, " (column {c})")?;
        }
        Ok(())
    }
}

impl std::error::Error for LuaFacing {}

/// Raises a shell error into Lua.
pub fn raise(error: Error) -> mlua::Error {
    mlua::Error::external(LuaFacing { cmd: None, error, location: None })
}

/// Raises a shell error into Lua naming the script line that called into Rust: the first
/// stack frame that is the user's source (not Rust, not mlua's glue, not the prelude).
pub fn raise_at(lua: &mlua::Lua, error: Error) -> mlua::Error {
    let location = (0..32).find_map(|level| {
        lua.inspect_stack(level, |d| {
            let src = d.source();
            // A script's whole path (`@path`): Lua's short form cuts a long one to `...tail`.
            let file = match src.source.as_deref() {
                Some(s) if s.starts_with('@') => &s[1..],
                _ => src.short_src.as_deref().unwrap_or(""),
            };
            let line = d.current_line()?;
            user_source(file).then(|| format!("{file}:{line}"))
        })?
    });
    mlua::Error::external(LuaFacing { cmd: None, error, location })
}

/// True for a chunk the user wrote (a script, a `lua` line, a `lib/` module), false for
/// Rust frames (`[C]`), mlua's generated glue (`__mlua_index`) and the prelude (`plcsh`).
fn user_source(file: &str) -> bool {
    !(file.is_empty()
        || file.starts_with("[C]")
        || file.starts_with("__mlua")
        || file.starts_with("[string")
        || file == "plcsh"
        || file.starts_with("(..."))
}

/// Raises a failed command's error into Lua.
pub fn raise_cmd(cmd: &str, error: Error) -> mlua::Error {
    mlua::Error::external(LuaFacing { cmd: Some(cmd.to_string()), error, location: None })
}

/// `Result<T, core::Error>` → `mlua::Result<T>`.
pub trait IntoLuaResult<T> {
    fn lua(self) -> mlua::Result<T>;
}

impl<T> IntoLuaResult<T> for crate::core::Result<T> {
    fn lua(self) -> mlua::Result<T> {
        self.map_err(raise)
    }
}

/// The shell error inside a Lua error, when the Lua error came from Rust.
pub fn facing(e: &mlua::Error) -> Option<&LuaFacing> {
    e.downcast_ref::<LuaFacing>()
}

/// A failed chunk, ready to report.
#[derive(Clone, Debug)]
pub struct Failure {
    /// Kind, device, operand and hint from the Rust error underneath, or kind `script`.
    pub error: Error,
    /// `scripts/x.lua:12` — where in the script it failed.
    pub location: Option<String>,
    /// The Lua stack traceback, without its `stack traceback:` heading.
    pub traceback: Option<String>,
}

/// Lua shortens a long chunk name (a script's path) to `...` and its last 56 bytes in every
/// location it writes (`luaO_chunkid`, LUA_IDSIZE 60): on Windows, where the temporary and
/// user folders are long, `C:\Users\…\press1\check.lua:12` would lose its start. Each
/// shortened form of `full` in `text` is put back whole.
pub fn restore_chunk_name(text: &str, full: &str) -> String {
    /// Shorter tails than this are not taken for the path (a message's own `...`).
    const MIN_TAIL: usize = 12;
    if full.len() < MIN_TAIL || !text.contains("...") {
        return text.to_string();
    }
    let mut out = String::with_capacity(text.len() + full.len());
    let mut rest = text;
    while let Some(i) = rest.find("...") {
        out.push_str(&rest[..i]);
        let after = &rest[i + 3..];
        // The longest tail of `full` that `after` starts with (at most 60 bytes are tried).
        let tail = (MIN_TAIL..=full.len().min(60))
            .rev()
            .filter(|k| full.is_char_boundary(full.len() - k))
            .map(|k| &full[full.len() - k..])
            .find(|t| after.starts_with(t));
        match tail {
            Some(t) => {
                out.push_str(full);
                rest = &after[t.len()..];
            }
            None => {
                out.push_str("...");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

impl Failure {
    /// The failure with every location in `path` written out whole ([`restore_chunk_name`]).
    pub fn with_full_chunk_name(mut self, path: &str) -> Failure {
        self.location = self.location.map(|l| restore_chunk_name(&l, path));
        self.traceback = self.traceback.map(|t| restore_chunk_name(&t, path));
        self.error.message = restore_chunk_name(&self.error.message, path);
        self
    }

    pub fn interrupted(&self) -> bool {
        self.error.kind == ErrorKind::Interrupted
    }

    /// The message with the location in front, as Lua prints errors (`file:line: message`).
    pub fn headline(&self) -> String {
        let e = &self.error;
        let mut body = e.to_string();
        if let Some(h) = &e.hint {
            // The hint is shown on its own line.
            if let Some(stripped) = body.strip_suffix(&format!(" — {h}")) {
                body = stripped.to_string();
            }
        }
        match &self.location {
            Some(l) if !body.starts_with(l.as_str()) => format!("{l}: {body}"),
            _ => body,
        }
    }

    /// Human report: `error[kind]: file:line: message`, the hint, then the traceback.
    pub fn human(&self) -> String {
        let mut s = format!("error[{}]: {}\n", self.error.kind.name(), self.headline());
        if let Some(h) = &self.error.hint {
            s.push_str(&format!("  {}\n", crate::msg!("label-hint", hint = h.as_str())));
        }
        if let Some(t) = &self.traceback {
            s.push_str("stack traceback:\n");
            s.push_str(t);
            s.push('\n');
        }
        s
    }

    /// JSON report: the shell's error object plus `where` and `traceback`.
    pub fn json(&self, cmd: &str) -> serde_json::Value {
        let mut v = crate::output::error_json(cmd, &self.error);
        if let Some(obj) = v.get_mut("error").and_then(|e| e.as_object_mut()) {
            if let Some(l) = &self.location {
                obj.insert("where".into(), l.clone().into());
            }
            if let Some(t) = &self.traceback {
                obj.insert("traceback".into(), t.clone().into());
            }
        }
        v
    }

    /// The error as the shell reports a failed `lua` line: location in the message.
    pub fn into_shell_error(self) -> Error {
        let mut e = self.error;
        // `lua:1` (a line typed in the shell) says nothing the user does not know.
        if let Some(l) = self.location.as_ref().filter(|l| !l.starts_with("lua:")) {
            if !e.message.starts_with(l.as_str()) {
                e.message = format!("{l}: {}", e.message);
            }
        }
        e
    }
}

/// Splits `msg\nstack traceback:\n\t…` into the message and the traceback body.
fn split_traceback(s: &str) -> (String, Option<String>) {
    match s.find("stack traceback:") {
        Some(i) => {
            let tb = s[i + "stack traceback:".len()..].trim_matches('\n').to_string();
            (s[..i].trim_end().to_string(), (!tb.is_empty()).then_some(tb))
        }
        None => (s.trim_end().to_string(), None),
    }
}

/// The first Lua source frame of a traceback (`scripts/x.lua:12`), skipping Rust (`[C]`)
/// frames and the prelude.
fn first_frame(tb: &str) -> Option<String> {
    tb.lines().map(str::trim).find_map(|l| {
        let mut parts = l.splitn(3, ':');
        let file = parts.next()?;
        if !user_source(file) {
            return None;
        }
        let line = parts.next()?;
        (!file.is_empty() && line.chars().all(|c| c.is_ascii_digit()) && !line.is_empty())
            .then(|| format!("{file}:{line}"))
    })
}

/// `file:line` at the start of a Lua error message (`scripts/x.lua:3: attempt to …`).
fn leading_location(msg: &str) -> Option<String> {
    let mut parts = msg.splitn(3, ':');
    let file = parts.next()?;
    let line = parts.next()?;
    parts.next()?;
    (!file.is_empty() && !file.contains(' ') && !line.is_empty() && line.chars().all(|c| c.is_ascii_digit()))
        .then(|| format!("{file}:{line}"))
}

/// `plc.read("VW0")`: a method called with a dot gets a string where `self` goes. The
/// explanation, when `e` is that mistake (the same at top level and inside `pcall`).
fn dot_for_colon(e: &mlua::Error) -> Option<String> {
    let mut cur = e;
    loop {
        match cur {
            mlua::Error::CallbackError { cause, .. } | mlua::Error::WithContext { cause, .. } => cur = cause,
            mlua::Error::BadArgument { to: Some(to), name: Some(name), .. } if name == "self" => {
                let method = to.rsplit('.').next().unwrap_or(to);
                return Some(crate::msg!("script-method-dot", method = method).text);
            }
            _ => return None,
        }
    }
}

/// `plcsh._explain(e)`, applied by the prelude's `pcall`, `xpcall` and `coroutine.resume`
/// to a caught error: a method called with a dot becomes the explanation a script gets at
/// top level (with the script line), any other error is returned as it is.
pub fn explain(_lua: &mlua::Lua, v: mlua::Value) -> mlua::Result<mlua::Value> {
    let mlua::Value::Error(e) = &v else { return Ok(v) };
    let Some(message) = dot_for_colon(e) else { return Ok(v) };
    let location = match e.as_ref() {
        mlua::Error::CallbackError { traceback, .. } => split_traceback(traceback).1.as_deref().and_then(first_frame),
        _ => None,
    };
    let error = Error::new(ErrorKind::Script, message);
    Ok(mlua::Value::Error(Box::new(mlua::Error::external(LuaFacing { cmd: None, error, location }))))
}

/// Turns a failed chunk's Lua error into a report.
pub fn failure(e: &mlua::Error) -> Failure {
    // The outermost traceback is the fullest one.
    let mut traceback = None;
    let mut cur = e;
    loop {
        match cur {
            mlua::Error::CallbackError { traceback: tb, cause } => {
                if traceback.is_none() {
                    traceback = Some(split_traceback(tb).1.unwrap_or_default());
                }
                cur = cause;
            }
            mlua::Error::WithContext { cause, .. } => cur = cause,
            _ => break,
        }
    }
    if let Some(f) = facing(e) {
        let location = f.location.clone().or_else(|| traceback.as_deref().and_then(first_frame));
        return Failure { error: f.error.clone(), location, traceback };
    }
    let (message, tb) = match cur {
        mlua::Error::RuntimeError(m) => split_traceback(m),
        _ if dot_for_colon(cur).is_some() => (dot_for_colon(cur).unwrap_or_default(), None),
        mlua::Error::SyntaxError { message, .. } => (message.clone(), None),
        other => split_traceback(&other.to_string()),
    };
    let traceback = traceback.or(tb);
    let location = leading_location(&message).or_else(|| traceback.as_deref().and_then(first_frame));
    let message = match &location {
        Some(l) => message.strip_prefix(l.as_str()).map(|m| m.trim_start_matches(':').trim_start()).unwrap_or(&message),
        None => &message,
    };
    let kind = if matches!(cur, mlua::Error::SyntaxError { .. }) { ErrorKind::Syntax } else { ErrorKind::Script };
    Failure { error: Error::new(kind, message.to_string()), location, traceback }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_script_paths_are_written_out_whole() {
        let full = r"C:\users\technician\Temp\plcsh-scripts-test-1184\pto_single_segment.lua";
        let cut = format!("...{}", &full[full.len() - 56..]);
        let msg = format!("{cut}:28: assert_eq failed; in {cut}:30 too ... and more");
        assert_eq!(
            restore_chunk_name(&msg, full),
            format!("{full}:28: assert_eq failed; in {full}:30 too ... and more")
        );
        assert_eq!(restore_chunk_name("short.lua:2: x", full), "short.lua:2: x");
        assert_eq!(restore_chunk_name("...", full), "...");
    }

    #[test]
    fn frames_and_locations() {
        let tb = "\t[C]: in ?\n\t[C]: in function 'error'\n\tscripts/a.lua:7: in function 'f'\n\tscripts/a.lua:9: in main chunk";
        assert_eq!(first_frame(tb).as_deref(), Some("scripts/a.lua:7"));
        assert_eq!(leading_location("x.lua:3: attempt to call a nil value").as_deref(), Some("x.lua:3"));
        assert_eq!(leading_location("error[value]: plc: VB2: 300"), None);
    }

    #[test]
    fn a_lua_runtime_error_keeps_file_and_line() {
        let lua = mlua::Lua::new();
        let e = lua.load("local x = nil\nreturn x + 1").set_name("@t.lua").exec().unwrap_err();
        let f = failure(&e);
        assert_eq!(f.location.as_deref(), Some("t.lua:2"));
        assert!(f.error.message.contains("arithmetic"), "{}", f.error.message);
        assert!(f.human().starts_with("error[script]: t.lua:2: attempt to perform arithmetic"), "{}", f.human());
    }

    #[test]
    fn a_rust_error_keeps_its_kind_device_and_operand() {
        let lua = mlua::Lua::new();
        let f = lua
            .create_function(|_, ()| -> mlua::Result<()> {
                Err(raise(Error::new(ErrorKind::Value, "300 is out of range for BYTE").device("plc").operand("VB2")))
            })
            .unwrap();
        lua.globals().set("boom", f).unwrap();
        let e = lua.load("local a = 1\nboom()").set_name("@t.lua").exec().unwrap_err();
        let f = failure(&e);
        assert_eq!(f.error.kind, ErrorKind::Value);
        assert_eq!(f.error.device.as_deref(), Some("plc"));
        assert_eq!(f.location.as_deref(), Some("t.lua:2"));
        assert!(f.human().contains("t.lua:2: plc: VB2: 300 is out of range"), "{}", f.human());
        assert!(f.traceback.unwrap().contains("main chunk"));
    }
}
