//! `plcsh sim serve`: serves simulated devices on real transports so any client (an HMI,
//! mbpoll, pymodbus, plcsh itself) can use them, and a lab or CI needs no hardware.
//!
//! The K2 simulator is served over Modbus TCP (`--tcp`), Modbus RTU on a pseudo-terminal
//! (`--rtu-pty LINK`) and RTU over TCP (`--rtu-tcp`), all on one shared simulator. Network
//! addresses bind loopback unless a host is given (`--tcp 5020` = `127.0.0.1:5020`; port 0
//! picks a free port). When every transport is up, one JSON line on stdout names what was
//! bound (real ports, pty device, link) so scripts wait for it instead of sleeping. Ctrl-C
//! or SIGTERM stop it; the pty symlink is removed.
//!
//! `--agent [VB3400]` runs the PLC-side helper program's semantics once per simulated scan
//! (issue 5, `k2::sim::agent`), so SM registers and instructions are reachable over Modbus
//! exactly as on a K2 running `lib/k2_agent.il`.
//!
//! Simulated Kinco servo drives are served on their own pseudo-terminal (`--servo-pty LINK
//! --servo-id 1[,2,…] [--servo-loop]`, the logic is `servo::sim::serve`); their fields
//! (`servo_pty`, `link`, `ids`, `echo`) join the readiness line.
//!
//! Shape: each served family adds its endpoints in its own function ([`serve_k2`],
//! [`serve_servo`]) — it binds, spawns its tasks and adds its fields to the readiness line.

use super::Cli;
use crate::core::link::async_pty::AsyncPty;
use crate::core::{Clock, Error, Result};
use crate::k2::sim::modbus_server::{self, K2Service};
use crate::output::{self, Style};
use clap::{Args, Subcommand};
use serde_json::{json, Map, Value as Json};
use std::io::Write;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::{Arc, Mutex};
use tokio::net::TcpListener;
use tokio::task::JoinSet;

/// `plcsh sim …`
#[derive(Subcommand, Debug)]
pub enum SimCmd {
    /// Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP.
    Serve(ServeArgs),
}

#[derive(Args, Debug)]
pub struct ServeArgs {
    /// Modbus TCP on ADDR (`127.0.0.1:5020`, `5020`, `0` for a free port; loopback unless a host is given).
    #[arg(long, value_name = "ADDR")]
    pub tcp: Option<String>,
    /// Modbus RTU on a new pseudo-terminal, with a symlink to its device at LINK.
    #[arg(long = "rtu-pty", value_name = "LINK")]
    pub rtu_pty: Option<PathBuf>,
    /// Modbus RTU frames over TCP on ADDR (as a serial-to-Ethernet gateway carries them).
    #[arg(long = "rtu-tcp", value_name = "ADDR")]
    pub rtu_tcp: Option<String>,
    /// Modbus unit id (slave address) the K2 answers to; requests for other ids get no reply.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=247))]
    pub unit: u8,
    /// Run the PLC-side helper program (lib/k2_agent.il) with its mailbox at this V address.
    #[arg(long, value_name = "VB_ADDR", num_args = 0..=1, default_missing_value = "VB3400")]
    pub agent: Option<String>,
    /// Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it.
    #[arg(long = "servo-pty", value_name = "LINK")]
    pub servo_pty: Option<PathBuf>,
    /// Drive ids on the servo line (several drives share it).
    #[arg(long = "servo-id", value_name = "ID[,ID…]", default_value = "1")]
    pub servo_id: String,
    /// RS232 loop mode: echo every request before the reply (connect with echo=1).
    #[arg(long = "servo-loop")]
    pub servo_loop: bool,
    /// Network connections served at once (per transport); more are closed on accept.
    #[arg(long = "max-connections", value_name = "N", default_value_t = 64)]
    pub max_connections: usize,
    /// Close a network connection that sends nothing for this long (`300s`, `2m`, `500ms`).
    #[arg(long = "idle-timeout", value_name = "DURATION", default_value = "300s")]
    pub idle_timeout: String,
    /// On Modbus TCP, answer only the --unit id (by default unit 0xFF is this device too, as libmodbus does).
    #[arg(long = "strict-unit")]
    pub strict_unit: bool,
}

impl ServeArgs {
    fn serves_k2(&self) -> bool {
        self.tcp.is_some() || self.rtu_pty.is_some() || self.rtu_tcp.is_some()
    }
}

