//! `plcsh sim serve`: serve simulators on pseudo-terminals for other programs.
//! This part: `--servo-pty LINK --servo-id 1[,2,…] [--servo-loop]` serves simulated Kinco
//! drives on one RS232 line (the logic is `servo::sim::serve`). Once the pty is open it
//! prints ONE readiness line of JSON on stdout —
//! `{"ready":true,"servo_pty":"/dev/pts/N","link":"LINK","ids":[1],"echo":false}` — then
//! serves until SIGINT/SIGTERM. The simulated drives follow the wall clock.

use crate::core::Clock;
use crate::servo::driver::parse_ids;
use crate::servo::sim::serve;
use std::io::Write;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

#[derive(clap::Args, Debug)]
pub struct ServeArgs {
    /// Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it.
    #[arg(long = "servo-pty", value_name = "LINK")]
    pub servo_pty: Option<PathBuf>,
    /// Drive ids on the servo line (several drives share it).
    #[arg(long = "servo-id", value_name = "ID[,ID…]", default_value = "1")]
    pub servo_id: String,
    /// RS232 loop mode: echo every request before the reply (connect with echo=1).
    #[arg(long = "servo-loop")]
    pub servo_loop: bool,
}

/// Runs the server; returns the exit status.
pub fn run(args: &ServeArgs) -> i32 {
    let Some(link) = &args.servo_pty else {
        eprintln!("plcsh sim serve: nothing to serve; give --servo-pty LINK");
        return 2;
    };
    let ids = match parse_ids(&args.servo_id) {
        Ok(v) => v,
        Err(m) => {
            eprintln!("plcsh sim serve: --servo-id: {m}");
            return 2;
        }
    };
    let stop = Arc::new(AtomicBool::new(false));
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        let _ = signal_hook::flag::register(sig, stop.clone());
    }
    let r = serve::serve_pty(Some(link), &ids, args.servo_loop, Clock::following(), &stop, |ready| {
        let mut line = serde_json::json!({"ready": true});
        if let (Some(m), serde_json::Value::Object(r)) = (line.as_object_mut(), serde_json::json!(ready)) {
            m.extend(r);
        }
        let mut out = std::io::stdout().lock();
        let _ = writeln!(out, "{line}");
        let _ = out.flush();
    });
    match r {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("plcsh sim serve: {e}");
            1
        }
    }
}
