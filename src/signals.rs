//! Stopping signals: SIGINT (Ctrl-C), SIGTERM (`timeout`, CI, systemd) and SIGHUP (a
//! dropped SSH session) all raise the session's interrupt flag, so a running command or Lua
//! script stops where it checks the flag and its `plcsh.on_abort` handlers run (PSTOP,
//! servo disable …). The process then exits with 128 + the signal (130, 143, 129), as
//! shells report a process a signal ended.
//!
//! On Windows, Ctrl-C, Ctrl-Break and closing the console window play the parts of SIGINT,
//! SIGTERM and SIGHUP (`core::platform::windows`), with the same exit statuses.
//!
//! A second signal of the same kind while the first is being handled ends the process at
//! once (the user means it). At an idle prompt nothing is running that could notice the
//! flag, so a watcher thread ends the process there itself; the simulator's retained
//! state does not depend on a clean exit (it is made durable as it is written).

use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// The last stopping signal received (0: none).
static RECEIVED: AtomicI32 = AtomicI32::new(0);
/// True while the shell waits for a line at the prompt (nothing to interrupt).
static IDLE: AtomicBool = AtomicBool::new(false);

/// Installs the handlers for the session's interrupt flag (the platform's stop signals:
/// [`crate::core::platform::install_stop_handlers`]).
pub fn install(interrupt: &Arc<AtomicBool>) {
    crate::core::platform::install_stop_handlers(interrupt, &RECEIVED);
}

/// Starts the watcher that ends the process on a signal received at an idle prompt. Only a
/// prompt is ever idle, so a one-shot command (`-c`) never starts it.
fn start_watcher() {
    static STARTED: std::sync::Once = std::sync::Once::new();
    STARTED.call_once(|| {
        std::thread::Builder::new()
            .name("signals".into())
            .spawn(|| loop {
                std::thread::sleep(Duration::from_millis(50));
                let sig = RECEIVED.load(Ordering::SeqCst);
                if sig != 0 && IDLE.load(Ordering::SeqCst) {
                    std::process::exit(128 + sig);
                }
            })
            .ok();
    });
}

/// The exit status a received SIGTERM or SIGHUP asks for (143, 129), if one arrived.
pub fn exit_status() -> Option<i32> {
    match RECEIVED.load(Ordering::SeqCst) {
        0 => None,
        sig => Some(128 + sig),
    }
}

/// Marks the prompt as waiting for input (true) or running a line (false).
pub fn set_idle(idle: bool) {
    if idle {
        start_watcher();
    }
    IDLE.store(idle, Ordering::SeqCst);
}
