//! `plcsh man`: the manual page in roff, made by the binary from its own clap definition
//! (every flag, its default and its environment variable, every subcommand) and from the
//! shell's command registry (every shell command with what it does), so the page cannot drift
//! from the program. `plcsh man > plcsh.1; man ./plcsh.1` reads it; the release archives carry
//! the same file.

use clap::CommandFactory;

/// Text as roff body text: backslashes escaped, and a line that would start with a control
/// character (`.` or `'`) kept as text.
fn roff_text(s: &str) -> String {
    let s = s.replace('\\', "\\e");
    s.lines()
        .map(|l| if l.starts_with(['.', '\'']) { format!("\\&{l}") } else { l.to_string() })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The page's date: the newest day in CHANGELOG.md (`### 2026-11-29 — …`), the last day its
/// contents changed — the same on every build of one source, and a date `man` and mandoc read
/// as one (the version goes in the source slot: `plcsh 0.1.0`).
fn date() -> &'static str {
    include_str!("../../CHANGELOG.md")
        .lines()
        .filter_map(|l| l.strip_prefix("### "))
        .map(|l| l.split_whitespace().next().unwrap_or(""))
        .find(|d| {
            d.len() == 10
                && d.bytes().enumerate().all(|(i, b)| if i == 4 || i == 7 { b == b'-' } else { b.is_ascii_digit() })
        })
        .unwrap_or("")
}

/// Roff that every formatter reads alike: each character beyond ASCII as its Unicode escape
/// (`…` → `\[u2026]`; groff without preconv and mandoc both read those), and the blank line
/// between two `.br` that clap_mangen puts before an option's possible values as the one `.sp`
/// it means.
fn portable(page: &str) -> String {
    let page = page.replace("\n.br\n\n.br\n", "\n.sp\n");
    let mut out = String::with_capacity(page.len());
    for c in page.chars() {
        if c.is_ascii() {
            out.push(c);
        } else {
            out.push_str(&format!("\\[u{:04X}]", u32::from(c)));
        }
    }
    out
}

/// The manual page, as `man` reads it.
pub fn page() -> Vec<u8> {
    let cmd = super::localise::command(super::Cli::command());
    let version = concat!("plcsh ", env!("CARGO_PKG_VERSION"));
    let man = clap_mangen::Man::new(cmd)
        .title("PLCSH")
        .date(date())
        .source(version)
        .manual(crate::msg!("cli-man-manual").text);
    let mut buf = Vec::new();
    // Writing into a Vec cannot fail.
    let _ = man.render_title(&mut buf);
    let _ = man.render_name_section(&mut buf);
    let _ = man.render_synopsis_section(&mut buf);
    let _ = man.render_description_section(&mut buf);
    let _ = man.render_options_section(&mut buf);
    let _ = man.render_subcommands_section(&mut buf);
    buf.extend_from_slice(shell_commands().as_bytes());
    let _ = man.render_version_section(&mut buf);
    portable(&String::from_utf8_lossy(&buf)).into_bytes()
}

/// The SHELL COMMANDS section: every command of the interactive shell and of `-c`, with its
/// forms and what it does, from the command registry.
fn shell_commands() -> String {
    let mut s = format!(".SH \"{}\"\n", crate::msg!("man-shell-commands"));
    s.push_str(&roff_text(&crate::msg!("man-shell-commands-intro")));
    s.push('\n');
    for c in crate::shell::commands::COMMANDS {
        s.push_str(".TP\n");
        // The first form is the tag; the others follow in bold, each on a line of its own, and
        // the description starts on a line of its own after the last (never run into it).
        let forms: Vec<String> = crate::shell::commands::forms::of(c).into_iter().map(|f| f.text).collect();
        for (i, f) in forms.iter().enumerate() {
            s.push_str(&format!("\\fB{}\\fR\n", roff_text(f)));
            if i > 0 {
                s.push_str(".br\n");
            }
        }
        s.push_str(&roff_text(&c.summary()));
        s.push('\n');
    }
    s
}

/// `plcsh man`: writes the page; returns the exit status.
pub fn run(out: &mut dyn std::io::Write) -> i32 {
    i32::from(out.write_all(&page()).is_err())
}

