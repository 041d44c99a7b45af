//! The Unix side of [`super`]: POSIX signals through signal-hook and tokio, `TIOCGWINSZ`,
//! `localtime_r`, `CLOCK_THREAD_CPUTIME_ID`, SIGINT to a child.

use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// SIGINT (Ctrl-C), SIGTERM (`timeout`, CI, systemd) and SIGHUP (a dropped SSH session):
/// the first one while none is pending is stored in `received` and raises `interrupt`;
/// later ones are ignored until the stop was handled (`received` back at 0), so a second
/// signal — GNU `timeout` sends SIGTERM to the child and then to its process group — cannot
/// interrupt the abort handlers the first one started. The grace period that bounds them is
/// kept by `crate::signals`.
pub fn install_stop_handlers(interrupt: &Arc<AtomicBool>, received: &'static AtomicI32) {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    for sig in [SIGINT, SIGTERM, SIGHUP] {
        let flag = interrupt.clone();
        // SAFETY: the action only does atomic operations, which are async-signal-safe.
        let _ = unsafe {
            signal_hook::low_level::register(sig, move || {
                if received.compare_exchange(0, sig, Ordering::SeqCst, Ordering::SeqCst).is_ok() {
                    flag.store(true, Ordering::SeqCst);
                }
            })
        };
    }
}

/// The user's language as POSIX says to look for messages: the first set of `LC_ALL`,
/// `LC_MESSAGES`, `LANG` (an empty one counts as unset).
pub fn ui_language() -> Option<String> {
    ["LC_ALL", "LC_MESSAGES", "LANG"].iter().find_map(|k| std::env::var(k).ok().filter(|v| !v.is_empty()))
}

/// A Unix terminal takes escape codes as it is: nothing to switch on.
pub fn enable_escapes() {}

/// Creates a folder only this user can enter (mode 0700).
pub fn create_private_dir(path: &std::path::Path) -> std::io::Result<()> {
    use std::os::unix::fs::DirBuilderExt;
    std::fs::DirBuilder::new().mode(0o700).create(path)
}

/// Opens `path` for reading, refusing a symbolic link in its last component (`O_NOFOLLOW`:
/// the call fails with `ELOOP`, reported as "a symbolic link").
pub fn open_no_follow(path: &std::path::Path) -> std::io::Result<std::fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    std::fs::OpenOptions::new().read(true).custom_flags(libc::O_NOFOLLOW).open(path).map_err(|e| {
        if e.raw_os_error() == Some(libc::ELOOP) {
            std::io::Error::other("a symbolic link")
        } else {
            e
        }
    })
}

/// A Unix terminal takes escape codes ([`super::escapes`] asks whether it is one).
pub fn console_escapes(_stream: super::Stream) -> bool {
    true
}

/// The stop cause's name for a signal's number: SIGTERM, SIGHUP, else Ctrl-C (SIGINT, or the
/// flag raised in the process).
pub fn stop_name(code: i32) -> &'static str {
    match code {
        super::code::TERM => "SIGTERM",
        super::code::HUP => "SIGHUP",
        _ => "Ctrl-C",
    }
}

/// A future that completes on Ctrl-C or SIGTERM (a server's stop). The handlers are
/// installed when this is called, so a signal sent right after is not lost.
pub fn stop_signal() -> std::io::Result<impl std::future::Future<Output = ()>> {
    use tokio::signal::unix::{signal, SignalKind};
    let mut int = signal(SignalKind::interrupt())?;
    let mut term = signal(SignalKind::terminate())?;
    let mut hup = signal(SignalKind::hangup())?;
    Ok(async move {
        tokio::select! {
            _ = int.recv() => {},
            _ = term.recv() => {},
            _ = hup.recv() => {},
        }
    })
}

/// Drops what was typed or pasted ahead on a terminal's standard input and not read yet
/// (after a Ctrl-C, queued input must not run); nothing when input is not a terminal.
pub fn discard_typed_ahead() {
    // SAFETY: tcflush on file descriptor 0; it fails harmlessly when 0 is not a terminal.
    unsafe {
        if libc::isatty(libc::STDIN_FILENO) == 1 {
            libc::tcflush(libc::STDIN_FILENO, libc::TCIFLUSH);
        }
    }
}

/// (columns, rows) of the terminal on standard output, or `None` when it is not a terminal.
pub fn terminal_size() -> Option<(usize, usize)> {
    // SAFETY: TIOCGWINSZ fills a `winsize` we own; a failing call leaves it zeroed.
    let mut ws: libc::winsize = unsafe { std::mem::zeroed() };
    let r = unsafe { libc::ioctl(libc::STDOUT_FILENO, libc::TIOCGWINSZ, &mut ws) };
    (r == 0 && ws.ws_col > 0 && ws.ws_row > 0).then_some((usize::from(ws.ws_col), usize::from(ws.ws_row)))
}

