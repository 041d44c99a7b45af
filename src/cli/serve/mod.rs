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
//! `--agent [VB3400]` runs the PLC-side helper program `lib/k2_agent.il` (as IL text, in the
//! simulator's scan engine, `k2::sim::agent`), so SM registers and instructions are reachable
//! over Modbus exactly as on a K2 running it; `--program FILE.il` runs a user program too.
//!
//! Simulated Kinco servo drives are served on their own pseudo-terminal (`--servo-pty LINK
//! --servo-id 1[,2,…] [--servo-loop] [--servo-baud 38400 --servo-latency 1ms | --servo-instant]
//! [--servo-strict]`, the logic is `servo::sim::serve`); their fields (`servo_pty`, `link`,
//! `ids`, `echo`, `servo_control`, timing) join the readiness line.
//!
//! A simulated FX PLC's programming port and computer link go on ptys of their own (`--fx-pty
//! LINK --fx-link-pty LINK2`, one shared memory; the logic is `fx::sim`).
//!
//! A simulated UMPK teaching PLC is served on a pseudo-terminal too (`--umpk-pty LINK
//! --umpk-model UMPK16`; the logic is `umpk::sim::serve`); it shares the servo line's stop flag.
//!
//! Shape: each served family adds its endpoints in its own function ([`serve_k2`],
//! [`serve_servo`]) — it binds, spawns its tasks and adds its fields to the readiness line.
//! `--fleet N` serves N K2s instead of one ([`fleet`], built by the same [`make_k2`]).
//!
//! `--rfc2217` makes the serial options' TCP ports speak RFC 2217 instead of raw TCP
//! ([`rfc2217`]: a front before each raw port).

mod fleet;
pub(crate) mod rfc2217;

use super::Cli;
use crate::core::link::async_pty::AsyncPty;
use crate::core::link::control;
use crate::core::link::served::ServeOn;
use crate::core::{Clock, Error, Result};
use crate::k2::sim::modbus_net;
use crate::k2::sim::modbus_server::K2Service;
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
    Serve(Box<ServeArgs>),
    /// Send one line to a served simulator's control channel (faults, events) and print the reply.
    Control(ControlArgs),
}

/// `plcsh sim control PATH WORDS…`
#[derive(Args, Debug)]
pub struct ControlArgs {
    /// The control channel (the `k2_control`, `umpk_control` or `servo_control` of the server's readiness line).
    #[arg(value_name = "PATH")]
    pub path: PathBuf,
    /// The control line, e.g. `fault no-reply times=2`, `faults`, `events`, `fault clear`.
    #[arg(value_name = "WORDS", required = true, num_args = 1.., trailing_var_arg = true, allow_hyphen_values = true)]
    pub words: Vec<String>,
}

