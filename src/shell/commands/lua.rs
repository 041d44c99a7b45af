//! `lua CODE`, `:CODE` and a `lua` … `end` block: run Lua in the session's one Lua state
//! (it persists across lines). The shell only recognises the forms and hands the code to the
//! installed [`crate::shell::ScriptHook`]; the Lua layer lives in `src/script/`.
//!
//! Block form: a line holding just `lua` opens a block; it closes at a line holding just
//! `end` when the code before that line is a complete chunk (so an `end` that closes a Lua
//! `for` or `function` stays part of the code).

use super::CommandSpec;
use crate::core::{Error, Result};
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const LUA: CommandSpec = CommandSpec {
    name: "lua",
    aliases: &[],
    usage: "lua CODE…   e.g. lua print(plc.VW100)   (also `:CODE`, or `lua` … `end` over several lines)",
    summary: || crate::msg!("summary-lua"),
    subcommands: &[],
    run: lua,
};

fn lua(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let Some(mut hook) = sh.script.take() else {
        return Err(Error::unsupported(crate::msg!("shell-lua-cannot-run")).hint(crate::msg!("shell-hint-lua-nested")));
    };
    let r = hook.run(sh, args.text);
    sh.script = Some(hook);
    r
}

/// The first line is just `lua`: a block.
fn is_block(text: &str) -> bool {
    text.lines().next().is_some_and(|l| l.trim().eq_ignore_ascii_case("lua"))
}

/// A Lua line as (column of the code, code), or `None` when the line is ordinary commands.
/// For a block, the code is the lines between `lua` and the closing `end`.
pub fn whole_line(line: &str) -> Option<(usize, String)> {
    let lead = line.len() - line.trim_start().len();
    let t = line.trim_start();
    if let Some(code) = t.strip_prefix(':') {
        return Some((lead + 1, code.to_string()));
    }
    if is_block(t) {
        let body: Vec<&str> = t.lines().skip(1).collect();
        let n = if body.last().is_some_and(|l| l.trim() == "end") { body.len() - 1 } else { body.len() };
        return Some((lead, body[..n].join("\n")));
    }
    let word = t.split_whitespace().next()?;
    if word.eq_ignore_ascii_case("lua") {
        let rest = &t[3..];
        let code_lead = rest.len() - rest.trim_start().len();
        return Some((lead + 3 + code_lead, rest.trim_start().to_string()));
    }
    None
}

/// True while `text` (one or more lines typed so far) is Lua that needs more input.
pub fn needs_more(sh: &mut Shell, text: &str) -> bool {
    let t = text.trim_start();
    let Some(hook) = sh.script.as_mut() else { return false };
    if is_block(t) {
        let body: Vec<&str> = t.lines().skip(1).collect();
        return match body.split_last() {
            Some((last, code)) if last.trim() == "end" => hook.incomplete(&code.join("\n")),
            _ => true,
        };
    }
    match whole_line(text) {
        Some((_, code)) => hook.incomplete(&code),
        None => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lua_forms_take_the_whole_line() {
        assert_eq!(whole_line("lua x = 1; y = 2"), Some((4, "x = 1; y = 2".into())));
        assert_eq!(whole_line("  :print(1); print(2)"), Some((3, "print(1); print(2)".into())));
        assert_eq!(whole_line("lua\nfor i=1,2 do\nend\nend"), Some((0, "for i=1,2 do\nend".into())));
        assert_eq!(whole_line("luax 1"), None);
        assert_eq!(whole_line("get VW0; lua print(1)"), None);
    }
}
