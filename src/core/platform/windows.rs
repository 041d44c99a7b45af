//! The Windows side of [`super`]: console control events, the console's size and its
//! virtual-terminal mode, the time zone through the C runtime, thread CPU time.
//!
//! Escape codes: a classic console (conhost: cmd.exe or Windows PowerShell in their own
//! window) shows them as text unless ENABLE_VIRTUAL_TERMINAL_PROCESSING is on, and it is off
//! by default. [`enable_escapes`] turns it on for standard output and error at start-up;
//! where the console refuses (consoles before Windows 10 1511), [`console_escapes`] says no
//! and output stays plain.
//!
//! Console events map onto the Unix signals' exit statuses: Ctrl-C is SIGINT (130),
//! Ctrl-Break — what console tools and process managers send to stop a program politely —
//! is SIGTERM (143), and closing the console window, logging off or shutting down is SIGHUP
//! (129). For a close, Windows ends the process once the handler returns (or after about
//! five seconds): the handler waits there, up to [`CLOSE_GRACE`], so the abort handlers run
//! and the state is saved before the window goes.

use super::code;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::OnceLock;
use std::sync::{Arc, Mutex};
use std::time::Duration;
use windows_sys::core::BOOL;
use windows_sys::Win32::Foundation::HANDLE;
use windows_sys::Win32::Foundation::{FALSE, TRUE};
use windows_sys::Win32::System::Console::{
    FlushConsoleInputBuffer, GetConsoleMode, GetConsoleScreenBufferInfo, GetStdHandle, SetConsoleCtrlHandler,
    SetConsoleMode, CONSOLE_MODE, CONSOLE_SCREEN_BUFFER_INFO, CTRL_BREAK_EVENT, CTRL_CLOSE_EVENT, CTRL_C_EVENT,
    CTRL_LOGOFF_EVENT, CTRL_SHUTDOWN_EVENT, ENABLE_VIRTUAL_TERMINAL_PROCESSING, STD_ERROR_HANDLE, STD_INPUT_HANDLE,
    STD_OUTPUT_HANDLE,
};

/// How long a closing console waits for the abort handlers (Windows allows about 5 s).
pub const CLOSE_GRACE: Duration = Duration::from_millis(4500);

struct Handlers {
    interrupt: Arc<AtomicBool>,
    received: &'static AtomicI32,
}

/// The flag and the record the handler raises (the last install wins). Windows runs a console
/// handler on a thread of its own, so a lock is fine here (it is no signal handler).
static HANDLERS: Mutex<Option<Handlers>> = Mutex::new(None);

unsafe extern "system" fn on_console_event(event: u32) -> BOOL {
    let guard = HANDLERS.lock().unwrap_or_else(|p| p.into_inner());
    let Some(h) = guard.as_ref() else { return FALSE };
    let sig = match event {
        CTRL_C_EVENT => code::INT,
        CTRL_BREAK_EVENT => code::TERM,
        CTRL_CLOSE_EVENT | CTRL_LOGOFF_EVENT | CTRL_SHUTDOWN_EVENT => code::HUP,
        _ => return FALSE,
    };
    // The first event while none is pending raises the flag; later ones wait until the
    // stop was handled (as on Unix: the abort handlers it started are not cut short).
    if h.received.compare_exchange(0, sig, Ordering::SeqCst, Ordering::SeqCst).is_ok() {
        h.interrupt.store(true, Ordering::SeqCst);
    }
    drop(guard);
    if sig == code::HUP {
        // The process ends when this returns: give the main thread time to stop cleanly
        // (it exits the process itself when done).
        std::thread::sleep(CLOSE_GRACE);
    }
    TRUE
}

/// Console events: the first one while none is pending is stored in `received` (Ctrl-C as
/// SIGINT, Ctrl-Break as SIGTERM, closing as SIGHUP) and raises `interrupt`.
pub fn install_stop_handlers(interrupt: &Arc<AtomicBool>, received: &'static AtomicI32) {
    *HANDLERS.lock().unwrap_or_else(|p| p.into_inner()) = Some(Handlers { interrupt: interrupt.clone(), received });
    // SAFETY: registers a handler function with the signature Windows calls.
    unsafe {
        SetConsoleCtrlHandler(Some(on_console_event), TRUE);
    }
}

