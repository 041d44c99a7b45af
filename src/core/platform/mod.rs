//! The operating system's services apart from transports: stop signals (Ctrl-C, SIGTERM,
//! SIGHUP; on Windows Ctrl-C, Ctrl-Break and closing the console window), the terminal's
//! size, the host's time zone, CPU time, and ending a child process politely.
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
    discard_typed_ahead, durable_rename, install_stop_handlers, interrupt_child, keep_c_shims, name_file, stop_signal,
    terminal_size, terminate_child, thread_cpu_time, unnamed_file, utc_offset,
};

/// The stop signals' numbers as exit statuses use them (128 + number), on every system:
/// what Windows' console events are mapped to.
pub mod code {
    pub const HUP: i32 = 1;
    pub const INT: i32 = 2;
    pub const TERM: i32 = 15;
}
