//! The REPL driven in a real terminal: tmux runs plcsh in a
//! pseudo-terminal, `send-keys` types, `capture-pane` reads the screen. Shows tab completion of
//! an SM register with its meaning, the inline hint, a `watch` that redraws in place and `plot`.
//! Skipped (with a message) when tmux is not installed; `.ci/run` installs it.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use std::process::Command;
use std::time::{Duration, Instant};

struct Tmux {
    socket: String,
}

impl Tmux {
    fn start(home: &std::path::Path) -> Option<Tmux> {
        Tmux::start_sized(home, 110, 45)
    }

    fn start_sized(home: &std::path::Path, width: u16, height: u16) -> Option<Tmux> {
        if Command::new("tmux").arg("-V").output().map(|o| !o.status.success()).unwrap_or(true) {
            common::skipped("tmux (apt-get install tmux)");
            return None;
        }
        // One tmux server per test (tests run in parallel threads of one process).
        static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let t = Tmux { socket: format!("plcsh-test-{}-{n}", std::process::id()) };
        let cmd = format!(
            "env HOME={h} XDG_DATA_HOME={h}/data XDG_CONFIG_HOME={h}/config LANG=C.UTF-8 TERM=xterm-256color {bin}",
            h = home.display(),
            bin = common::bin()
        );
        let ok = t.tmux(&[
            "-f",
            "/dev/null",
            "new-session",
            "-d",
            "-x",
            &width.to_string(),
            "-y",
            &height.to_string(),
            "-s",
            "t",
            &cmd,
        ]);
        assert!(ok, "tmux new-session failed");
        Some(t)
    }

    fn tmux(&self, args: &[&str]) -> bool {
        Command::new("tmux")
            .args(["-u", "-L", &self.socket])
            .args(args)
            .env("LANG", "C.UTF-8")
            .env("PLCSH_LANG", "en")
            .status()
            .map(|s| s.success())
            .unwrap_or(false)
    }

    fn keys(&self, keys: &[&str]) {
        let mut a = vec!["send-keys", "-t", "t"];
        a.extend_from_slice(keys);
        assert!(self.tmux(&a));
    }

    fn literal(&self, text: &str) {
        assert!(self.tmux(&["send-keys", "-t", "t", "-l", text]));
    }

    fn screen(&self) -> String {
        let o = Command::new("tmux")
            .args(["-u", "-L", &self.socket, "capture-pane", "-p", "-t", "t"])
            .env("LANG", "C.UTF-8")
            .output()
            .expect("capture-pane");
        String::from_utf8_lossy(&o.stdout).into_owned()
    }

    /// The screen with lines the pane wrapped joined again (`capture-pane -J`).
    fn joined_screen(&self) -> String {
        let o = Command::new("tmux")
            .args(["-u", "-L", &self.socket, "capture-pane", "-p", "-J", "-t", "t"])
            .env("LANG", "C.UTF-8")
            .output()
            .expect("capture-pane");
        String::from_utf8_lossy(&o.stdout).into_owned()
    }

    /// Waits for the screen to satisfy `ok` (a readiness condition, not a timing assertion:
    /// the deadline only turns a hang into a failure with the screen shown).
    fn wait_for(&self, what: &str, ok: impl Fn(&str) -> bool) -> String {
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            let s = self.screen();
            if ok(&s) {
                return s;
            }
            assert!(Instant::now() < deadline, "waited for {what}; screen:\n{s}");
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        self.tmux(&["kill-server"]);
    }
}

