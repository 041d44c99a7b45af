//! The console and the words plcsh shows, as a user of this system meets them.
//!
//! Words (every system): `--help` names this system's default profile file, `sim --help`
//! says how a served line is reached here, and a port that is not there gets a hint naming
//! this system's ports (`COM3` on Windows, `/dev/ttyUSB0` elsewhere).
//!
//! The console (Windows, run by `.ci/windows` under Wine in a terminal, where Wine gives the
//! process a console): plcsh switches the console it inherits to process escape codes at
//! start-up (ENABLE_VIRTUAL_TERMINAL_PROCESSING, which a classic console has off), and with
//! `PLCSH_CONSOLE_VT=off` — acting as a console that refuses — it leaves the mode alone and
//! writes its error and `watch`'s samples without escape codes (read back from the console's
//! screen buffer).

mod common;
use common::{plcsh, Start};

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn help_names_this_systems_profile_file_and_served_lines() {
    let out = plcsh().arg("--help").output_retrying().unwrap();
    let help = text(&out.stdout);
    assert!(out.status.success(), "{help}");
    let sim = text(&plcsh().args(["sim", "--help"]).output_retrying().unwrap().stdout);
    if cfg!(windows) {
        assert!(help.contains(r"%APPDATA%\plcsh\config\devices.toml"), "{help}");
        assert!(!help.contains("~/.config"), "{help}");
        assert!(!sim.contains("pty") && sim.contains("TCP port") && sim.contains("COM port pair"), "{sim}");
    } else {
        assert!(help.contains("/plcsh/devices.toml") && !help.contains("%APPDATA%"), "{help}");
        assert!(sim.contains("pty"), "{sim}");
    }
}

