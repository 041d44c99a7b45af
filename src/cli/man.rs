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

/// The manual page, as `man` reads it.
pub fn page() -> Vec<u8> {
    let cmd = super::Cli::command();
    let man = clap_mangen::Man::new(cmd).title("PLCSH").date(env!("CARGO_PKG_VERSION")).manual("plcsh manual");
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
    buf
}

/// The SHELL COMMANDS section: every command of the interactive shell and of `-c`, with its
/// forms and what it does, from the command registry.
fn shell_commands() -> String {
    let mut s = String::from(".SH \"SHELL COMMANDS\"\n");
    s.push_str(&roff_text(
        "Typed at the plcsh> prompt, given to -c (several separated by ;) or run from Lua with plcsh.exec. \
         help lists them by group, help COMMAND shows a command's forms.",
    ));
    s.push('\n');
    for c in crate::shell::commands::COMMANDS {
        s.push_str(".TP\n");
        let forms: Vec<String> = crate::shell::commands::forms::of(c).into_iter().map(|f| f.text).collect();
        s.push_str(&format!("\\fB{}\\fR\n", roff_text(&forms.join("\n.br\n")).replace("\n\\&.br", "\n.br")));
        s.push_str(&roff_text(c.summary));
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
                    ".P", ".LP"
                ]
                .contains(&macro_),
                "a line read as a roff request: {l}"
            );
        }
    }
}
