//! The command language shared by the REPL, one-shot `-c` and Lua's `plcsh.exec`:
//! `get VW100 SMD72`, `set SMB67=16#85, SMW68=500, SMD72=1000`, `read VW0..VW20`,
//! several commands per line separated by `;`. Commands are registered in one list
//! (`commands::COMMANDS`), one file per command family, each a thin call into the session.
//! Lua lines (`lua …`, `:…`, a `lua` … `end` block) are whole: `;` belongs to Lua there; the
//! shell hands them to a [`ScriptHook`] the cli installs (`script::install`), so the shell
//! knows the hook, not the language.

pub mod commands;
pub mod complete;
pub mod edits;
pub mod files;
pub mod helper;
pub mod lex;
pub mod names;
pub mod progress;
pub mod repl;
pub mod sample;
pub mod term;

#[cfg(test)]
mod messages_tests;

use crate::core::{Error, ErrorKind, Result};
use crate::output::{self, Outcome, Style};
use crate::session::Session;
use std::io::Write;

/// The part of a line a command received, with its column in the line (for carets).
#[derive(Clone, Copy, Debug)]
pub struct Args<'a> {
    pub text: &'a str,
    pub offset: usize,
}

/// The shell: a session plus output settings.
pub struct Shell {
    pub session: Session,
    pub style: Style,
    pub verbose: bool,
    /// Set by `quit`.
    pub quit: bool,
    /// The last `trace`, for `plot`.
    pub last_trace: Option<sample::Recording>,
    /// Runs Lua (`lua …`, `:…`); `None` while a chunk runs (no nesting) or when not installed.
    pub script: Option<Box<dyn ScriptHook>>,
    /// Where commands may write files (`files::check_write`); confined in a sandboxed run.
    pub write_rule: files::WriteRule,
    /// Teaching labs (`lab new|check|grade`); `None` when not installed.
    pub labs: Option<std::sync::Arc<dyn LabHook>>,
}

/// Teaching labs, which the `lab` command hands its work to ([`crate::lab`]). Labs sit above
/// the shell — a lab grades with Lua and shells of its own — so the shell knows this hook, not
/// the module; the cli installs it (`lab::hook::install`), as it installs the [`ScriptHook`].
pub trait LabHook: Send + Sync {
    /// Writes an example lab into `dir`.
    fn new_lab(&self, dir: &std::path::Path) -> Result<Outcome>;
    /// Checks a lab against its reference solution: the table, its headline, and whether every
    /// criterion held.
    fn check(&self, lab: &std::path::Path) -> Result<(Outcome, String, bool)>;
    /// How many workers grade at once unless `jobs=` says.
    fn default_jobs(&self) -> usize;
    /// Grades `submissions` in `jobs` workers: the summary's headline and table, and each
    /// submission's report as JSON.
    fn grade(
        &self,
        lab: &std::path::Path,
        submissions: &[std::path::PathBuf],
        jobs: usize,
    ) -> Result<(String, Outcome, Vec<serde_json::Value>)>;
}

/// An embedded language the shell hands whole lines to (Lua, `src/script/`).
pub trait ScriptHook: Send {
    /// Runs a chunk with the shell; the outcome shows the chunk's results.
    fn run(&mut self, shell: &mut Shell, code: &str) -> Result<Outcome>;
    /// True while `code` is an unfinished chunk (the REPL then reads another line).
    fn incomplete(&mut self, code: &str) -> bool;
}

/// The line without a trailing comment: an unquoted `#` at the start or after a space,
/// followed by a space or the end (`get VW0   # speed`, as a checklist writes it). `16#85`,
/// `T#5s` and the manual's spaced `B # 16 # 85` are values; a `#` in quotes is text.
fn strip_comment(line: &str) -> &str {
    let b = line.as_bytes();
    for (i, c, role) in crate::core::text::Quotes::roles(line) {
        if c == '#'
            && role == crate::core::text::Role::Bare
            && (i == 0 || b[i - 1].is_ascii_whitespace())
            && b.get(i + 1).is_none_or(|n| n.is_ascii_whitespace())
        {
            // Read in the manual's spelling with the `#` after it (`В # 16 # 85` is `B#16#85`).
            let before = format!("{} #", word_before(&line[..i]));
            let folded = crate::core::text::fold_manual_spelling(&before).map_or(before, |f| f.0);
            if !crate::core::literal::is_literal_head(folded.trim_end_matches(" #")) {
                return &line[..i];
            }
        }
    }
    line
}