#[derive(Args, Debug, Clone)]
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
    /// Run this IL program in the served K2 (docs/il.md); load errors stop the server.
    #[arg(long, value_name = "FILE.il")]
    pub program: Option<PathBuf>,
    /// Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it.
    #[arg(long = "servo-pty", value_name = "LINK", conflicts_with = "servo_tcp")]
    pub servo_pty: Option<PathBuf>,
    /// Serve simulated Kinco servo drives on a TCP port, as a serial device server would (kinco+tcp://ADDR).
    #[arg(long = "servo-tcp", value_name = "ADDR")]
    pub servo_tcp: Option<String>,
    /// The served drive line's control channel at PATH (default: LINK.ctl beside --servo-pty's
    /// link); clients name it with `control=PATH` (e.g. `kinco+tcp://ADDR?control=PATH`).
    #[arg(long = "servo-control", value_name = "PATH")]
    pub servo_control: Option<PathBuf>,
    /// Drive ids on the servo line (several drives share it).
    #[arg(long = "servo-id", value_name = "ID[,ID…]", default_value = "1")]
    pub servo_id: String,
    /// RS232 loop mode: echo every request before the reply (connect with echo=1).
    #[arg(long = "servo-loop")]
    pub servo_loop: bool,
    /// Line timing: replies take the frame time at this baud rate (10 bits a byte).
    #[arg(long = "servo-baud", value_name = "BAUD", default_value_t = 38_400)]
    pub servo_baud: u32,
    /// Line timing: the drive's think-time before it answers (e.g. 1ms, 0).
    #[arg(long = "servo-latency", value_name = "DURATION", default_value = "1ms")]
    pub servo_latency: String,
    /// Answer at once instead of at line speed (benchmarks, CI).
    #[arg(long = "servo-instant")]
    pub servo_instant: bool,
    /// Refuse writes whose size code differs from the object's (abort 0x06070010).
    #[arg(long = "servo-strict")]
    pub servo_strict: bool,
    /// Serve a simulated FX PLC's programming port on a new pseudo-terminal (symlink at LINK).
    #[arg(long = "fx-pty", value_name = "LINK", conflicts_with = "fx_tcp")]
    pub fx_pty: Option<PathBuf>,
    /// Serve the simulated FX PLC's programming port on a TCP port (fx+tcp://ADDR).
    #[arg(long = "fx-tcp", value_name = "ADDR")]
    pub fx_tcp: Option<String>,
    /// Serve the same FX PLC's computer link (format 1, sum check on) on another pseudo-terminal.
    #[arg(long = "fx-link-pty", value_name = "LINK", conflicts_with = "fx_link_tcp")]
    pub fx_link_pty: Option<PathBuf>,
    /// Serve the same FX PLC's computer link on a TCP port (fxlink+tcp://ADDR).
    #[arg(long = "fx-link-tcp", value_name = "ADDR")]
    pub fx_link_tcp: Option<String>,
    /// The simulated FX PLC's model (FX1S, FX1N, FX2N, FX3U; FX2NC and FX3UC name the FX2N and FX3U).
    #[arg(long = "fx-model", value_name = "MODEL", default_value = "FX2N")]
    pub fx_model: String,
    /// The computer link's station number (0–31).
    #[arg(long = "fx-station", value_name = "N", default_value_t = 0)]
    pub fx_station: u8,
    /// An FX instruction list the simulated FX PLC runs (docs/il.md, "The FX family").
    #[arg(long = "fx-program", value_name = "FILE.il")]
    pub fx_program: Option<PathBuf>,
    /// Serve a simulated UMPK teaching PLC on a new pseudo-terminal; LINK becomes a symlink to it.
    #[arg(long = "umpk-pty", value_name = "LINK", conflicts_with = "umpk_tcp")]
    pub umpk_pty: Option<PathBuf>,
    /// Serve a simulated UMPK teaching PLC on a TCP port (umpk+tcp://ADDR).
    #[arg(long = "umpk-tcp", value_name = "ADDR")]
    pub umpk_tcp: Option<String>,
    /// The simulated UMPK's model (UMPK8 or UMPK16).
    #[arg(long = "umpk-model", value_name = "MODEL", default_value = "UMPK16", value_parser = crate::umpk::sim::serve::parse_model)]
    pub umpk_model: &'static crate::umpk::model::Model,
    /// Bit numbers of W,H,R,E,P,T in the UMPK's status word.
    #[arg(long = "umpk-status-bits", value_name = "W,H,R,E,P,T", default_value = "5,4,3,2,1,0", value_parser = crate::umpk::codec::StatusLayout::parse)]
    pub umpk_status_bits: crate::umpk::codec::StatusLayout,
    /// Make the simulated UMPK's flash write fail on this 64-byte page (programming gets `W`):
    /// 0–31 on the UMPK8, 0–47 on the UMPK16.
    #[arg(long = "umpk-flash-fail", value_name = "PAGE")]
    pub umpk_flash_fail: Option<u16>,
    /// Where the simulated UMPK keeps its flash, program info and error history (default: one
    /// file per model and link in the user's data directory; `none` keeps nothing).
    #[arg(long = "umpk-state", value_name = "FILE")]
    pub umpk_state: Option<PathBuf>,
    /// An IL lab program the simulated UMPK runs each 10 ms cycle (docs/il.md, "The UMPK family").
    #[arg(long = "umpk-program", value_name = "FILE.il")]
    pub umpk_program: Option<PathBuf>,
    /// The served FX PLC's control channel at PATH (default: LINK.ctl beside --fx-pty's link):
    /// X inputs switched, a silent line, stuck inputs while clients use its ports.
    #[arg(long = "fx-control", value_name = "PATH")]
    pub fx_control: Option<PathBuf>,
    /// The served UMPK's control channel at PATH (default: LINK.ctl beside --umpk-pty's link):
    /// inputs, square waves and faults while the lab's software uses the line.
    #[arg(long = "umpk-control", value_name = "PATH")]
    pub umpk_control: Option<PathBuf>,
    /// The served K2's control channel at PATH (default: LINK.ctl beside --rtu-pty's link):
    /// faults added, listed and cleared and the fault event log read while clients poll
    /// (`plcsh sim control PATH …`, or `control=PATH` in the client's URL).
    #[arg(long = "k2-control", value_name = "PATH")]
    pub k2_control: Option<PathBuf>,
    /// Inject a fault into the served K2, e.g. `--fault "no-reply on VW100 after=2s times=1"` (repeatable; see `help sim`).
    #[arg(long = "fault", value_name = "SPEC")]
    pub faults: Vec<String>,
    /// Network connections served at once (per transport); more are closed on accept.
    #[arg(long = "max-connections", value_name = "N", default_value_t = 64)]
    pub max_connections: usize,
    /// Close a network connection that sends nothing for this long (`300s`, `2m`, `500ms`).
    #[arg(long = "idle-timeout", value_name = "DURATION", default_value = "300s")]
    pub idle_timeout: String,
    /// On Modbus TCP, answer only the --unit id (by default unit 0xFF is this device too, as libmodbus does).
    #[arg(long = "strict-unit")]
    pub strict_unit: bool,
    /// Serve N simulated K2s, each with its own memory, on N TCP ports (with --tcp: port 0 gives each a
    /// free port, port P gives P, P+1, …); the readiness line lists them under `fleet` (docs/fleets.md).
    #[arg(long = "fleet", value_name = "N", requires = "tcp", conflicts_with_all = ["rtu_pty", "rtu_tcp", "k2_control"],
        value_parser = clap::value_parser!(u16).range(1..=10_000))]
    pub fleet: Option<u16>,
    /// The serial options' TCP ports (--rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp, --umpk-tcp) speak RFC 2217
    /// (Telnet COM-PORT-OPTION) instead of raw TCP: for FAMILY+rfc2217:// and virtual COM port drivers.
    #[arg(long = "rfc2217")]
    pub rfc2217: bool,
}

