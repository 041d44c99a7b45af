//! Stopping signals: SIGINT (Ctrl-C), SIGTERM (`timeout`, CI, systemd) and SIGHUP (a
//! dropped SSH session) raise the session's interrupt flag, so a running command or Lua
//! script stops where it checks the flag and its `plcsh.on_abort` handlers run (PSTOP,
//! servo disable …). The rest of the command line and any queued input are dropped; the
//! process then exits with 128 + the signal — 130 for Ctrl-C, 143 for SIGTERM, 129 for
//! SIGHUP — whichever command was running. In the interactive REPL a Ctrl-C instead returns
//! to the prompt (the rest of the line and what was typed or pasted ahead are dropped).
//!
//! On Windows, Ctrl-C, Ctrl-Break and closing the console window play the parts of SIGINT,
//! SIGTERM and SIGHUP (`core::platform::windows`), with the same exit statuses.
//!
//! **A second signal does not cut the handlers short.** The first signal is the stop; more
//! signals while it is handled are ignored (GNU `timeout` sends SIGTERM to the child and
//! then to its whole process group, so two arrive together). The handlers are bounded by
//! [`ABORT_GRACE`]: if the process has not finished its stop by then, a watcher ends it with
//! the first signal's status. SIGKILL ends it at once, as always. At an idle prompt (or
//! while a piped session waits for input) nothing is running that could notice the flag,
//! so the watcher ends the process there at once; the simulator's retained state does not
//! depend on a clean exit (it is made durable as it is written).
//!
//! **The watcher starts when it can have work.** A one-shot that reads and exits never
//! starts it (one thread less to create at every start): the first real sleep or wait
//! ([`crate::core::Clock::sleep_real`]), the first prompt ([`set_idle`]) and the first stop
//! noticed by the running work ([`cause`], which every interrupted command or script asks
//! before its abort handlers run) start it, once. A signal that comes before it starts is
//! not lost: the handlers have already raised the flag, and the watcher's first look sees it.

use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// How long the abort handlers of a stopped command or script may run before the process is
/// ended anyway (documented in the README, "A stop stops").
pub const ABORT_GRACE: Duration = Duration::from_secs(5);

/// The pending stopping signal (0: none): the first one received since the last was handled.
static RECEIVED: AtomicI32 = AtomicI32::new(0);
/// True while the shell waits for a line at the prompt (nothing to interrupt).
static IDLE: AtomicBool = AtomicBool::new(false);

/// Installs the handlers for the session's interrupt flag (the platform's stop signals:
/// [`crate::core::platform::install_stop_handlers`]). The watcher that keeps the grace
/// period starts later, when it can have work ([`start_watcher`]).
pub fn install(interrupt: &Arc<AtomicBool>) {
    crate::core::platform::install_stop_handlers(interrupt, &RECEIVED);
    crate::core::clock::before_sleep(start_watcher);
}

/// Starts, once per process, the watcher that ends the process on a signal received at an
/// idle prompt and on one whose stop has taken longer than [`ABORT_GRACE`], and wakes
/// sleeping waits when a signal raised the flag. Called by whatever may wait for a signal:
/// a sleep, a prompt, a stop being handled.
pub fn start_watcher() {
    static STARTED: std::sync::Once = std::sync::Once::new();
    STARTED.call_once(|| {
        std::thread::Builder::new()
            .name("signals".into())
            .spawn(|| {
                let mut since: Option<(i32, Instant)> = None;
                loop {
                    std::thread::sleep(Duration::from_millis(20));
                    let sig = RECEIVED.load(Ordering::SeqCst);
                    if sig == 0 {
                        since = None;
                        continue;
                    }
                    if since.is_none() {
                        // The flag is up: sleeping waits look at it now (core::Clock::sleep_real).
                        crate::core::Clock::wake_sleepers();
                    }
                    if IDLE.load(Ordering::SeqCst) {
                        std::process::exit(crate::core::exit::for_signal(sig));
                    }
                    let (s, t) = *since.get_or_insert((sig, Instant::now()));
                    if s != sig {
                        since = Some((sig, Instant::now()));
                    } else if t.elapsed() > ABORT_GRACE {
                        eprintln!("{}", crate::msg!("shell-stop-overdue", seconds = ABORT_GRACE.as_secs()));
                        std::process::exit(crate::core::exit::for_signal(sig));
                    }
                }
            })
            .ok();
    });
}

/// The exit status the pending stop asks for (130, 143, 129), if a signal arrived.
pub fn exit_status() -> Option<i32> {
    match RECEIVED.load(Ordering::SeqCst) {
        0 => None,
        sig => Some(crate::core::exit::for_signal(sig)),
    }
}

/// What stopped the work, for messages, in this system's words: `Ctrl-C`, `SIGTERM`,
/// `SIGHUP` (on Windows `Ctrl-Break`, `console closed`); Ctrl-C when no signal is pending
/// (the flag was raised in the process).
pub fn cause() -> &'static str {
    // A stop is being handled: its abort handlers get the grace period.
    start_watcher();
    crate::core::platform::words::stop_name(RECEIVED.load(Ordering::SeqCst))
}

/// True when the pending stop is a Ctrl-C (the REPL returns to its prompt on one).
pub fn is_ctrl_c() -> bool {
    RECEIVED.load(Ordering::SeqCst) == crate::core::platform::code::INT
}

/// The stop was handled and the session goes on (a Ctrl-C in the REPL): the next signal
/// counts again.
pub fn handled() {
    RECEIVED.store(0, Ordering::SeqCst);
}

/// Marks the prompt as waiting for input (true) or running a line (false).
pub fn set_idle(idle: bool) {
    if idle {
        start_watcher();
    }
    IDLE.store(idle, Ordering::SeqCst);
}
