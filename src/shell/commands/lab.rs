//! `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS… [jobs=N]`: teaching labs from
//! the shell, the same calls as `plcsh lab …` (`crate::lab`, through the shell's
//! [`crate::shell::LabHook`]). A lab builds its own
//! simulators, so the session's devices are not touched. Refused in a sandboxed run (grading
//! starts processes and writes lab folders).

use super::CommandSpec;
use crate::core::{Error, Result};
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const LAB: CommandSpec = CommandSpec {
    name: "lab",
    aliases: &[],
    usage: "lab new NAME | lab check LAB | lab grade LAB SUBMISSIONS… [jobs=N]",
    summary: || crate::msg!("summary-lab"),
    subcommands: &["new", "check", "grade"],
    run: lab,
};

fn lab(sh: &mut Shell, args: Args) -> Result<Outcome> {
    if sh.session.confine.is_some() {
        return Err(Error::unsupported(crate::msg!("lab-not-in-sandbox")));
    }
    // Folders and files as text: `lab check "Лабораторные/лаб 1"` (docs/commands.md, "Quoting").
    let raw = crate::shell::lex::words(args.text).map_err(|e| e.shift(args.offset))?;
    let text: Vec<_> = raw.iter().map(|w| crate::shell::lex::unquote(w.1)).collect();
    let words: Vec<&str> = text.iter().map(|w| w.as_ref()).collect();
    let usage = LAB.usage;
    let labs = sh.labs.clone().ok_or_else(|| Error::unsupported(crate::msg!("lab-not-in-this-run")))?;
    match words.as_slice() {
        ["new", name] => labs.new_lab(std::path::Path::new(name)),
        ["check", path] => {
            let (o, head, ok) = labs.check(std::path::Path::new(path))?;
            if !ok {
                return Err(Error::state(head).hint(crate::msg!("lab-hint-check-table")));
            }
            Ok(o.note(head))
        }
        ["grade", path, rest @ ..] if !rest.is_empty() => {
            let mut jobs = labs.default_jobs();
            let mut subs = Vec::new();
            for (w, typed) in rest.iter().zip(&raw[2..]) {
                // A quoted word is a file, never an option.
                match w.strip_prefix("jobs=").filter(|_| !typed.1.starts_with(['"', '\''])) {
                    Some(n) => {
                        jobs = n
                            .parse()
                            .ok()
                            .filter(|n| *n > 0)
                            .ok_or_else(|| Error::usage(crate::msg!("lab-bad-jobs", jobs = n)).hint(usage))?;
                    }
                    None => subs.push(std::path::PathBuf::from(w)),
                }
            }
            let (head, o, json) = labs.grade(std::path::Path::new(path), &subs, jobs)?;
            Ok(o.note(head).with("submissions", json))
        }
        _ => Err(Error::usage(crate::msg!("lab-needs-sub")).hint(usage).column(args.offset)),
    }
}