/// Seconds east of UTC of the host's zone at Unix time `t` (0 if unknown).
pub fn utc_offset(t: i64) -> i64 {
    // SAFETY: localtime_r writes only into `tm`, which we own; `t` is a valid time_t.
    unsafe {
        let tt: libc::time_t = t as libc::time_t;
        let mut tm: libc::tm = std::mem::zeroed();
        if libc::localtime_r(&tt, &mut tm).is_null() {
            return 0;
        }
        tm.tm_gmtoff as i64
    }
}

/// Renames `from` over `to` (both in `dir`) and makes the rename durable: an fsync of the
/// directory, so a returned `Ok` survives a power cut.
pub fn durable_rename(from: &std::path::Path, to: &std::path::Path, dir: &std::path::Path) -> std::io::Result<()> {
    std::fs::rename(from, to)?;
    std::fs::File::open(dir).and_then(|d| d.sync_all())
}

/// A file in `dir` without a name (Linux `O_TMPFILE`), for [`crate::core::durable`]: its
/// content can be written and fsync'd before it is named, so a crash meanwhile leaves
/// nothing behind. `None` where the system or the file system has none (then a named
/// temporary file is used).
pub fn unnamed_file(dir: &std::path::Path) -> Option<std::fs::File> {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::fs::OpenOptionsExt;
        std::fs::OpenOptions::new().write(true).mode(0o666).custom_flags(libc::O_TMPFILE).open(dir).ok()
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = dir;
        None
    }
}

/// Gives a file from [`unnamed_file`] the name `to` (which must not exist): `linkat` of its
/// `/proc/self/fd` entry, following the link.
pub fn name_file(f: &std::fs::File, to: &std::path::Path) -> std::io::Result<()> {
    use std::os::fd::AsRawFd;
    use std::os::unix::ffi::OsStrExt;
    let from = std::ffi::CString::new(format!("/proc/self/fd/{}", f.as_raw_fd())).map_err(std::io::Error::other)?;
    let to = std::ffi::CString::new(to.as_os_str().as_bytes()).map_err(std::io::Error::other)?;
    // SAFETY: two NUL-terminated paths that live across the call; no other memory is involved.
    let r =
        unsafe { libc::linkat(libc::AT_FDCWD, from.as_ptr(), libc::AT_FDCWD, to.as_ptr(), libc::AT_SYMLINK_FOLLOW) };
    if r == 0 {
        Ok(())
    } else {
        Err(std::io::Error::last_os_error())
    }
}

/// CPU time the calling thread has used.
pub fn thread_cpu_time() -> Duration {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: clock_gettime writes one timespec through a valid pointer.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    Duration::new(ts.tv_sec as u64, ts.tv_nsec as u32)
}

/// Asks a child to stop as `kill` or a service manager would (SIGTERM).
pub fn terminate_child(child: &std::process::Child) {
    // SAFETY: kill(2) on a process id; no memory is involved.
    unsafe {
        libc::kill(child.id() as libc::pid_t, libc::SIGTERM);
    }
}

/// Asks a child to stop as Ctrl-C would (SIGINT), so it can print its summary.
pub fn interrupt_child(child: &std::process::Child) {
    // SAFETY: kill(2) on a process id; no memory is involved.
    unsafe {
        libc::kill(child.id() as libc::pid_t, libc::SIGINT);
    }
}

/// Nothing to keep: the C library reads UTF-8 names as they are (Windows needs shims for Lua).
pub fn keep_c_shims() -> usize {
    0
}

#[cfg(test)]
mod tests {
    /// On Linux the content of a durable write exists without a name until it is named: a
    /// process killed meanwhile leaves no file behind.
    #[cfg(target_os = "linux")]
    #[test]
    fn an_unnamed_file_has_no_name_until_it_is_given_one() {
        use std::io::Write;
        let d = std::env::temp_dir().join(format!("plcsh-unnamed-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        let Some(mut f) = super::unnamed_file(&d) else {
            eprintln!("no O_TMPFILE on this file system; the named temporary file is used");
            return;
        };
        f.write_all(b"content").unwrap();
        f.sync_all().unwrap();
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 0, "nothing in the directory yet");
        super::name_file(&f, &d.join(".x.tmp")).unwrap();
        assert_eq!(std::fs::read(d.join(".x.tmp")).unwrap(), b"content");
        assert!(super::name_file(&f, &d.join(".x.tmp")).is_err(), "an existing name is not replaced");
        let _ = std::fs::remove_dir_all(&d);
    }
}