#[test]
fn completion_hints_watch_and_plot_in_a_real_terminal() {
    let home = std::env::temp_dir().join(format!("plcsh-tmux-home-{}", std::process::id()));
    std::fs::create_dir_all(&home).unwrap();
    let Some(t) = Tmux::start(&home) else { return };
    t.wait_for("the prompt", |s| s.contains("plc(sim)>"));

    // Tab completion of an SM register: SMB6<Tab><Tab> lists the candidates with their meaning.
    t.literal("get SMB6");
    t.keys(&["Tab"]);
    t.keys(&["Tab"]);
    let s = t.wait_for("the SMB6x candidates", |s| s.contains("SMB67") && s.contains("control byte"));
    assert!(s.lines().any(|l| l.contains("SMB67") && l.contains("PTO0/PWM0 (Q0.0) control byte")), "{s}");
    // Completing further: SMB67 is now unique with "7"; Tab leaves "get SMB67" and the hint shows its meaning.
    t.literal("7");
    t.wait_for("the inline hint", |s| {
        s.lines().any(|l| l.contains("plc(sim)> get SMB67") && l.contains("— PTO0/PWM0"))
    });
    t.keys(&["C-u"]);

    // watch redraws in place: after 6 samples the screen holds exactly one table.
    t.literal("watch SM0.5 VW0 every=200ms count=6");
    t.keys(&["Enter"]);
    let s = t.wait_for("the sixth sample", |s| s.contains("sample 6 ") && s.matches("plc(sim)>").count() >= 2);
    assert_eq!(s.matches("Ctrl-C stops").count(), 1, "one table, redrawn in place:\n{s}");
    assert_eq!(s.matches("  SM0.5").count(), 1, "{s}");

    // trace then plot: a braille chart with axes.
    t.keys(&["C-l"]);
    t.literal("trace SM0.5 every=20ms for=1200ms; plot SM0.5 width=50 height=4");
    t.keys(&["Enter"]);
    // The last label is the last sample's wall-clock time (about 1.2s), so only its shape is checked.
    let s = t.wait_for("the plot", |s| {
        s.contains("└──") && s.lines().any(|l| l.trim_start().starts_with("0s") && l.trim_end().ends_with('s'))
    });
    assert!(s.contains("1 ┤") && s.contains("0 ┤"), "{s}");
    assert!(s.chars().any(|c| ('\u{2801}'..='\u{28FF}').contains(&c)), "braille dots drawn:\n{s}");
    t.literal("quit");
    t.keys(&["Enter"]);
    let _ = std::fs::remove_dir_all(&home);
}

/// A commissioning checklist pasted into the REPL: every line runs in order, as if typed, with
/// the usual rule inside one line (after a failing command the rest of that line is skipped).
/// Once with bracketed paste (tmux `paste-buffer -p` marks the block: it arrives as one input),
/// once without (the lines arrive as keystrokes typed ahead of the prompt).
#[test]
fn pasted_blocks_run_every_line_in_order() {
    for bracketed in [true, false] {
        let home = std::env::temp_dir().join(format!("plcsh-tmux-paste-{}-{bracketed}", std::process::id()));
        std::fs::create_dir_all(&home).unwrap();
        let Some(t) = Tmux::start(&home) else { return };
        t.wait_for("the prompt", |s| s.contains("plc(sim)>"));
        let block = "set VW0=11\nget VW0\nget VW2; get Q0.9; set VW4=99\nset VW6=33\nget VW4 VW6\n";
        assert!(t.tmux(&["set-buffer", "-b", "p", block]));
        let mut paste = vec!["paste-buffer", "-d", "-b", "p", "-t", "t"];
        if bracketed {
            paste.push("-p");
            // With bracketed paste the block waits in the editor until Enter, as in bash.
        }
        assert!(t.tmux(&paste));
        if bracketed {
            t.wait_for("the pasted block", |s| s.contains("get VW4 VW6"));
            t.keys(&["Enter"]);
        }
        let s = t.wait_for("the last pasted line's output", |s| s.contains("VW6  33"));
        assert!(s.contains("11"), "set VW0=11 then get VW0 ran:\n{s}");
        assert!(s.contains("Q0.9"), "the bad operand is reported:\n{s}");
        // `set VW4=99` came after the failing command on its line, so VW4 still reads 0.
        // The output after the last line ran (the echo `plc(sim)> get VW4 VW6`).
        let lines: Vec<&str> = s.lines().collect();
        let at = lines.iter().rposition(|l| l.starts_with("plc(sim)> get VW4 VW6")).expect("the last line echoed");
        let after = &lines[at + 1..];
        assert!(after.iter().any(|l| l.starts_with("VW6") && l.contains("33")), "{s}");
        assert!(after.iter().any(|l| l.trim_end() == "VW4  0"), "VW4 was not set:\n{s}");
        // In order: VW0's value shows before the error, the error before VW6's.
        let pos = |p: &str| s.find(p).unwrap_or_else(|| panic!("{p} missing:\n{s}"));
        assert!(pos("VW0  11") < pos("error[operand]") && pos("error[operand]") < pos("VW6  33"), "{s}");
        t.literal("quit");
        t.keys(&["Enter"]);
        drop(t);
        let _ = std::fs::remove_dir_all(&home);
    }
}