/// The K2 manual's spelling ([`crate::core::text::fold_manual_spelling`]) read in the words of
/// a command's arguments that may be operands or values — never in its text words (file
/// paths, names, messages: [`commands::text_words`]) or quoted ones. Returns the new text
/// and the words that changed, or `None` when nothing did (or the words cannot be split: the
/// command then reports that as typed).
pub(crate) fn fold_operands(cmd: &str, text: &str) -> Option<(String, Vec<(String, String)>)> {
    fold_operands_except(cmd, text, |_| vec![]).map(|f| (f.0, f.1))
}

/// What [`fold_operands_except`] made: the new text, the words that changed, and where each
/// piece of the new text was typed.
type Folded = (String, Vec<(String, String)>, edits::Edits);

/// [`fold_operands`], leaving alone also the words `keep` marks (tag names and words that the
/// spelling would not make operands: `names::unfolded_words`).
fn fold_operands_except(cmd: &str, text: &str, keep: impl FnOnce(&[(usize, &str)]) -> Vec<bool>) -> Option<Folded> {
    if text.is_ascii() && !text.contains('%') {
        return None;
    }
    let words = lex::words(text).ok()?;
    let raw: Vec<&str> = words.iter().map(|w| w.1).collect();
    let mut mask = commands::text_words(cmd, &raw);
    for (m, k) in mask.iter_mut().zip(keep(&words)) {
        *m |= k;
    }
    let mut out = String::with_capacity(text.len());
    let mut changed = Vec::new();
    let mut edits = edits::Edits::default();
    let (mut copied, mut k) = (0, 0);
    while k < words.len() {
        if mask[k] {
            k += 1;
            continue;
        }
        // A run of operand words, folded as one piece (`% VW2` is two words).
        let mut j = k;
        while j + 1 < words.len() && !mask[j + 1] {
            j += 1;
        }
        let (start, end) = (words[k].0, words[j].0 + words[j].1.len());
        out.push_str(&text[copied..start]);
        match crate::core::text::fold_manual_spelling(&text[start..end]) {
            Some((f, c)) => {
                edits.replaced((start, end), (out.len(), out.len() + f.len()), true);
                out.push_str(&f);
                changed.extend(c);
            }
            None => out.push_str(&text[start..end]),
        }
        copied = end;
        k = j + 1;
    }
    out.push_str(&text[copied..]);
    (out != text).then_some((out, changed, edits))
}

/// A usage error from a command with sub-commands whose first word is none of them: the
/// hint names the nearest sub-command (`servo stauts` → `servo status`).
fn suggest_subcommand(spec: &commands::CommandSpec, args: Args, e: Error) -> Error {
    let word = args.text.split_whitespace().next().unwrap_or("").to_ascii_lowercase();
    if e.kind != ErrorKind::Usage
        || spec.subcommands.is_empty()
        || word.is_empty()
        || spec.subcommands.contains(&word.as_str())
    {
        return e;
    }
    let Some((d, near)) = spec.subcommands.iter().map(|s| (crate::core::text::edit_distance(&word, s), *s)).min()
    else {
        return e;
    };
    if d > 2 || d >= word.len() {
        return e;
    }
    e.hint(crate::msg!("shell-hint-subcommand", command = spec.name, near = near))
}

/// One naming rule for every result (docs/json.md): `cmd` is the command's registry name, and
/// `sub` the sub-command word when the command has them (`sim wires` and `sim faults` are
/// both `"cmd":"sim"`, with `"sub":"wires"` and `"sub":"faults"`). The sub-command is the first
/// word, or the second after a device name (`servo axis1 status`).
fn name_outcome(spec: &commands::CommandSpec, args: &str, mut o: Outcome) -> Outcome {
    o.cmd = spec.name.to_string();
    if !spec.subcommands.is_empty() && !o.data.contains_key("sub") {
        let sub = args
            .split_whitespace()
            .take(2)
            .map(|w| w.to_ascii_lowercase())
            .find(|w| spec.subcommands.contains(&w.as_str()));
        if let Some(sub) = sub {
            o.data.insert("sub".into(), serde_json::Value::String(sub));
        }
    }
    o
}

/// The word just before a position: back to a space, `=` or `,` (`SMB67=B ` → `B`).
fn word_before(text: &str) -> &str {
    let t = text.trim_end();
    let start = t.rfind(|c: char| c.is_whitespace() || c == '=' || c == ',').map_or(0, |i| i + 1);
    &t[start..]
}

/// One command's result, with the command name for error reporting.
pub type CmdResult = std::result::Result<Outcome, (String, Error)>;

impl Shell {
    pub fn new(session: Session, style: Style) -> Shell {
        Shell {
            session,
            style,
            verbose: false,
            quit: false,
            last_trace: None,
            script: None,
            write_rule: None,
            labs: None,
        }
    }