/// Whether standard output and error take escape codes, decided once (see [`enable_escapes`]).
static ESCAPES: OnceLock<[bool; 2]> = OnceLock::new();

/// The user's UI language (Settings › Time & language), as a tag: Windows programs speak the
/// language of the user's interface, not of the locale's number formats.
pub fn ui_language() -> Option<String> {
    // SAFETY: takes nothing, returns the user's UI language as a LANGID.
    let id = unsafe { windows_sys::Win32::Globalization::GetUserDefaultUILanguage() };
    Some(super::langid_tag(id).to_string())
}

/// Creates a folder for this user's own files. Windows has no mode bits: a folder in the
/// user's temporary folder (`%LOCALAPPDATA%\Temp`) inherits an access list that admits only
/// the user, administrators and the system.
pub fn create_private_dir(path: &std::path::Path) -> std::io::Result<()> {
    std::fs::create_dir(path)
}

/// Opens `path` for reading without following a reparse point in its last component
/// (`FILE_FLAG_OPEN_REPARSE_POINT`): a symbolic link or a junction opens as itself and is
/// refused as "a symbolic link".
pub fn open_no_follow(path: &std::path::Path) -> std::io::Result<std::fs::File> {
    use std::os::windows::fs::OpenOptionsExt;
    const FILE_FLAG_OPEN_REPARSE_POINT: u32 = 0x0020_0000;
    let f = std::fs::OpenOptions::new().read(true).custom_flags(FILE_FLAG_OPEN_REPARSE_POINT).open(path)?;
    if f.metadata()?.file_type().is_symlink() {
        return Err(std::io::Error::other("a symbolic link"));
    }
    Ok(f)
}

/// Turns on virtual-terminal processing for standard output and error where they are
/// consoles, once per process. `PLCSH_CONSOLE_VT=off` acts as if the console refused.
pub fn enable_escapes() {
    ESCAPES.get_or_init(|| {
        let refuse = std::env::var(super::CONSOLE_VT_ENV).is_ok_and(|v| v.eq_ignore_ascii_case("off"));
        // SAFETY: the handles are the process's standard streams; the calls fail harmlessly
        // on a handle that is not a console.
        unsafe { [vt_on(GetStdHandle(STD_OUTPUT_HANDLE), refuse), vt_on(GetStdHandle(STD_ERROR_HANDLE), refuse)] }
    });
}

/// Whether `stream`, when it is a terminal, takes escape codes.
pub fn console_escapes(stream: super::Stream) -> bool {
    enable_escapes();
    let both = ESCAPES.get().copied().unwrap_or([false, false]);
    both[match stream {
        super::Stream::Stdout => 0,
        super::Stream::Stderr => 1,
    }]
}

/// Switches the console behind `h` to process escape codes; true when it does (already, or
/// now). A handle that is no console — a pipe, a file, or the pipe of an MSYS2/Cygwin
/// terminal, which reads escape codes itself — needs nothing (true). With `refuse`, the mode
/// is left alone and a console without the mode counts as refusing.
///
/// # Safety
/// `h` is a handle of this process (or null/invalid, which the calls refuse).
unsafe fn vt_on(h: HANDLE, refuse: bool) -> bool {
    let mut mode: CONSOLE_MODE = 0;
    // SAFETY: `mode` is ours; see the function's contract for `h`.
    if unsafe { GetConsoleMode(h, &mut mode) } == 0 {
        return true;
    }
    if refuse {
        return false;
    }
    if mode & ENABLE_VIRTUAL_TERMINAL_PROCESSING != 0 {
        return true;
    }
    // SAFETY: as above.
    unsafe { SetConsoleMode(h, mode | ENABLE_VIRTUAL_TERMINAL_PROCESSING) != 0 }
}