/// The first screens a user sees fit an 80-column terminal: the banner, `help`, `help sim`,
/// `help servo`, `models` and the completion menu are at most 80 columns wide (details behind
/// `help COMMAND` / `models MODEL`), and a menu line cut to fit ends between words.
#[test]
fn help_and_models_fit_80_columns() {
    let home = std::env::temp_dir().join(format!("plcsh-tmux-80-{}", std::process::id()));
    std::fs::create_dir_all(&home).unwrap();
    let Some(t) = Tmux::start_sized(&home, 80, 60) else { return };
    let s = t.wait_for("the prompt", |s| s.contains("plc(sim)>"));
    assert!(s.contains("Devices: plc"), "{s}");
    let full: Vec<&str> = s.lines().filter(|l| l.chars().count() >= 80).collect();
    assert!(full.is_empty(), "the banner wraps at 80 columns:\n{s}");
    for (cmd, expect) in [
        ("help", "help COMMAND"),
        ("models", "models MODEL"),
        ("help sim", "sub-commands"),
        ("help servo", "sub-commands"),
    ] {
        t.keys(&["C-l"]);
        t.literal(cmd);
        t.keys(&["Enter"]);
        let s = t.wait_for(cmd, |s| s.contains(expect) && s.matches("plc(sim)>").count() >= 2);
        // A line wrapped by the terminal fills all 80 columns and continues below: none may.
        let full: Vec<&str> = s.lines().filter(|l| l.chars().count() >= 80).collect();
        assert!(full.is_empty(), "`{cmd}` wraps at 80 columns:\n{s}");
    }
    // The completion menu on an empty line: every command with its summary, one a line,
    // each cut between two words to fit.
    t.keys(&["C-l"]);
    t.keys(&["Tab"]);
    t.keys(&["Tab"]);
    let s = t.wait_for("the command menu", |s| s.contains("connect") && s.contains("eeprom"));
    let full: Vec<&str> = s.lines().filter(|l| l.chars().count() >= 80).collect();
    assert!(full.is_empty(), "the completion menu wraps at 80 columns:\n{s}");
    let cut: Vec<&str> = s.lines().filter(|l| l.trim_end().ends_with('…')).collect();
    assert!(!cut.is_empty(), "long summaries are cut:\n{s}");
    for l in &cut {
        let kept = l.trim_end().trim_end_matches('…');
        let name = kept.split_whitespace().next().unwrap();
        let summary = plcsh::shell::commands::find(name).expect("a command").summary();
        let shown = kept[name.len()..].trim_start();
        assert!(
            summary.starts_with(shown) && summary[shown.len()..].starts_with([' ', ',', ';', ':']),
            "`{l}` ends inside a word of `{summary}`"
        );
    }
    t.keys(&["C-u"]);
    // A long inline hint (the servo usage) is cut at the edge instead of wrapping under the prompt.
    t.keys(&["C-l"]);
    t.literal("servo ");
    let s = t.wait_for("the servo hint", |s| s.lines().any(|l| l.starts_with("plc(sim)> servo ") && l.contains('…')));
    let prompt: Vec<&str> = s.lines().skip_while(|l| !l.starts_with("plc(sim)> servo ")).collect();
    assert!(prompt[0].chars().count() < 80, "{s}");
    assert!(prompt.get(1).is_none_or(|l| l.trim().is_empty()), "nothing wrapped below the prompt:\n{s}");
    t.keys(&["C-u"]);
    t.literal("quit");
    t.keys(&["Enter"]);
    drop(t);
    let _ = std::fs::remove_dir_all(&home);
}

