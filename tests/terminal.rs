//! The REPL driven in a real terminal (issue 8 "what it must show"): tmux runs plcsh in a
//! pseudo-terminal, `send-keys` types, `capture-pane` reads the screen. Shows tab completion of
//! an SM register with its meaning, the inline hint, a `watch` that redraws in place and `plot`.
//! Skipped (with a message) when tmux is not installed; `.ci/run` installs it.

mod common;
use std::process::Command;
use std::time::{Duration, Instant};

struct Tmux {
    socket: String,
}

impl Tmux {
    fn start(home: &std::path::Path) -> Option<Tmux> {
        if Command::new("tmux").arg("-V").output().map(|o| !o.status.success()).unwrap_or(true) {
            eprintln!("tmux is not installed: skipping the terminal test (apt-get install tmux)");
            return None;
        }
        let t = Tmux { socket: format!("plcsh-test-{}", std::process::id()) };
        let cmd = format!(
            "env HOME={h} XDG_DATA_HOME={h}/data XDG_CONFIG_HOME={h}/config LANG=C.UTF-8 TERM=xterm-256color {bin}",
            h = home.display(),
            bin = common::bin()
        );
        let ok = t.tmux(&["-f", "/dev/null", "new-session", "-d", "-x", "110", "-y", "45", "-s", "t", &cmd]);
        assert!(ok, "tmux new-session failed");
        Some(t)
    }

    fn tmux(&self, args: &[&str]) -> bool {
        Command::new("tmux")
            .args(["-u", "-L", &self.socket])
            .args(args)
            .env("LANG", "C.UTF-8")
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
