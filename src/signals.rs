//! Stopping signals: SIGINT (Ctrl-C), SIGTERM (`timeout`, CI, systemd) and SIGHUP (a
//! dropped SSH session) all raise the session's interrupt flag, so a running command or Lua
//! script stops where it checks the flag and its `plcsh.on_abort` handlers run (PSTOP,
//! servo disable …). The process then exits with 128 + the signal (130, 143, 129), as
//! shells report a process a signal ended.
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

const STOPPING: [i32; 3] = [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM, signal_hook::consts::SIGHUP];

/// Installs the handlers for the session's interrupt flag.
pub fn install(interrupt: &Arc<AtomicBool>) {
    for sig in STOPPING {
        // Order matters (signal-hook's documented pattern): the conditional shutdown sees
        // the flag as the previous signal left it, then the flag is raised.
        let _ = signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, interrupt.clone());
        let _ = signal_hook::flag::register(sig, interrupt.clone());
        if sig != signal_hook::consts::SIGINT {
            // SAFETY: the action only stores to an atomic, which is async-signal-safe.
            let _ = unsafe { signal_hook::low_level::register(sig, move || RECEIVED.store(sig, Ordering::SeqCst)) };
        }
    }
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