/// Ctrl-C during a command in the REPL stops it and returns to the prompt; the rest of the
/// line and the rest of a pasted block do not run (they would write VW10 and VW12).
#[test]
fn ctrl_c_in_the_repl_returns_to_the_prompt_without_running_the_rest() {
    let home = std::env::temp_dir().join(format!("plcsh-tmux-ctrlc-{}", std::process::id()));
    std::fs::create_dir_all(&home).unwrap();
    let Some(t) = Tmux::start(&home) else { return };
    t.wait_for("the prompt", |s| s.contains("plc(sim)>"));
    t.literal("watch VW0 every=100ms; set VW10=5");
    t.keys(&["Enter"]);
    t.wait_for("a sample", |s| s.contains("sample 2 "));
    t.keys(&["C-c"]);
    t.wait_for("the prompt again", |s| s.trim_end().ends_with("plc(sim)>"));
    // A pasted block: the watch, then a write that must not run after the Ctrl-C.
    t.keys(&["C-l"]);
    t.wait_for("a clear screen", |s| !s.contains("sample"));
    assert!(t.tmux(&["set-buffer", "-b", "q", "watch VW0 every=100ms\nset VW12=5\n"]));
    assert!(t.tmux(&["paste-buffer", "-d", "-b", "q", "-p", "-t", "t"]));
    // With bracketed paste the block waits in the editor until Enter, as in bash.
    t.wait_for("the pasted block", |s| s.contains("set VW12=5"));
    t.keys(&["Enter"]);
    t.wait_for("a sample of the pasted watch", |s| s.contains("sample 2 "));
    t.keys(&["C-c"]);
    t.wait_for("the prompt again", |s| s.trim_end().ends_with("plc(sim)>"));
    t.keys(&["C-l"]);
    t.literal("get VW10 VW12");
    t.keys(&["Enter"]);
    // The typed line shows both names too: wait for the result lines themselves.
    let s = t.wait_for("the values", |s| s.lines().any(|l| l.trim_start().starts_with("VW12 ")));
    assert!(s.lines().any(|l| l.trim_start().starts_with("VW10") && l.trim_end().ends_with(" 0")), "{s}");
    assert!(s.lines().any(|l| l.trim_start().starts_with("VW12") && l.trim_end().ends_with(" 0")), "{s}");
}

/// Two shells in two terminals on the same default state file: the second says once that the
/// file is taken and runs a `plc` that keeps nothing, instead of refusing to open.
#[test]
fn a_second_shell_on_the_same_state_file_opens_with_a_warning() {
    let home = std::env::temp_dir().join(format!("plcsh-tmux-two-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&home);
    std::fs::create_dir_all(&home).unwrap();
    let Some(first) = Tmux::start(&home) else { return };
    first.wait_for("the first prompt", |s| s.contains("plc(sim)>"));
    first.literal("set VW3700=42");
    first.keys(&["Enter"]);
    let Some(second) = Tmux::start(&home) else { return };
    second.wait_for("the second prompt", |s| s.contains("plc(sim)>"));
    // The warning as one line, however the pane wrapped it.
    let s = second.joined_screen();
    assert!(s.contains("is in use by process") && s.contains("keeps nothing"), "{s}");
    second.literal("set VW3700=7; get VW3700");
    second.keys(&["Enter"]);
    second.wait_for("the second shell's own plc", |s| s.contains("VW3700  7"));
    first.literal("get VW3700");
    first.keys(&["Enter"]);
    first.wait_for("the first shell keeps its value", |s| s.contains("VW3700  42"));
    drop((first, second));
    let _ = std::fs::remove_dir_all(&home);
}

/// Two shells open at once under one user: each keeps its lines in the history file (the
/// one that quits later appends to what the other saved, never rewrites it from its own copy).
#[test]
fn two_shells_at_once_both_keep_their_history() {
    let home = std::env::temp_dir().join(format!("plcsh-tmux-history-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&home);
    std::fs::create_dir_all(&home).unwrap();
    let Some(a) = Tmux::start(&home) else { return };
    let Some(b) = Tmux::start(&home) else { return };
    a.wait_for("the first prompt", |s| s.contains("plc(sim)>"));
    b.wait_for("the second prompt", |s| s.contains("plc(sim)>"));
    a.literal("get VW10");
    a.keys(&["Enter"]);
    a.wait_for("the first shell's answer", |s| s.contains("VW10  0"));
    b.literal("get VW12");
    b.keys(&["Enter"]);
    b.wait_for("the second shell's answer", |s| s.contains("VW12  0"));
    let file = home.join("data").join("plcsh").join("history.txt");
    let read = || std::fs::read_to_string(&file).unwrap_or_default();
    let wait_file = |what: &str, ok: &dyn Fn(&str) -> bool| {
        let deadline = Instant::now() + Duration::from_secs(30);
        while !ok(&read()) {
            assert!(Instant::now() < deadline, "waited for {what}; history file:\n{}", read());
            std::thread::sleep(Duration::from_millis(50));
        }
    };
    a.literal("quit");
    a.keys(&["Enter"]);
    wait_file("the first shell's line", &|t| t.contains("get VW10"));
    b.literal("quit");
    b.keys(&["Enter"]);
    wait_file("the second shell's line", &|t| t.contains("get VW12"));
    let text = read();
    assert!(text.contains("get VW10") && text.contains("get VW12"), "both shells' lines are kept:\n{text}");
    let _ = std::fs::remove_dir_all(&home);
}
