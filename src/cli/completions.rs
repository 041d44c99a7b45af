//! `plcsh completions bash|zsh|fish|powershell`: shell completion scripts generated from the
//! clap definition by the binary itself (design guide, style 8), so they cannot drift from the
//! flags. The generated files are committed in `completions/`; a test regenerates them and
//! fails when they are stale. Regenerate with `cargo run -- completions --write completions/`
//! (or `PLCSH_BLESS=1 cargo test completions`).

use clap::CommandFactory;
use clap_complete::Shell;
use std::path::Path;

/// Every shell we ship a script for, with its file name in `completions/`.
pub const FILES: &[(Shell, &str)] = &[
    (Shell::Bash, "plcsh.bash"),
    (Shell::Zsh, "_plcsh"),
    (Shell::Fish, "plcsh.fish"),
    (Shell::PowerShell, "_plcsh.ps1"),
];

/// `cmd` without its hidden subcommands (`lab worker`, which `lab grade` runs itself), at
/// every level, so no shell completes them (nor `help lab worker`, made from the same tree).
fn without_hidden(cmd: clap::Command) -> clap::Command {
    let all = cmd.get_subcommands().count();
    let visible: Vec<clap::Command> = cmd.get_subcommands().filter(|s| !s.is_hide_set()).cloned().collect();
    if visible.len() == all {
        return cmd.mut_subcommands(without_hidden);
    }
    // clap cannot take a subcommand out: the command is made again with its own arguments,
    // texts and settings and the visible subcommands only.
    // (clap takes a name as `&'static str`: the few names of a one-shot generation are leaked.)
    let name: &'static str = Box::leak(cmd.get_name().to_string().into_boxed_str());
    let mut fresh = clap::Command::new(name)
        .subcommand_required(cmd.is_subcommand_required_set())
        .arg_required_else_help(cmd.is_arg_required_else_help_set());
    if let Some(a) = cmd.get_about() {
        fresh = fresh.about(a.clone());
    }
    if let Some(a) = cmd.get_long_about() {
        fresh = fresh.long_about(a.clone());
    }
    for a in cmd.get_arguments() {
        fresh = fresh.arg(a.clone());
    }
    fresh.subcommands(visible.into_iter().map(without_hidden))
}

/// The completion script for `shell`.
pub fn script(shell: Shell) -> Vec<u8> {
    let mut cmd = without_hidden(super::Cli::command());
    let mut buf = Vec::new();
    clap_complete::generate(shell, &mut cmd, "plcsh", &mut buf);
    buf
}

/// Writes every script into `dir`; returns the paths written.
pub fn write_all(dir: &Path) -> std::io::Result<Vec<String>> {
    std::fs::create_dir_all(dir)?;
    let mut written = Vec::new();
    for (shell, file) in FILES {
        let path = dir.join(file);
        std::fs::write(&path, script(*shell))?;
        written.push(path.display().to_string());
    }
    Ok(written)
}

/// `plcsh completions [SHELL] [--write DIR]`; returns the exit status.
pub fn run(shell: Option<Shell>, write: Option<&Path>, out: &mut dyn std::io::Write) -> i32 {
    if let Some(dir) = write {
        return match write_all(dir) {
            Ok(paths) => {
                for p in paths {
                    let _ = writeln!(out, "{}", crate::msg!("cli-completions-wrote", file = p.to_string()));
                }
                0
            }
            Err(e) => {
                eprintln!(
                    "{}",
                    crate::msg!(
                        "cli-completions-cannot-write",
                        dir = dir.display().to_string(),
                        reason = e.to_string()
                    )
                );
                1
            }
        };
    }
    match shell {
        Some(s) => i32::from(out.write_all(&script(s)).is_err()),
        None => {
            eprintln!("{}", crate::msg!("cli-completions-name-a-shell"));
            2
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The committed scripts match what the binary generates now.
    #[test]
    fn committed_completions_are_current() {
        // The committed scripts are made on Unix; on Windows the help texts in them name
        // Windows paths and lines (`core::platform::words`), so they differ by those words.
        if cfg!(windows) {
            println!("skipped: needs Unix help texts (the committed scripts are made on Unix)");
            return;
        }
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("completions");
        if std::env::var_os("PLCSH_BLESS").is_some() {
            write_all(&dir).unwrap();
        }
        for (shell, file) in FILES {
            let path = dir.join(file);
            let committed = std::fs::read(&path).unwrap_or_default();
            assert!(
                committed == script(*shell),
                "{} is stale or missing: regenerate with `cargo run -- completions --write completions/` \
                 (or `PLCSH_BLESS=1 cargo test completions`) and commit it",
                path.display()
            );
        }
    }

    #[test]
    fn scripts_know_the_subcommands_and_flags() {
        let bash = String::from_utf8(script(Shell::Bash)).unwrap();
        for word in ["completions", "devices", "models", "--config", "--device"] {
            assert!(bash.contains(word), "{word} missing from the bash script");
        }
    }

    /// A hidden subcommand (`lab worker`, run by `lab grade` itself) is completed by no shell,
    /// while its visible neighbours are.
    #[test]
    fn no_shell_completes_a_hidden_subcommand() {
        for shell in [Shell::Bash, Shell::Zsh, Shell::Fish, Shell::PowerShell] {
            let s = String::from_utf8(script(shell)).unwrap();
            assert!(s.contains("grade") && s.contains("check"), "{shell:?}: lab's visible subcommands");
            for as_a_name in ["'worker:", "\"worker\"", "'worker'", "grade worker", ",worker)", "__worker"] {
                assert!(!s.contains(as_a_name), "{shell:?} offers `lab worker` ({as_a_name})");
            }
        }
    }
}