/// The stop cause's name for an event's number: Ctrl-Break (stored as SIGTERM's number),
/// the console closing (SIGHUP's: "console closed"), else Ctrl-C.
pub fn stop_name(code: i32) -> &'static str {
    match code {
        code::TERM => "Ctrl-Break",
        code::HUP => "console closed",
        _ => "Ctrl-C",
    }
}

/// A future that completes on Ctrl-C, Ctrl-Break or a closing console (a server's stop).
pub fn stop_signal() -> std::io::Result<impl std::future::Future<Output = ()>> {
    let mut c = tokio::signal::windows::ctrl_c()?;
    let mut b = tokio::signal::windows::ctrl_break()?;
    let mut close = tokio::signal::windows::ctrl_close()?;
    Ok(async move {
        tokio::select! {
            _ = c.recv() => {},
            _ = b.recv() => {},
            _ = close.recv() => {},
        }
    })
}

/// Drops what was typed or pasted ahead in the console and not read yet (after a Ctrl-C,
/// queued input must not run); nothing when input is not a console.
pub fn discard_typed_ahead() {
    // SAFETY: the handle is the process's standard input; the call fails harmlessly when it
    // is not a console.
    unsafe {
        FlushConsoleInputBuffer(GetStdHandle(STD_INPUT_HANDLE));
    }
}

/// (columns, rows) of the console window on standard output, or `None` when it is not one.
pub fn terminal_size() -> Option<(usize, usize)> {
    // SAFETY: the handle is the process's standard output; the info struct is ours.
    unsafe {
        let h = GetStdHandle(STD_OUTPUT_HANDLE);
        let mut info: CONSOLE_SCREEN_BUFFER_INFO = std::mem::zeroed();
        if GetConsoleScreenBufferInfo(h, &mut info) == 0 {
            return None;
        }
        let cols = i32::from(info.srWindow.Right) - i32::from(info.srWindow.Left) + 1;
        let rows = i32::from(info.srWindow.Bottom) - i32::from(info.srWindow.Top) + 1;
        (cols > 0 && rows > 0).then_some((cols as usize, rows as usize))
    }
}

extern "C" {
    fn _localtime64_s(tm: *mut Tm, time: *const i64) -> i32;
    fn _mkgmtime64(tm: *mut Tm) -> i64;
}

/// The C runtime's `struct tm`.
#[repr(C)]
#[derive(Default)]
struct Tm {
    tm_sec: i32,
    tm_min: i32,
    tm_hour: i32,
    tm_mday: i32,
    tm_mon: i32,
    tm_year: i32,
    tm_wday: i32,
    tm_yday: i32,
    tm_isdst: i32,
}

/// Seconds east of UTC of the host's zone at Unix time `t` (0 if unknown): the local civil
/// time read back as if it were UTC, minus `t`.
pub fn utc_offset(t: i64) -> i64 {
    let mut tm = Tm::default();
    // SAFETY: both calls read and write only the `tm` we own.
    unsafe {
        if _localtime64_s(&mut tm, &t) != 0 {
            return 0;
        }
        let local = _mkgmtime64(&mut tm);
        if local == -1 {
            0
        } else {
            local - t
        }
    }
}