    /// Puts the session under a sandbox's rules ([`crate::confine`]): devices, snapshots and
    /// the commands that read or write files follow them.
    pub fn confine(&mut self, rules: std::sync::Arc<crate::confine::Confinement>) {
        self.write_rule = Some(rules.write.clone());
        self.session.confine = Some(rules);
    }

    /// Runs every command on the line in order and returns their results. A failing
    /// command does not stop the ones after it on the same line only if it is not a
    /// write: after a failed command the rest of the line is skipped (the line is treated
    /// like a script: later commands usually depend on earlier ones).
    pub fn exec(&mut self, line: &str) -> Vec<CmdResult> {
        let mut results = Vec::new();
        self.exec_each(line, |_, r| results.push(r));
        results
    }

    /// [`exec`](Self::exec), handing each result to `on` as soon as its command finished, so
    /// output appears in order with what later commands print themselves (Lua's `print`).
    pub fn exec_each(&mut self, line: &str, mut on: impl FnMut(&mut Shell, CmdResult)) {
        if let Some((offset, code)) = commands::lua::whole_line(line) {
            let args = Args { text: &code, offset };
            let r = (commands::lua::LUA.run)(self, args).map_err(|e| ("lua".to_string(), e));
            return on(self, r);
        }
        let line = strip_comment(line);
        let parts = match lex::split_commands(line) {
            Ok(p) => p,
            Err(e) => return on(self, Err(("line".into(), e))),
        };
        for (offset, part) in parts {
            let lead = part.len() - part.trim_start().len();
            let cmd_text = part.trim();
            if cmd_text.is_empty() {
                continue;
            }
            let r = self.exec_one(cmd_text, offset + lead);
            let failed = r.is_err();
            on(self, r);
            // A stop (Ctrl-C, SIGTERM, SIGHUP) ends the whole line, whichever command saw it.
            if failed || self.quit || self.session.interrupted() {
                break;
            }
        }
    }

    fn exec_one(&mut self, text: &str, offset: usize) -> CmdResult {
        let name_len = text.find(char::is_whitespace).unwrap_or(text.len());
        // The K2 manual's own spelling (`В#16#85` with a Cyrillic В, `% VW2`) reads as meant in
        // operands and values; paths and names stay as typed (`fold_operands`).
        let typed = &text[..name_len];
        let folded_name = crate::core::text::fold_manual_spelling(typed);
        let name = folded_name.as_ref().map_or(typed, |f| f.0.as_str()).to_ascii_lowercase();
        let rest = &text[name_len..];
        let lead = rest.len() - rest.trim_start().len();
        let args = Args { text: rest.trim(), offset: offset + name_len + lead };
        let Some(spec) = commands::find(&name) else {
            let e = Error::new(ErrorKind::Usage, crate::msg!("shell-unknown-command", name = name.as_str()))
                .column(offset)
                .hint(commands::suggest(&name));
            return Err((name, e));
        };
        let mut changed: Vec<(String, String)> = folded_name.map(|f| f.1).unwrap_or_default();
        let (dev, args) = match self.device_first(spec, args) {
            Some((dev, args)) => (Some(dev), args),
            None => (None, args),
        };
        // A graded submission drives the lab's machine and never rebuilds it: the one check
        // for every command that changes the bench ([`crate::confine::bench_action`]).
        if let Some(c) = &self.session.confine {
            if let Some(what) = crate::confine::bench_action(spec.name, args.text) {
                c.check_bench(&what).map_err(|e| (spec.name.to_string(), e.column(offset)))?;
            }
        }
        let folded =
            fold_operands_except(spec.name, args.text, |words| names::unfolded_words(&self.session, spec.name, words));
        let typed_args = args;
        let args = Args { text: folded.as_ref().map_or(args.text, |f| f.0.as_str()), offset: args.offset };
        changed.extend(folded.as_ref().map(|f| f.1.clone()).unwrap_or_default());
        // Tag names as their operands, for the commands that read operands themselves.
        let named = names::operands_for(&self.session, spec, args.text);
        let folded_args = args;
        let args = Args { text: named.as_ref().map_or(args.text, |n| n.0.as_str()), offset: args.offset };
        // A refusal points at what was typed, whatever the rewriting above made of it.
        let typed_column = |c: usize| {
            let Some(rel) = c.checked_sub(args.offset).filter(|&r| r <= args.text.len()) else { return c };
            let rel = named.as_ref().map_or(rel, |n| n.1.typed(folded_args.text, args.text, rel));
            let rel = folded.as_ref().map_or(rel, |f| f.2.typed(typed_args.text, folded_args.text, rel));
            args.offset + rel
        };
        let mut r = match dev {
            Some(dev) => {
                // The command acts on DEVICE as if it were the current one, for this command only.
                let before = self.session.current_index().ok();
                self.session.use_index(dev);
                let r = self.run_spec(spec, args);
                if let Some(b) = before {
                    self.session.use_index(b);
                }
                r
            }
            None => self.run_spec(spec, args),
        };
        if let Err((_, e)) = r.as_mut() {
            e.column = e.column.map(typed_column);
        }
        if let (false, Ok(o)) = (changed.is_empty(), r.as_mut()) {
            let words: Vec<String> = changed.iter().map(|(a, b)| format!("`{a}` as `{b}`")).collect();
            o.notes.push(format!(
                "read {} (the K2 manual's spelling: Cyrillic look-alike letters, `% VW2`)",
                words.join(", ")
            ));
        }
        r
    }