impl ServeArgs {
    fn serves_k2(&self) -> bool {
        self.tcp.is_some() || self.rtu_pty.is_some() || self.rtu_tcp.is_some()
    }
}

/// Where a serial family is served: `--X-pty LINK` or `--X-tcp ADDR`.
fn serve_on(pty: &Option<PathBuf>, tcp: &Option<String>) -> Result<Option<ServeOn>> {
    Ok(match (pty, tcp) {
        (Some(l), _) => Some(ServeOn::Pty(Some(l.clone()))),
        (None, Some(a)) => Some(ServeOn::Tcp(listen_addr(a)?)),
        (None, None) => None,
    })
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
        Error::usage(crate::msg!("cli-serve-not-an-address", text = text)).hint(crate::msg!("cli-hint-serve-address"))
    })
}

pub(super) async fn bind(text: &str) -> Result<TcpListener> {
    let addr = listen_addr(text)?;
    TcpListener::bind(addr).await.map_err(|e| {
        Error::io(crate::msg!("cli-serve-cannot-listen", addr = addr.to_string()))
            .cause(e)
            .hint(crate::msg!("cli-hint-serve-port"))
    })
}

/// Raises a stop flag when dropped (stops the servo line's thread).
struct StopOnDrop(Arc<AtomicBool>);