#[cfg(test)]
mod tests {
    /// A command's forms stand each on a line of their own, and its description starts on a
    /// line after the last (never `pto status N start a single-segment…`).
    #[test]
    fn the_last_form_never_runs_into_the_description() {
        let page = String::from_utf8(super::page()).unwrap();
        let pto = crate::shell::commands::find("pto").unwrap();
        let at = page.find("\\fBpto status N\\fR\n").expect("pto's last form on the page");
        let after = &page[at..].lines().nth(1).unwrap_or("");
        assert_eq!(*after, ".br", "a break after the last form");
        assert!(page[at..].lines().nth(2).unwrap_or("").starts_with(&super::roff_text(&pto.summary())[..20]));
    }

    /// The page is plain ASCII roff (every other character as `\[uXXXX]`) with a date in the
    /// date slot, and groff (`-ww`, every warning) and mandoc (`-T lint -W warning`) read it
    /// without a warning. Run where they are installed (.ci/run installs both); one `skipped:`
    /// line elsewhere.
    #[test]
    fn groff_and_mandoc_read_the_page_without_a_warning() {
        let page = super::page();
        assert!(page.is_ascii(), "raw UTF-8 on the page");
        let text = String::from_utf8(page.clone()).unwrap();
        let th = text.lines().find(|l| l.starts_with(".TH")).unwrap_or("");
        assert!(
            th.starts_with(".TH PLCSH 1 20") && th.contains(concat!("\"plcsh ", env!("CARGO_PKG_VERSION"), "\"")),
            "{th}"
        );
        let dir = std::env::temp_dir().join(format!("plcsh-man-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("plcsh.1");
        std::fs::write(&file, &page).unwrap();
        let runs = |tool: &str| std::process::Command::new(tool).arg("--version").output().is_ok();
        let mut missing = Vec::new();
        for (tool, args) in [("groff", &["-ww", "-man", "-z"][..]), ("mandoc", &["-T", "lint", "-W", "warning"][..])] {
            if !runs(tool) {
                missing.push(tool);
                continue;
            }
            let o = std::process::Command::new(tool).args(args).arg(&file).output().unwrap();
            let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
            assert!(said.trim().is_empty(), "{tool} {}:\n{said}", args.join(" "));
        }
        let _ = std::fs::remove_dir_all(&dir);
        if !missing.is_empty() {
            // The Windows stage runs this under Wine, where the Unix man tools are not programs
            // it can start: the page is the same bytes there, read by the Linux run.
            assert!(
                std::env::var_os("CI").is_none() || cfg!(windows),
                "{missing:?} required when CI is set (.ci/run installs them)"
            );
            // Straight to the terminal: cargo test hides a passing test's eprintln!.
            use std::io::Write;
            let _ = writeln!(
                std::io::stderr().lock(),
                "skipped: needs {} (apt-get install groff mandoc) (groff_and_mandoc_read_the_page_without_a_warning)",
                missing.join(" and ")
            );
        }
    }

    /// The page is roff that names every subcommand and every shell command.
    #[test]
    fn the_page_names_every_subcommand_and_shell_command() {
        use clap::CommandFactory;
        let page = String::from_utf8(super::page()).unwrap();
        // clap_mangen's two lines that define the apostrophe for groff come first.
        let th = page.lines().find(|l| !l.starts_with(".ie") && !l.starts_with(".el")).unwrap_or("");
        assert!(th.starts_with(".TH PLCSH 1 "), "{th}");
        for sub in super::super::Cli::command().get_subcommands() {
            assert!(page.contains(&format!("plcsh\\-{}", sub.get_name())), "{} is not on the page", sub.get_name());
        }
        for c in crate::shell::commands::COMMANDS {
            assert!(page.contains(&format!("\\fB{}", c.name)), "{} is not on the page", c.name);
        }
        assert!(page.contains("\\-\\-json"), "the flags are on the page");
        // No body line starts with a control character by accident.
        for l in page.lines().filter(|l| l.starts_with('.')) {
            let macro_ = l.split_whitespace().next().unwrap_or("");
            assert!(
                [
                    ".TH", ".SH", ".SS", ".TP", ".PP", ".br", ".B", ".IP", ".RS", ".RE", ".ie", ".el", ".nf", ".fi",
                    ".P", ".LP", ".sp"
                ]
                .contains(&macro_),
                "a line read as a roff request: {l}"
            );
        }
    }
}