/// Renames `from` over `to` durably: MoveFileExW with MOVEFILE_WRITE_THROUGH returns only once
/// the rename is on disk (a directory cannot be fsync'd on Windows).
pub fn durable_rename(from: &std::path::Path, to: &std::path::Path, _dir: &std::path::Path) -> std::io::Result<()> {
    use std::os::windows::ffi::OsStrExt;
    use windows_sys::Win32::Storage::FileSystem::{MoveFileExW, MOVEFILE_REPLACE_EXISTING, MOVEFILE_WRITE_THROUGH};
    let wide = |p: &std::path::Path| p.as_os_str().encode_wide().chain(Some(0)).collect::<Vec<u16>>();
    let (f, t) = (wide(from), wide(to));
    // SAFETY: two NUL-terminated wide strings that live across the call.
    if unsafe { MoveFileExW(f.as_ptr(), t.as_ptr(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) } == 0 {
        return Err(std::io::Error::last_os_error());
    }
    Ok(())
}

/// Windows has no files without a name: [`crate::core::durable`] writes a named
/// temporary file.
pub fn unnamed_file(_dir: &std::path::Path) -> Option<std::fs::File> {
    None
}

/// Never called: [`unnamed_file`] gives no file to name.
pub fn name_file(_f: &std::fs::File, _to: &std::path::Path) -> std::io::Result<()> {
    Err(std::io::Error::from(std::io::ErrorKind::Unsupported))
}

/// CPU time the calling thread has used.
pub fn thread_cpu_time() -> Duration {
    use windows_sys::Win32::Foundation::FILETIME;
    use windows_sys::Win32::System::Threading::{GetCurrentThread, GetThreadTimes};
    let zero = FILETIME { dwLowDateTime: 0, dwHighDateTime: 0 };
    let (mut c, mut e, mut k, mut u) = (zero, zero, zero, zero);
    // SAFETY: the pseudo-handle of this thread and four FILETIMEs we own.
    unsafe { GetThreadTimes(GetCurrentThread(), &mut c, &mut e, &mut k, &mut u) };
    let ticks = |f: FILETIME| (u64::from(f.dwHighDateTime) << 32) | u64::from(f.dwLowDateTime);
    Duration::from_nanos((ticks(k) + ticks(u)).saturating_mul(100))
}

/// Stops a child (Windows has no SIGTERM to send to another process).
pub fn terminate_child(child: &std::process::Child) {
    interrupt_child(child);
}

/// Stops a child (Windows has no SIGINT to send to another console's process).
pub fn interrupt_child(child: &std::process::Child) {
    use windows_sys::Win32::System::Threading::{OpenProcess, TerminateProcess, PROCESS_TERMINATE};
    // SAFETY: opens and terminates the process by id; the handle is closed by the OS at exit.
    unsafe {
        let h = OpenProcess(PROCESS_TERMINATE, FALSE, child.id());
        if !h.is_null() {
            TerminateProcess(h, 1);
            windows_sys::Win32::Foundation::CloseHandle(h);
        }
    }
}

/// Lua's own file functions (`io.open`, `io.lines`, `dofile`, `loadfile`, `os.remove`,
/// `os.rename`) call the C library with UTF-8 names, which the Windows C library reads in the
/// ANSI code page: a script in `C:\Users\Иванов\…` could not open its own files. The Windows
/// build compiles Lua with these calls renamed (`.cargo/config.toml`, `CFLAGS_…windows…`), and
/// these functions take the UTF-8 name, make it UTF-16 and call the C library's wide forms.
mod utf8_stdio {
    use std::ffi::{c_char, c_int, c_void, CStr};

    extern "C" {
        fn _wfopen(name: *const u16, mode: *const u16) -> *mut c_void;
        fn _wfreopen(name: *const u16, mode: *const u16, f: *mut c_void) -> *mut c_void;
        fn _wremove(name: *const u16) -> c_int;
        fn _wrename(from: *const u16, to: *const u16) -> c_int;
    }

    /// A NUL-terminated UTF-16 copy of a UTF-8 C string (invalid UTF-8 replaced, as it could
    /// name no file anyway).
    unsafe fn wide(s: *const c_char) -> Vec<u16> {
        let text = unsafe { CStr::from_ptr(s) }.to_string_lossy();
        text.encode_utf16().chain(std::iter::once(0)).collect()
    }

    #[no_mangle]
    pub unsafe extern "C" fn plcsh_fopen(name: *const c_char, mode: *const c_char) -> *mut c_void {
        let (n, m) = unsafe { (wide(name), wide(mode)) };
        unsafe { _wfopen(n.as_ptr(), m.as_ptr()) }
    }

    #[no_mangle]
    pub unsafe extern "C" fn plcsh_freopen(name: *const c_char, mode: *const c_char, f: *mut c_void) -> *mut c_void {
        if name.is_null() {
            return unsafe { _wfreopen(std::ptr::null(), wide(mode).as_ptr(), f) };
        }
        let (n, m) = unsafe { (wide(name), wide(mode)) };
        unsafe { _wfreopen(n.as_ptr(), m.as_ptr(), f) }
    }

    #[no_mangle]
    pub unsafe extern "C" fn plcsh_remove(name: *const c_char) -> c_int {
        let n = unsafe { wide(name) };
        unsafe { _wremove(n.as_ptr()) }
    }

    #[no_mangle]
    pub unsafe extern "C" fn plcsh_rename(from: *const c_char, to: *const c_char) -> c_int {
        let (a, b) = unsafe { (wide(from), wide(to)) };
        unsafe { _wrename(a.as_ptr(), b.as_ptr()) }
    }

    /// The functions' addresses, taken so the linker keeps them for Lua in every binary.
    pub fn keep() -> [usize; 4] {
        [
            plcsh_fopen as *const () as usize,
            plcsh_freopen as *const () as usize,
            plcsh_remove as *const () as usize,
            plcsh_rename as *const () as usize,
        ]
    }
}

/// Keeps the UTF-8 C-library functions Lua is compiled against in the binary.
pub fn keep_c_shims() -> usize {
    std::hint::black_box(utf8_stdio::keep()).iter().sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The console events map onto the Unix signals' statuses: Ctrl-C raises the interrupt
    /// flag only (the shell tells it apart itself), Ctrl-Break is stored as SIGTERM. (Closing
    /// the window, SIGHUP, waits for the grace period before returning, so it is not run here.)
    #[test]
    fn console_events_raise_the_flag_and_record_the_signal() {
        static RECEIVED: AtomicI32 = AtomicI32::new(0);
        let flag = Arc::new(AtomicBool::new(false));
        install_stop_handlers(&flag, &RECEIVED);
        // SAFETY: calls the handler as Windows would, on this thread.
        assert_eq!(unsafe { on_console_event(CTRL_C_EVENT) }, TRUE);
        assert!(flag.load(Ordering::SeqCst));
        assert_eq!(RECEIVED.load(Ordering::SeqCst), code::INT);
        // A second event while the first is pending changes nothing.
        flag.store(false, Ordering::SeqCst);
        assert_eq!(unsafe { on_console_event(CTRL_BREAK_EVENT) }, TRUE);
        assert!(!flag.load(Ordering::SeqCst));
        assert_eq!(RECEIVED.load(Ordering::SeqCst), code::INT);
        // Once handled, the next one counts.
        RECEIVED.store(0, Ordering::SeqCst);
        assert_eq!(unsafe { on_console_event(CTRL_BREAK_EVENT) }, TRUE);
        assert!(flag.load(Ordering::SeqCst));
        assert_eq!(RECEIVED.load(Ordering::SeqCst), code::TERM);
        // An event that is not a stop is left to the next handler.
        assert_eq!(unsafe { on_console_event(99) }, FALSE);
    }

    /// A handle that is no console (a pipe, a file, nothing) needs no switch, refused or
    /// not: whether it is a terminal decides (`super::escapes`). The console itself is
    /// checked by tests/windows_console.rs, in a console under Wine.
    #[test]
    fn a_handle_that_is_no_console_needs_no_switch() {
        // SAFETY: a null handle, which the console calls refuse.
        unsafe {
            assert!(vt_on(std::ptr::null_mut(), false));
            assert!(vt_on(std::ptr::null_mut(), true));
        }
    }

    #[test]
    fn the_stop_causes_use_windows_words() {
        assert_eq!(stop_name(code::TERM), "Ctrl-Break");
        assert_eq!(stop_name(code::INT), "Ctrl-C");
        assert_eq!(stop_name(0), "Ctrl-C");
        assert_eq!(stop_name(code::HUP), "console closed");
    }

    #[test]
    fn the_time_zone_offset_is_whole_minutes_within_a_day() {
        let off = utc_offset(1_800_000_000);
        assert!(off.abs() <= 14 * 3600 && off % 60 == 0, "{off}");
    }
}
