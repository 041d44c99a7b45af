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

/// The completion script for `shell`.
pub fn script(shell: Shell) -> Vec<u8> {
    let mut cmd = super::Cli::command();
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
                    let _ = writeln!(out, "wrote {p}");
                }
                0
            }
            Err(e) => {
                eprintln!("plcsh: cannot write completions into {}: {e}", dir.display());
                1
            }
        };
    }
    match shell {
        Some(s) => i32::from(out.write_all(&script(s)).is_err()),
        None => {
            eprintln!("plcsh completions: name a shell (bash, zsh, fish, powershell) or give --write DIR");
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
}