/// `HOST:PORT`, or a bare port on 127.0.0.1.
pub fn listen_addr(text: &str) -> Result<SocketAddr> {
    let t = text.trim();
    let full = if let Ok(port) = t.trim_start_matches(':').parse::<u16>() {
        format!("127.0.0.1:{port}")
    } else {
        t.to_string()
    };
    full.parse().map_err(|_| {
        Error::usage(format!("`{text}` is not an address to listen on"))
            .hint("use HOST:PORT (127.0.0.1:5020, 0.0.0.0:502) or a port (5020; 0 picks a free one)")
    })
}

async fn bind(text: &str) -> Result<TcpListener> {
    let addr = listen_addr(text)?;
    TcpListener::bind(addr).await.map_err(|e| {
        Error::io(format!("cannot listen on {addr}"))
            .cause(e)
            .hint("choose another port (0 picks a free one); ports below 1024 need privileges")
    })
}

/// Raises a stop flag when dropped (stops the servo line's thread).
struct StopOnDrop(Arc<AtomicBool>);

impl Drop for StopOnDrop {
    fn drop(&mut self) {
        self.0.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

/// Files to remove when the server stops.
#[derive(Default)]
struct Cleanup {
    links: Vec<PathBuf>,
}

impl Drop for Cleanup {
    fn drop(&mut self) {
        for l in &self.links {
            let _ = std::fs::remove_file(l);
        }
    }
}

/// Binds the K2's transports, spawns their servers and names them in `ready`.
async fn serve_k2(
    cli: &Cli,
    args: &ServeArgs,
    clock: &Clock,
    tasks: &mut JoinSet<std::io::Result<()>>,
    ready: &mut Map<String, Json>,
    cleanup: &mut Cleanup,
) -> Result<()> {
    let mut sim = crate::k2::sim::open(&cli.model, clock.clone())?;
    // The served K2 keeps its backup area and retained ranges only in a file named for it
    // (`--state FILE`): a lab's server never touches the shell's default state file.
    if let Some(path) = cli.state.as_ref().filter(|p| p.as_os_str() != "none") {
        sim.attach_state(path.clone())?;
        ready.insert("state".into(), json!(path));
    }
    ready.insert("model".into(), json!(sim.model().name));
    ready.insert("unit".into(), json!(args.unit));
    if let Some(base) = &args.agent {
        let b = crate::k2::agent::protocol::parse_base(base).map_err(Error::usage)?;
        sim.enable_agent(b).map_err(Error::usage)?;
        ready.insert("agent".into(), json!(format!("VB{b}")));
    }
    let service = K2Service::new(Arc::new(Mutex::new(sim)), args.unit);
    let idle =
        crate::core::literal::parse_duration_us(&args.idle_timeout).ok().filter(|us| *us > 0).ok_or_else(|| {
            Error::usage(format!("--idle-timeout {} is not a duration", args.idle_timeout)).hint("e.g. 300s, 2m")
        })?;
    let limits = modbus_server::Limits {
        max_connections: args.max_connections,
        idle: std::time::Duration::from_micros(idle as u64),
        unit_ff: !args.strict_unit,
    };
    if let Some(a) = &args.tcp {
        let l = bind(a).await?;
        ready.insert("tcp".into(), json!(l.local_addr()?.to_string()));
        tasks.spawn(modbus_server::serve_tcp(l, service.clone(), limits));
    }
    if let Some(a) = &args.rtu_tcp {
        let l = bind(a).await?;
        ready.insert("rtu_tcp".into(), json!(l.local_addr()?.to_string()));
        tasks.spawn(modbus_server::serve_rtu_over_tcp(l, service.clone(), limits));
    }
    if let Some(link) = &args.rtu_pty {
        let pty = AsyncPty::open()?;
        pty.link(link)?;
        cleanup.links.push(link.clone());
        ready.insert("rtu_pty".into(), json!({"path": pty.path(), "link": link}));
        let service = service.clone();
        tasks.spawn(async move { modbus_server::serve_rtu(&pty, service).await });
    }
    Ok(())
}

/// Serves simulated drives on a pty from a thread of their own (the servo line is a
/// blocking byte stream); returns once the pty is open, with its fields for `ready`.
async fn serve_servo(args: &ServeArgs, stop: &Arc<AtomicBool>, ready: &mut Map<String, Json>) -> Result<()> {
    let Some(link) = args.servo_pty.clone() else { return Ok(()) };
    let ids = crate::servo::driver::parse_ids(&args.servo_id)
        .map_err(|m| Error::usage(format!("--servo-id: {m}")).hint("e.g. --servo-id 1,2"))?;
    let (tx, rx) = tokio::sync::oneshot::channel::<Result<Json>>();
    let (echo, stop) = (args.servo_loop, stop.clone());
    std::thread::spawn(move || {
        let mut tx = Some(tx);
        let r = crate::servo::sim::serve::serve_pty(Some(&link), &ids, echo, Clock::following(), &stop, |r| {
            if let Some(tx) = tx.take() {
                let _ = tx.send(Ok(json!(r)));
            }
        });
        if let (Err(e), Some(tx)) = (r, tx.take()) {
            let _ = tx.send(Err(e));
        }
    });
    match rx.await {
        Ok(Ok(Json::Object(m))) => {
            ready.extend(m);
            Ok(())
        }
        Ok(Ok(_)) => Ok(()),
        Ok(Err(e)) => Err(e),
        Err(_) => Err(Error::io("the servo line stopped before it was ready")),
    }
}

/// Waits for Ctrl-C or SIGTERM. Both handlers are installed when this is called, before
/// the readiness line goes out, so a signal sent right after it is not lost.
fn until_stopped() -> std::io::Result<impl std::future::Future<Output = ()>> {
    use tokio::signal::unix::{signal, SignalKind};
    let mut int = signal(SignalKind::interrupt())?;
    let mut term = signal(SignalKind::terminate())?;
    Ok(async move {
        tokio::select! {
            _ = int.recv() => {},
            _ = term.recv() => {},
        }
    })
}

async fn serve(cli: &Cli, args: &ServeArgs, out: &mut dyn Write) -> Result<()> {
    if !args.serves_k2() && args.servo_pty.is_none() {
        return Err(Error::usage("sim serve needs at least one transport")
            .hint("e.g. plcsh sim serve --tcp 127.0.0.1:5020 --rtu-pty /tmp/k2 --rtu-tcp 0 --servo-pty /tmp/kinco"));
    }
    if args.agent.is_some() && !args.serves_k2() {
        return Err(Error::usage("--agent runs in the served K2: give --tcp, --rtu-pty or --rtu-tcp too"));
    }
    let stopped = until_stopped().map_err(|e| Error::io("cannot install signal handlers").cause(e))?;
    let clock = match cli.time {
        super::TimeMode::Wall => Clock::following(),
        super::TimeMode::Stepped => Clock::stepped(),
    };
    let mut tasks = JoinSet::new();
    let mut ready = Map::new();
    ready.insert("ok".into(), json!(true));
    ready.insert("cmd".into(), json!("sim serve"));
    ready.insert("ready".into(), json!(true));
    let mut cleanup = Cleanup::default();
    if args.serves_k2() {
        serve_k2(cli, args, &clock, &mut tasks, &mut ready, &mut cleanup).await?;
    }
    let servo_stop = Arc::new(AtomicBool::new(false));
    let _stop_servo = StopOnDrop(servo_stop.clone());
    serve_servo(args, &servo_stop, &mut ready).await?;
    // Removed here too, not only by the servo line's thread: on SIGINT/SIGTERM the process
    // may end before that thread notices its stop flag.
    cleanup.links.extend(args.servo_pty.clone());
    serde_json::to_writer(&mut *out, &ready).map_err(|e| Error::io("cannot print the readiness line").cause(e))?;
    writeln!(out)?;
    out.flush()?;
    tokio::select! {
        () = stopped => Ok(()),
        Some(r) = tasks.join_next() => {
            let e = match r {
                Ok(Ok(())) => "a server stopped".to_string(),
                Ok(Err(e)) => e.to_string(),
                Err(e) => e.to_string(),
            };
            Err(Error::io("serving failed").cause(e))
        }
    }
}

/// Runs `plcsh sim serve`; returns the exit status.
pub fn run(cli: &Cli, args: &ServeArgs, style: Style, out: &mut dyn Write) -> i32 {
    let rt = match tokio::runtime::Builder::new_current_thread().enable_all().build() {
        Ok(rt) => rt,
        Err(e) => {
            let _ = output::write_error(out, style, "sim serve", &Error::io("cannot start a runtime").cause(e), None);
            return 1;
        }
    };
    match rt.block_on(serve(cli, args, out)) {
        Ok(()) => 0,
        Err(e) => {
            let _ = output::write_error(out, style, "sim serve", &e, None);
            if e.kind == crate::core::ErrorKind::Usage {
                2
            } else {
                1
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bare_ports_bind_loopback() {
        assert_eq!(listen_addr("5020").unwrap().to_string(), "127.0.0.1:5020");
        assert_eq!(listen_addr(":0").unwrap().to_string(), "127.0.0.1:0");
        assert_eq!(listen_addr("0.0.0.0:502").unwrap().to_string(), "0.0.0.0:502");
        assert!(listen_addr("localhost:x").is_err());
    }
}