#[test]
fn a_missing_port_gets_a_hint_with_this_systems_port_names() {
    let port = if cfg!(windows) { "COM9" } else { "/dev/ttyPLCSHMISSING9" };
    let out = plcsh()
        .args(["-d", &format!("rtu:{port}"), "-c", "get VW0"])
        .stdin(std::process::Stdio::null())
        .output_retrying()
        .unwrap();
    let err = text(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert!(err.contains("serial port") && err.contains(port), "{err}");
    if cfg!(windows) {
        assert!(err.contains("COM3") && !err.contains("/dev/"), "{err}");
    } else {
        assert!(err.contains("/dev/ttyUSB0") && !err.contains("COM3"), "{err}");
    }
}

/// A command for a servo drive or a UMPK when none is open hints how to open one, with this
/// system's port name.
#[test]
fn a_missing_servo_or_umpk_gets_a_hint_with_this_systems_port_name() {
    for line in ["close servo; servo status", "umpk info"] {
        let out =
            plcsh().args(["--state", "none", "-c", line]).stdin(std::process::Stdio::null()).output_retrying().unwrap();
        let err = text(&out.stderr);
        assert!(!out.status.success() && err.contains("open one with --device"), "{line}: {err}");
        if cfg!(windows) {
            assert!(err.contains(":COM3") && !err.contains("/dev/"), "{line}: {err}");
        } else {
            assert!(err.contains(":/dev/ttyUSB0") && !err.contains("COM3"), "{line}: {err}");
        }
    }
}

#[cfg(windows)]
mod console {
    use super::common::{plcsh, Start};
    use windows_sys::Win32::Foundation::HANDLE;
    use windows_sys::Win32::System::Console::{
        GetConsoleMode, GetConsoleScreenBufferInfo, GetStdHandle, ReadConsoleOutputCharacterW, SetConsoleMode,
        CONSOLE_MODE, CONSOLE_SCREEN_BUFFER_INFO, COORD, ENABLE_VIRTUAL_TERMINAL_PROCESSING, STD_OUTPUT_HANDLE,
    };

    /// The console on standard output, when this test process has one.
    fn console() -> Option<HANDLE> {
        // SAFETY: the process's standard output handle and a mode we own.
        unsafe {
            let h = GetStdHandle(STD_OUTPUT_HANDLE);
            let mut m: CONSOLE_MODE = 0;
            (GetConsoleMode(h, &mut m) != 0).then_some(h)
        }
    }

    fn mode(h: HANDLE) -> CONSOLE_MODE {
        let mut m: CONSOLE_MODE = 0;
        // SAFETY: a console handle of this process and a mode we own.
        assert!(unsafe { GetConsoleMode(h, &mut m) } != 0);
        m
    }

    fn set_mode(h: HANDLE, m: CONSOLE_MODE) {
        // SAFETY: as above.
        assert!(unsafe { SetConsoleMode(h, m) } != 0, "{}", std::io::Error::last_os_error());
    }

    /// The last `n` rows of the console's screen buffer up to the cursor, as text.
    fn last_rows(h: HANDLE, n: i16) -> String {
        // SAFETY: a console handle, an info struct and a buffer we own, read within its size.
        unsafe {
            let mut info: CONSOLE_SCREEN_BUFFER_INFO = std::mem::zeroed();
            assert!(GetConsoleScreenBufferInfo(h, &mut info) != 0);
            let width = info.dwSize.X.max(1) as usize;
            let top = (info.dwCursorPosition.Y - n).max(0);
            let rows = (info.dwCursorPosition.Y - top + 1) as usize;
            let mut buf = vec![0u16; width * rows];
            let mut read = 0u32;
            let at = COORD { X: 0, Y: top };
            ReadConsoleOutputCharacterW(h, buf.as_mut_ptr(), buf.len() as u32, at, &mut read);
            String::from_utf16_lossy(&buf[..read as usize])
        }
    }

    /// Whether a console is required here: `.ci/windows` runs this file in a terminal and
    /// says so; elsewhere (output captured) there is no console to check.
    fn required() -> bool {
        std::env::var_os("PLCSH_WINE_CONSOLE").is_some()
    }

    /// The inherited console is switched to escape codes at start-up; with the refusal asked
    /// for, it is left alone and the error is written without escape codes.
    #[test]
    fn the_console_takes_escape_codes_or_output_stays_plain() {
        let Some(h) = console() else {
            assert!(!required(), "PLCSH_WINE_CONSOLE is set but standard output is no console");
            super::common::skipped("a console on standard output (.ci/windows runs this in a terminal)");
            return;
        };
        let plain = mode(h) & !ENABLE_VIRTUAL_TERMINAL_PROCESSING;
        set_mode(h, plain);
        let st = plcsh().args(["-c", "get VW0"]).stdin(std::process::Stdio::null()).status_retrying();
        assert!(st.success());
        let switched = mode(h);
        set_mode(h, plain);
        assert_eq!(switched, plain | ENABLE_VIRTUAL_TERMINAL_PROCESSING, "plcsh switched its console to escape codes");

        let st = plcsh()
            .args(["-c", "get NOSUCH"])
            .env("PLCSH_CONSOLE_VT", "off")
            .stdin(std::process::Stdio::null())
            .status_retrying();
        assert!(!st.success());
        assert_eq!(mode(h), plain, "a console that refuses is left as it was");
        // The row the error starts on (the test harness writes its own rows around it).
        let shown = last_rows(h, 8);
        let at = shown.find("error[operand]").unwrap_or_else(|| panic!("no error on the console: {shown:?}"));
        let row = &shown[shown[..at].rfind("  ").unwrap_or(0)..];
        let row = &row[..row.find("hint:").unwrap_or(row.len())];
        assert!(!row.contains('\u{1b}') && !row.contains("[31m") && !row.contains('←'), "{row:?}");

        // `watch` prints its plain form: one line per sample, no erase-line codes.
        let st = plcsh()
            .args(["-c", "watch VW0 SMB28 every=10ms count=3"])
            .env("PLCSH_CONSOLE_VT", "off")
            .stdin(std::process::Stdio::null())
            .status_retrying();
        assert!(st.success());
        let shown = last_rows(h, 8);
        let at = shown.rfind("VW0").unwrap_or_else(|| panic!("no watch output on the console: {shown:?}"));
        let rows = &shown[shown[..at].rfind("watch VW0").map_or(0, |i| i + 9)..];
        assert!(!rows.contains('\u{1b}') && !rows.contains("[2K") && !rows.contains('←'), "{rows:?}");
    }

    /// Ctrl-Break (SIGTERM's part on Windows, docs/windows.md "Stopping") stops `sim serve` with
    /// 0 and `watch` with 143. It is sent with GenerateConsoleCtrlEvent to a process group of
    /// plcsh's own; Wine 8 cannot deliver a console event to another process (the call fails),
    /// so there the test prints its one `skipped:` line. Ctrl-C cannot be sent to one process
    /// group at all (a new group starts with Ctrl-C off): its handling is unit-tested in
    /// core::platform::windows.
    #[test]
    fn ctrl_break_stops_long_running_commands_with_the_documented_status() {
        use std::io::BufRead;
        use std::os::windows::process::CommandExt;
        use windows_sys::Win32::System::Console::{GenerateConsoleCtrlEvent, CTRL_BREAK_EVENT};
        use windows_sys::Win32::System::Threading::CREATE_NEW_PROCESS_GROUP;
        let cases: [(&str, &[&str], i32); 2] = [
            ("sim serve", &["sim", "serve", "--tcp", "127.0.0.1:0", "--state", "none"], 0),
            ("watch", &["--state", "none", "--json", "-c", "watch VW0 every=20ms"], 143),
        ];
        for (what, args, want) in cases {
            let mut child = plcsh()
                .args(args)
                .stdin(std::process::Stdio::null())
                .stdout(std::process::Stdio::piped())
                .stderr(std::process::Stdio::null())
                .creation_flags(CREATE_NEW_PROCESS_GROUP)
                .spawn_retrying()
                .expect("plcsh starts");
            let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
            assert!(lines.next().is_some(), "{what}: a first line");
            // The output is read to its end meanwhile (a full pipe must not hold the stop up).
            let reader = std::thread::spawn(move || lines.count());
            // SAFETY: a console event to the process group the child leads.
            if unsafe { GenerateConsoleCtrlEvent(CTRL_BREAK_EVENT, child.id()) } == 0 {
                let _ = child.kill();
                let _ = child.wait();
                let _ = reader.join();
                super::common::skipped(
                    "a console that delivers Ctrl-Break to another process (GenerateConsoleCtrlEvent fails under Wine 8)",
                );
                return;
            }
            let sent = std::time::Instant::now();
            let status = loop {
                if let Some(st) = child.try_wait().unwrap() {
                    break st;
                }
                if sent.elapsed() > std::time::Duration::from_secs(30) {
                    let _ = child.kill();
                    panic!("{what} still runs 30 s after Ctrl-Break");
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            };
            let _ = reader.join();
            assert_eq!(status.code(), Some(want), "{what} stopped by Ctrl-Break");
        }
    }

    trait Status {
        fn status_retrying(&mut self) -> std::process::ExitStatus;
    }

    impl Status for std::process::Command {
        fn status_retrying(&mut self) -> std::process::ExitStatus {
            let mut child = self.spawn_retrying().expect("plcsh starts");
            child.wait().expect("plcsh ends")
        }
    }
}