    fn run_spec(&mut self, spec: &commands::CommandSpec, args: Args) -> CmdResult {
        // Every command is strict in one place: a word after the end of its forms is refused
        // before the command runs or its device is made ready.
        commands::forms::check(spec, args).map_err(|e| (spec.name.to_string(), e))?;
        if !commands::NO_CURRENT_DEVICE.contains(&spec.name) {
            // The device the command acts on, ready first (`crate::pending`): the reason it is
            // not (its state file held, its link down) is the command's error.
            if let Ok(i) = self.session.current_index() {
                self.session.ready(i).map_err(|e| (spec.name.to_string(), e))?;
            }
        }
        (spec.run)(self, args)
            .map(|o| name_outcome(spec, args.text, o))
            .map_err(|e| (spec.name.to_string(), suggest_subcommand(spec, args, e)))
    }

    /// The device word of a command in [`commands::DEVICE_FIRST`] (`eeprom press status`,
    /// `rtc press`, `wait press event 1`): an open device's name right after the command word
    /// (a sub-command's word wins over a device of the same name). Returns the device and the
    /// arguments after it.
    fn device_first<'a>(&self, spec: &commands::CommandSpec, args: Args<'a>) -> Option<(usize, Args<'a>)> {
        if !commands::DEVICE_FIRST.contains(&spec.name) {
            return None;
        }
        let word = args.text.split_whitespace().next()?;
        if spec.subcommands.iter().any(|s| s.eq_ignore_ascii_case(word)) {
            return None;
        }
        let dev = self.session.index(word).ok()?;
        let rest = &args.text[word.len()..];
        let lead = rest.len() - rest.trim_start().len();
        Some((dev, Args { text: rest.trim(), offset: args.offset + word.len() + lead }))
    }

    /// Runs a line and writes each result (human-readable errors to stderr, JSON ones to `out`);
    /// returns true when every command succeeded.
    pub fn run_line(&mut self, line: &str, out: &mut dyn Write) -> bool {
        let mut ok = true;
        let before = self.verbose.then(|| self.requests());
        self.exec_each(line, |sh, r| {
            let w = match &r {
                Ok(o) => output::write_outcome(out, sh.style, o),
                Err((cmd, e)) => {
                    ok = false;
                    output::report_error(out, sh.style, cmd, e, Some(line))
                }
            };
            // Flushed per command: a Lua `print` in a later command goes to stdout directly.
            if w.and_then(|_| out.flush()).is_err() {
                ok = false;
            }
        });
        let _ = out.flush();
        if let Some(before) = before {
            self.report_requests(&before);
        }
        ok
    }

    /// Wire requests sent so far, per open device (for `-v`).
    fn requests(&self) -> Vec<(String, u64)> {
        self.session.entries().iter().map(|e| (e.name.clone(), e.device.requests())).collect()
    }

    /// `-v`: how many requests the line sent, per device (nothing for in-process devices).
    fn report_requests(&self, before: &[(String, u64)]) {
        let sent: Vec<String> = self
            .requests()
            .into_iter()
            .filter_map(|(name, n)| {
                let was = before.iter().find(|(b, _)| *b == name).map(|(_, c)| *c).unwrap_or(0);
                (n > was).then(|| format!("{name} {}", n - was))
            })
            .collect();
        if !sent.is_empty() {
            eprintln!("requests: {}", sent.join(", "));
        }
    }

    /// True while `text` is a Lua chunk that needs more lines (REPL continuation).
    pub fn needs_more(&mut self, text: &str) -> bool {
        commands::lua::needs_more(self, text)
    }

    /// The name of the device a command acts on by default.
    pub fn current_device(&self) -> Result<String> {
        let i = self.session.current_index()?;
        Ok(self.session.entries()[i].name.clone())
    }
}