impl Drop for StopOnDrop {
    fn drop(&mut self) {
        self.0.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

/// What ends with the server: files to remove, control channels (they remove their own
/// files), and the stop flag the threads serving lines and channels watch.
#[derive(Default)]
struct Cleanup {
    links: Vec<PathBuf>,
    channels: Vec<control::Channel>,
    stop: Arc<AtomicBool>,
}

/// With `-v`: one line on stderr each time an injected fault acts on the served K2, with its
/// virtual time (read from the simulator's event log; reading it changes nothing).
fn report_faults(sim: Arc<Mutex<crate::k2::sim::K2Sim>>, stop: Arc<AtomicBool>) {
    std::thread::spawn(move || {
        let mut seen = 0u64;
        while !stop.load(std::sync::atomic::Ordering::Relaxed) {
            let lines: Vec<String> = {
                let s = sim.lock().unwrap_or_else(|p| p.into_inner());
                let new: Vec<_> = s.events.list().into_iter().filter(|e| e.seq >= seen).collect();
                seen = new.last().map_or(seen, |e| e.seq + 1);
                new.iter()
                    .filter(|e| matches!(e.kind, crate::k2::instr::EventKind::Fault { .. }))
                    .map(|e| format!("{:.6} s: {}", e.time.as_secs_f64(), e.kind.describe()))
                    .collect()
            };
            for l in lines {
                eprintln!("{}", crate::msg!("cli-serve-fault-acted", line = l.as_str()));
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
    });
}

impl Drop for Cleanup {
    fn drop(&mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        for l in &self.links {
            let _ = std::fs::remove_file(l);
        }
    }
}

/// The readiness line's word on the helper: `--agent` runs the copy of `lib/k2_agent.il`
/// built into this plcsh (generated for the mailbox base), never a file on disk, so an edited
/// helper is run as the program instead (docs/simulator.md).
pub fn agent_note(base: u32) -> String {
    format!(
        "built-in copy of lib/k2_agent.il (plcsh {}, mailbox VB{base}); an edited copy runs with --program FILE instead of --agent",
        env!("CARGO_PKG_VERSION")
    )
}

/// One simulated K2 as the flags describe it (model, state, helper program, faults, user
/// program), its fields added to `ready`. Shared by the single K2 and by `--fleet N`.
pub(super) fn make_k2(
    cli: &Cli,
    args: &ServeArgs,
    clock: &Clock,
    ready: &mut Map<String, Json>,
    bench: Option<crate::k2::sim::K2Sim>,
) -> Result<crate::k2::sim::K2Sim> {
    let mut sim = match bench {
        Some(sim) => sim,
        None => crate::k2::sim::open(&cli.model, clock.clone())?,
    };
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
        // Which copy runs: the one built into plcsh (an edited lib/k2_agent.il is not read).
        ready.insert("agent_program".into(), json!(agent_note(b)));
    }
    for f in &args.faults {
        let spec = crate::k2::sim::fault::parse(f).map_err(|m| Error::usage(format!("--fault \"{f}\": {m}")))?;
        let now = sim.last;
        sim.faults.add(&spec, now);
    }
    if let Some(p) = &args.program {
        let text = crate::core::encoding::read_source(p).map_err(|e| {
            Error::io(crate::msg!("shell-cannot-read-because", file = p.display().to_string(), reason = e.to_string()))
        })?;
        sim.load_program(&text, &p.display().to_string())?;
        ready.insert("program".into(), json!(p.display().to_string()));
    }
    Ok(sim)
}

/// How the served K2s treat their network connections (`--max-connections`, `--idle-timeout`, `--strict-unit`).
pub(super) fn limits(args: &ServeArgs) -> Result<modbus_net::Limits> {
    let idle = crate::core::literal::parse_option_duration_us(&args.idle_timeout)
        .ok()
        .filter(|us| *us > 0)
        .ok_or_else(|| {
            Error::usage(crate::msg!("cli-serve-idle-timeout", value = args.idle_timeout.as_str()))
                .hint(crate::msg!("cli-hint-serve-idle-timeout"))
        })?;
    Ok(modbus_net::Limits {
        max_connections: args.max_connections,
        idle: std::time::Duration::from_micros(idle as u64),
        unit_ff: !args.strict_unit,
    })
}

/// Binds the K2's transports, spawns their servers and names them in `ready`.
async fn serve_k2(
    cli: &Cli,
    args: &ServeArgs,
    clock: &Clock,
    tasks: &mut JoinSet<std::io::Result<()>>,
    ready: &mut Map<String, Json>,
    cleanup: &mut Cleanup,
    bench: Option<crate::k2::sim::K2Sim>,
) -> Result<()> {
    let stop = cleanup.stop.clone();
    let sim = make_k2(cli, args, clock, ready, bench)?;
    let sim = Arc::new(Mutex::new(sim));
    let service = K2Service::new(sim.clone(), args.unit);
    let control = args.k2_control.clone().or_else(|| args.rtu_pty.as_deref().map(control::default_path));
    if let Some(path) = control {
        let s = sim.clone();
        let answer: control::Answer = Arc::new(move |text: &str| {
            control::reply(crate::k2::sim::control::answer(
                &mut s.lock().unwrap_or_else(|p| p.into_inner()),
                text,
                true,
            ))
        });
        let ch = control::Channel::open(&path, "the served K2's control channel", answer, stop.clone())?;
        ready.insert("k2_control".into(), json!(ch.path()));
        cleanup.channels.push(ch);
    }
    if cli.verbose > 0 {
        report_faults(sim.clone(), stop);
    }
    let limits = limits(args)?;
    if let Some(a) = &args.tcp {
        let l = bind(a).await?;
        ready.insert("tcp".into(), json!(l.local_addr()?.to_string()));
        tasks.spawn(modbus_net::serve_tcp(l, service.clone(), limits));
    }
    if let Some(a) = &args.rtu_tcp {
        let l = bind(a).await?;
        ready.insert("rtu_tcp".into(), json!(l.local_addr()?.to_string()));
        tasks.spawn(modbus_net::serve_rtu_over_tcp(l, service.clone(), limits));
    }
    if let Some(link) = &args.rtu_pty {
        let pty = AsyncPty::open()?;
        pty.link(link)?;
        cleanup.links.push(link.clone());
        ready.insert("rtu_pty".into(), json!({"path": pty.path(), "link": link}));
        let service = service.clone();
        tasks.spawn(async move { modbus_net::serve_rtu(&pty, service).await });
    }
    Ok(())
}

/// Serves simulated drives on a pty from a thread of their own (the servo line is a
/// blocking byte stream); returns once the pty is open, with its fields for `ready`.
async fn serve_servo(
    args: &ServeArgs,
    stop: &Arc<AtomicBool>,
    ready: &mut Map<String, Json>,
    cleanup: &mut Cleanup,
    bench: Option<Arc<Mutex<crate::servo::sim::SimLine>>>,
) -> Result<()> {
    let Some(on) = serve_on(&args.servo_pty, &args.servo_tcp)? else { return Ok(()) };
    // The process may exit before the line's thread sees the stop flag: once the line is up,
    // its link and control socket are removed on the way out here too.
    let mut made: Vec<PathBuf> = match &on {
        ServeOn::Pty(Some(link)) => vec![link.clone(), crate::servo::sim::serve::control_path(link)],
        _ => Vec::new(),
    };
    made.extend(args.servo_control.iter().cloned());
    let ids = crate::servo::driver::parse_ids(&args.servo_id)
        .map_err(|m| Error::usage(format!("--servo-id: {m}")).hint("e.g. --servo-id 1,2"))?;
    let latency = crate::core::literal::parse_option_duration_us(&args.servo_latency)
        .ok()
        .filter(|us| *us >= 0)
        .ok_or_else(|| {
            Error::usage(crate::msg!("cli-serve-servo-latency", value = args.servo_latency.as_str()))
                .hint(crate::msg!("cli-hint-serve-servo-latency"))
        })?;
    if args.servo_baud == 0 {
        return Err(Error::usage(crate::msg!("cli-serve-servo-baud")));
    }
    let pace =
        crate::servo::sim::Pace { baud: args.servo_baud, latency: std::time::Duration::from_micros(latency as u64) };
    let opts = crate::servo::sim::serve::Options {
        control: args.servo_control.clone(),
        ids,
        echo: args.servo_loop,
        pace: (!args.servo_instant).then_some(pace),
        strict: args.servo_strict,
    };
    let (tx, rx) = tokio::sync::oneshot::channel::<Result<Json>>();
    let stop = stop.clone();
    std::thread::spawn(move || {
        let mut tx = Some(tx);
        let on_ready = |r: &crate::servo::sim::serve::Ready| {
            if let Some(tx) = tx.take() {
                let _ = tx.send(Ok(json!(r)));
            }
        };
        let r = match bench {
            Some(line) => crate::servo::sim::serve::serve_on_line(&on, &opts, line, &stop, on_ready),
            None => crate::servo::sim::serve::serve(&on, &opts, Clock::following(), &stop, on_ready),
        };
        if let (Err(e), Some(tx)) = (r, tx.take()) {
            let _ = tx.send(Err(e));
        }
    });
    match rx.await {
        Ok(Ok(Json::Object(m))) => {
            ready.extend(m);
            cleanup.links.extend(made);
            Ok(())
        }
        Ok(Ok(_)) => {
            cleanup.links.extend(made);
            Ok(())
        }
        Ok(Err(e)) => Err(e),
        Err(_) => Err(Error::io(crate::msg!("cli-serve-servo-line-stopped"))),
    }
}

async fn serve(cli: &Cli, args: &ServeArgs, out: &mut dyn Write) -> Result<()> {
    // With --rfc2217 the families serve raw TCP on loopback, and fronts listen where asked.
    let (behind, fronts) = rfc2217::behind_fronts(args)?;
    let args = behind.as_ref().unwrap_or(args);
    let servo = serve_on(&args.servo_pty, &args.servo_tcp)?;
    let fx = (serve_on(&args.fx_pty, &args.fx_tcp)?, serve_on(&args.fx_link_pty, &args.fx_link_tcp)?);
    let umpk = serve_on(&args.umpk_pty, &args.umpk_tcp)?;
    if !args.serves_k2() && servo.is_none() && fx.0.is_none() && fx.1.is_none() && umpk.is_none() {
        return Err(
            Error::usage(crate::msg!("cli-serve-needs-transport")).hint(crate::msg!("cli-hint-serve-transport"))
        );
    }
    if args.agent.is_some() && !args.serves_k2() {
        return Err(Error::usage(crate::msg!("cli-serve-agent-needs-k2")));
    }
    let stopped =
        crate::core::platform::stop_signal().map_err(|e| Error::io(crate::msg!("cli-serve-no-signals")).cause(e))?;
    let clock = match cli.time {
        super::TimeMode::Wall => Clock::following(),
        super::TimeMode::Stepped => Clock::stepped(),
    };
    let mut tasks = JoinSet::new();
    let mut ready = Map::new();
    ready.insert("ok".into(), json!(true));
    ready.insert("cmd".into(), json!("sim"));
    ready.insert("sub".into(), json!("serve"));
    ready.insert("ready".into(), json!(true));
    let mut cleanup = Cleanup::default();
    let (k2, line) = match &cli.bench {
        Some(path) => {
            let (k2, line, notes) = crate::wiring::bench::serve_parts(path, &clock)?;
            ready.insert("bench".into(), json!(notes));
            (k2, line)
        }
        None => (None, None),
    };
    let servo_stop = Arc::new(AtomicBool::new(false));
    let _stop_servo = StopOnDrop(servo_stop.clone());
    if let Some(n) = args.fleet {
        fleet::serve(cli, args, n, &clock, &mut tasks, &mut ready).await?;
    } else if args.serves_k2() {
        serve_k2(cli, args, &clock, &mut tasks, &mut ready, &mut cleanup, k2).await?;
    }
    serve_servo(args, &servo_stop, &mut ready, &mut cleanup, line).await?;
    let fx_plc = crate::fx::sim::PlcOptions {
        model: &args.fx_model,
        station: args.fx_station,
        program: args.fx_program.as_deref(),
        clock: &clock,
        control: args.fx_control.clone(),
    };
    let (fx_ready, fx_control) = crate::fx::sim::serve_ports(fx.0, fx.1, fx_plc, &servo_stop).await?;
    ready.extend(fx_ready);
    cleanup.channels.extend(fx_control);
    cleanup.links.extend(args.fx_pty.iter().chain(&args.fx_link_pty).cloned());
    if let Some(on) = umpk {
        cleanup.links.extend(args.umpk_pty.iter().cloned());
        // The control channel goes with the server, even when the process exits before the
        // UMPK's thread sees the stop flag.
        cleanup.links.extend(args.umpk_control.clone().or_else(|| args.umpk_pty.as_deref().map(control::default_path)));
        let u = crate::umpk::sim::serve::Options {
            on,
            model: args.umpk_model,
            layout: args.umpk_status_bits,
            flash_fail: args.umpk_flash_fail.map(usize::from),
            state: args.umpk_state.clone(),
            program: args.umpk_program.clone(),
            control: args.umpk_control.clone(),
        };
        ready.extend(crate::umpk::sim::serve::spawn(u, servo_stop.clone()).await?);
    }
    for (field, listen) in fronts {
        let Some(inner) = ready.get(field).and_then(Json::as_str).and_then(|a| a.parse().ok()) else { continue };
        let (addr, task) = rfc2217::front(listen, inner).await?;
        ready.insert(field.into(), json!(addr.to_string()));
        ready.insert("rfc2217".into(), json!(true));
        tasks.spawn(task);
    }
    serde_json::to_writer(&mut *out, &ready).map_err(|e| Error::io(crate::msg!("cli-serve-no-readiness")).cause(e))?;
    writeln!(out)?;
    out.flush()?;
    tokio::select! {
        () = stopped => Ok(()),
        Some(r) = tasks.join_next() => {
            let e = match r {
                Ok(Ok(())) => crate::msg!("cli-serve-server-stopped").text,
                Ok(Err(e)) => e.to_string(),
                Err(e) => e.to_string(),
            };
            Err(Error::io(crate::msg!("cli-serve-failed")).cause(e))
        }
    }
}

/// Runs `plcsh sim control PATH WORDS…`: one line to a served simulator's control channel;
/// the reply as text (or the JSON object with `--json`). Exit 0 on `ok`, 2 when the
/// simulator refused the line, 1 when the channel cannot be reached.
pub fn control_run(args: &ControlArgs, style: Style, out: &mut dyn Write) -> i32 {
    let line = args.words.join(" ");
    match control::send(&args.path, &line) {
        Ok((text, data)) => {
            let mut o = output::Outcome::new("sim").with("sub", "control").text(text);
            if let Json::Object(m) = data {
                for (k, v) in m {
                    if k != "ok" && k != "text" {
                        o = o.with(&k, v);
                    }
                }
            }
            match output::write_outcome(out, style, &o) {
                Ok(()) => 0,
                Err(_) => 1,
            }
        }
        Err(e) => {
            let _ = output::report_error(out, style, "sim", &e, None);
            if e.kind == crate::core::ErrorKind::Usage {
                2
            } else {
                1
            }
        }
    }
}

/// Runs `plcsh sim serve`; returns the exit status.
pub fn run(cli: &Cli, args: &ServeArgs, style: Style, out: &mut dyn Write) -> i32 {
    let rt = match tokio::runtime::Builder::new_current_thread().enable_all().build() {
        Ok(rt) => rt,
        Err(e) => {
            let _ =
                output::report_error(out, style, "sim", &Error::io(crate::msg!("cli-serve-no-runtime")).cause(e), None);
            return 1;
        }
    };
    match rt.block_on(serve(cli, args, out)) {
        Ok(()) => 0,
        Err(e) => {
            let _ = output::report_error(out, style, "sim", &e, None);
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
