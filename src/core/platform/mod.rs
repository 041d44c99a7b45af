//! The operating system's services apart from transports: stop signals (Ctrl-C, SIGTERM,
//! SIGHUP; on Windows Ctrl-C, Ctrl-Break and closing the console window), the terminal's
//! size and whether it takes escape codes ([`escapes`]), the host's time zone, CPU time,
//! ending a child process politely, and the words help and hints use for this system's
//! files, ports and stops ([`words`]).
//!
//! [`unix`] and `windows` offer the same functions; this file picks one, so the rest of
//! the program (families, shell, CLI) never names an operating system. Together with
//! `core::link` (ports, ptys, sockets) these are the only places that may.

#[cfg(unix)]
pub mod unix;
#[cfg(unix)]
use unix as sys;
#[cfg(windows)]
pub mod windows;
#[cfg(windows)]
use windows as sys;

pub use sys::{
    create_private_dir, discard_typed_ahead, durable_rename, install_stop_handlers, interrupt_child, keep_c_shims,
    name_file, open_no_follow, stop_signal, terminal_size, terminate_child, thread_cpu_time, ui_language, unnamed_file,
    utc_offset,
};

/// The language tag of a Windows LANGID (`GetUserDefaultUILanguage`): its primary language
/// (low 10 bits) and, for Chinese, its script by sub-language (`0x0804` zh-CN and `0x1004`
/// zh-SG are Simplified; `0x0404` zh-TW, `0x0C04` zh-HK, `0x1404` zh-MO Traditional).
/// Pure, so tested on every system; `core::msg::Lang::from_tag` reads the result.
pub fn langid_tag(id: u16) -> &'static str {
    match (id & 0x3ff, id >> 10) {
        (0x09, _) => "en",
        (0x19, _) => "ru",
        (0x04, 0x01 | 0x03 | 0x05) => "zh-TW",
        (0x04, _) => "zh-CN",
        _ => "und",
    }
}

#[cfg(test)]
mod language_tests {
    #[test]
    fn langids_name_their_languages() {
        assert_eq!(super::langid_tag(0x0409), "en");
        assert_eq!(super::langid_tag(0x0419), "ru");
        assert_eq!(super::langid_tag(0x0804), "zh-CN");
        assert_eq!(super::langid_tag(0x1004), "zh-CN");
        assert_eq!(super::langid_tag(0x0404), "zh-TW");
        assert_eq!(super::langid_tag(0x0C04), "zh-TW");
        assert_eq!(super::langid_tag(0x0407), "und");
    }
}

/// The bytes of `path`, read without following a symbolic link in its last component
/// ([`open_no_follow`]), at most `cap` bytes (a longer file is refused, never read whole).
pub fn read_no_follow(path: &std::path::Path, cap: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let f = open_no_follow(path)?;
    let mut out = Vec::new();
    f.take(cap.saturating_add(1)).read_to_end(&mut out)?;
    if out.len() as u64 > cap {
        return Err(std::io::Error::other(format!("longer than {cap} bytes")));
    }
    Ok(out)
}

/// Whether `path` itself is a symbolic link (on Windows a junction too).
pub fn is_link(path: &std::path::Path) -> bool {
    std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink())
}

/// A standard stream that output with escape codes may go to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stream {
    Stdout,
    Stderr,
}

/// Whether escape codes — colour, erasing a line, moving the cursor for an in-place redraw —
/// may be written to `stream`: it is a terminal, and on Windows its console was switched to
/// process them ([`enable_escapes`]; a console that refuses shows them as `←[31m`). This is
/// the one place that decides it; where it says no, output is plain (no colour, and `watch`
/// prints line by line).
pub fn escapes(stream: Stream) -> bool {
    use std::io::IsTerminal;
    let terminal = match stream {
        Stream::Stdout => std::io::stdout().is_terminal(),
        Stream::Stderr => std::io::stderr().is_terminal(),
    };
    terminal && sys::console_escapes(stream)
}

/// Whether colour may be written to `stream`: [`escapes`], and `NO_COLOR` unset or empty
/// (no-color.org). In-place redraws do not depend on `NO_COLOR`, only on [`escapes`].
pub fn colour(stream: Stream) -> bool {
    escapes(stream) && !no_color()
}

/// `NO_COLOR` is set to something.
pub fn no_color() -> bool {
    std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty())
}

/// At start-up: lets the console process escape codes on standard output and error where
/// they are consoles (Windows: ENABLE_VIRTUAL_TERMINAL_PROCESSING; a terminal on Unix always
/// does). Called once early; [`escapes`] does it too if it was not.
pub fn enable_escapes() {
    sys::enable_escapes();
}

/// The environment variable that makes plcsh act as if the console could not be switched
/// to escape codes (`PLCSH_CONSOLE_VT=off`): for a console that accepts the switch but draws
/// them badly, and for tests of the plain fallback. Read on Windows only.
pub const CONSOLE_VT_ENV: &str = "PLCSH_CONSOLE_VT";

/// The words help texts and hints use for this system (one place, so the rest of the
/// program never names an operating system): a serial port, the profile file, how a served
/// line is reached, the stops. The macros give them as literals, for `concat!` in help
/// texts and tables.
pub mod words {
    /// A serial port's name, as examples show it (`COM3` on Windows, `/dev/ttyUSB0` elsewhere).
    #[cfg(windows)]
    macro_rules! port {
        () => {
            "COM3"
        };
    }
    #[cfg(not(windows))]
    macro_rules! port {
        () => {
            "/dev/ttyUSB0"
        };
    }
    pub(crate) use port;

    /// Where the device profiles are read from when neither `--config` nor `PLCSH_CONFIG`
    /// says, as the user writes it (`crate::paths::config_file` resolves the same place).
    #[cfg(windows)]
    macro_rules! profile_file {
        () => {
            r"%APPDATA%\plcsh\config\devices.toml"
        };
    }
    #[cfg(target_os = "macos")]
    macro_rules! profile_file {
        () => {
            "~/Library/Application Support/plcsh/devices.toml"
        };
    }
    #[cfg(not(any(windows, target_os = "macos")))]
    macro_rules! profile_file {
        () => {
            "~/.config/plcsh/devices.toml"
        };
    }
    pub(crate) use profile_file;

    /// Where `sim serve` puts a simulated serial device for other programs on this system.
    #[cfg(windows)]
    macro_rules! served_line {
        () => {
            "on a TCP port (raw or RFC 2217, which a COM port pair such as com0com's can reach)"
        };
    }
    #[cfg(not(windows))]
    macro_rules! served_line {
        () => {
            "on a pty or a TCP port (raw or RFC 2217)"
        };
    }
    pub(crate) use served_line;
    /// Which of [`served_line`]'s two texts this system's is, as the message catalogue's
    /// `cli-sub-sim` selects it: `tcp` on Windows, `pty` elsewhere.
    #[cfg(windows)]
    pub const SERVED: &str = "tcp";
    #[cfg(not(windows))]
    pub const SERVED: &str = "pty";

    /// A serial port's name, as examples show it.
    pub const PORT: &str = port!();
    /// The default profile file, as the user writes it.
    pub const PROFILE_FILE: &str = profile_file!();

    /// The name of the polite stop that is not Ctrl-C, as the stop cause says it.
    pub fn stop_name(code: i32) -> &'static str {
        super::sys::stop_name(code)
    }
}

/// The stop signals' numbers as exit statuses use them (128 + number), on every system:
/// what Windows' console events are mapped to.
pub mod code {
    pub const HUP: i32 = 1;
    pub const INT: i32 = 2;
    pub const TERM: i32 = 15;
}
