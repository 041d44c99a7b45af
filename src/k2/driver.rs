//! The K2 wire driver: a real K2 (or `plcsh sim serve`, or any K2-compatible Modbus
//! server) over Modbus TCP (`tcp://HOST:PORT`), Modbus RTU on a serial port
//! (`rtu:/dev/ttyUSB0?baud=…`) or RTU through a serial-to-Ethernet gateway
//! (`rtu+tcp://HOST:PORT`), with the same operand names as the simulator.
//!
//! How a batch goes on the wire:
//! 1. Every operand is mapped first ([`super::modbus_map`]); SM, T and C (not in the K2
//!    Modbus map) and writes to inputs are refused before anything is sent.
//! 2. Reads are coalesced ([`super::coalesce`]): the fewest, cheapest requests the limits
//!    allow, one function code per table.
//! 3. Writes keep their order. A byte, a bit or an odd-address word in V or AQ is a
//!    read-modify-write of the enclosing registers: the registers are read (coalesced)
//!    before the first write, patched, and written back. Between that read and the write
//!    the PLC program may change the other byte of the register, and that change is then
//!    overwritten (see README, "Byte and bit writes on a live PLC"). Coils are written bit
//!    by bit and need no read.
//!
//! Failures: a Modbus exception is the PLC refusing (kind `refused`), reported by name with
//! the operand, never retried. Link failures (no answer within the timeout, a dropped TCP
//! connection, a garbled reply) are retried with backoff after reconnecting (reopening the
//! port, which also drops a late reply), and reported as kind `link` naming what to check.
//!
//! SM operands and the instructions (PLS, HDEF, HSC, PSTOP, RTC) go through the PLC-side
//! helper program's mailbox when the device has `agent=VB…` ([`sm`], docs/agent.md).
//!
//! The `Device` trait is synchronous, and so is the driver: a request is a `write` on the
//! socket or serial port and the reply a `poll` and a `read` ([`port`]; a stream handed over
//! with [`K2Wire::attach`] runs on a runtime of its own). Every frame is reported to
//! [`crate::core::trace`]. The Modbus framing is the driver's own ([`client`]): a read's reply
//! stays in the receive buffer and each operand is decoded straight from its bytes, so a
//! polling loop's read of 100 registers costs one slice copy and a plan it already has, not
//! a conversion per register.

mod client;

pub use client::fuzz_replies;
mod reads;
mod sm;

use super::agent::client::AgentClient;
use super::catalog::{self, Model};
use super::coalesce::{self, Costs};
use super::memory::Memory;
use super::modbus_map::{self, DataMut, Span, WordOrder};
use super::operand::{K2Operand, Width};
use super::space::K2Space;
use crate::core::link::port::{self as port, AsyncPort, Port};
use crate::core::link::serial::{Carrier, LineSettings, Parity};
use crate::core::trace::Proto;
use crate::core::url::DeviceUrl;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::msg;
use client::ModbusClient;
use std::collections::HashMap;
use std::time::Duration;
use tokio_modbus::{ExceptionCode, Request};

/// How the PLC is reached.
#[derive(Clone, Debug, PartialEq)]
pub enum Link {
    /// Modbus TCP to `HOST:PORT`.
    Tcp { addr: String },
    /// Modbus RTU on a serial port.
    Rtu { path: String, line: LineSettings },
    /// Modbus RTU frames over a TCP connection (a transparent serial gateway).
    RtuOverTcp { addr: String },
    /// Modbus RTU frames through an RFC 2217 device server, which sets the line.
    RtuRfc2217 { addr: String, line: LineSettings },
    /// A byte stream handed over by the caller ([`K2Wire::attach`]): RTU or TCP framing.
    /// It cannot be reopened after a link failure.
    Attached { rtu: bool },
}

impl Link {
    /// The default per-request timeout: a second on TCP (gateways add the serial time);
    /// on a serial line 200 ms of PLC turnaround plus the time a maximal request and
    /// reply (2 × 256 characters of 11 bits) take at the baud rate.
    pub fn default_timeout(&self) -> Duration {
        match self {
            Link::Rtu { line, .. } => Duration::from_millis(200) + line.time_of(512),
            Link::RtuRfc2217 { line, .. } => Duration::from_secs(1) + line.time_of(512),
            _ => Duration::from_secs(1),
        }
    }

    fn costs(&self) -> Costs {
        match self {
            Link::Tcp { .. } | Link::Attached { rtu: false } => Costs::TCP,
            _ => Costs::RTU,
        }
    }

    /// What to check when the PLC does not answer.
    fn hint(&self) -> String {
        msg!("k2-hint-no-reply", link = self.kind()).into()
    }

    /// The link as the messages' `$link` selector names it.
    fn kind(&self) -> &'static str {
        match self {
            Link::Tcp { .. } => "tcp",
            Link::Rtu { .. } => "rtu",
            Link::RtuOverTcp { .. } => "gateway",
            Link::RtuRfc2217 { .. } => "rfc2217",
            Link::Attached { .. } => "stream",
        }
    }
}

impl Link {
    /// What to check when bytes arrive but do not make a valid reply: with a bad CRC the
    /// frame was damaged on its way (Modbus over serial line V1.02 §2.5.1.2: the CRC covers
    /// the whole frame), otherwise the line carries something that is not this PLC's reply.
    fn garbled_hint(&self, bad_crc: bool) -> String {
        if bad_crc {
            msg!("k2-hint-damaged", link = self.kind()).into()
        } else {
            msg!("k2-hint-garbled", link = self.kind()).into()
        }
    }
}

/// Per-device settings from the URL.
#[derive(Clone, Debug)]
pub struct Settings {
    pub unit: u8,
    pub word_order: WordOrder,
    pub timeout: Duration,
    /// Further attempts after a link failure (not after a Modbus exception).
    pub retries: u32,
}

/// Parses `timeout=`: milliseconds, or a duration with a unit (`500ms`, `2s`).
/// Checks a K2 wire option (a profile's `[options]`, `Device::set_option`) without a
/// connection: profiles are checked with it when the file is loaded.
pub fn check_option(key: &str, value: &str) -> Result<()> {
    match key {
        "word_order" => WordOrder::parse(value).map(|_| ()),
        "timeout" => parse_timeout(value).map(|_| ()),
        "retries" => parse_retries(value).map(|_| ()),
        "agent" => Ok(()),
        _ => Err(Error::usage(msg!("k2-no-option", key = key)).hint(msg!("k2-hint-options"))),
    }
}

fn parse_retries(value: &str) -> Result<u32> {
    value.parse().map_err(|_| Error::usage(msg!("k2-retries-not-number", value = value)))
}

fn parse_timeout(v: &str) -> Result<Duration> {
    crate::core::literal::parse_timeout(v).map_err(Error::usage)
}

/// One exchange: a read whose reply stays in the client's buffer, or any request decoded.
#[derive(Clone, Copy)]
enum Op<'a> {
    Read(u8, u16, u16),
    Call(&'a Request<'static>),
}

/// A failed request, before it is put in the user's terms.
enum Failure {
    Exception(ExceptionCode),
    Link(Error),
}

/// A K2 over Modbus.
pub struct K2Wire {
    info: DeviceInfo,
    space: K2Space,
    link: Link,
    settings: Settings,
    ctx: Option<ModbusClient>,
    requests: u64,
    /// The data of each request of the last read (registers as big-endian bytes, coils
    /// packed LSB first, as they travel), kept to be refilled by the next read.
    blocks: Vec<Vec<u8>>,
    /// The plan of the last read batch.
    last_read: Option<ReadPlan>,
    /// The PLC-side helper, when configured (`agent=VB3400`).
    agent: Option<AgentClient>,
    /// SM bytes as last read or written through the helper.
    sm_shadow: Memory,
    /// The PLC closed the current connection (set by the traced stream).
    peer_closed: std::sync::Arc<std::sync::atomic::AtomicBool>,
}

/// A read batch mapped and planned (everything but the wire).
struct ReadPlan {
    ops: Vec<Operand>,
    k2: Vec<K2Operand>,
    spans: Vec<Span>,
    requests: Vec<Span>,
    /// For each operand: where its bits are in the replies.
    takes: Vec<Take>,
}

/// Where one operand's value is in the replies of a planned read, worked out once per plan
/// so that decoding a polled batch is a byte load per operand.
#[derive(Clone, Copy, Debug)]
struct Take {
    /// The request (reply block) holding it.
    block: usize,
    how: How,
    /// The type the value is read as.
    dtype: crate::core::DataType,
}

#[derive(Clone, Copy, Debug)]
enum How {
    /// A word in a register reply: its high byte's index.
    Word(usize),
    /// A byte in a register reply: its index.
    Byte(usize),
    /// Anything else, through [`modbus_map::decode_reply`]: the operand, its span's offset
    /// and length in units of the reply, and whether the reply is packed bits.
    Span { op: K2Operand, off: usize, count: usize, bits: bool },
}

impl Take {
    fn new(o: &Operand, op: &K2Operand, span: &Span, request: &Span, block: usize, off: usize) -> Take {
        let bits = request.table().is_bits();
        let at = 2 * off + (op.byte % 2) as usize;
        let how = match op.width {
            Width::Word if !bits => How::Word(at),
            Width::Byte if !bits => How::Byte(at),
            _ => How::Span { op: *op, off, count: span.count as usize, bits },
        };
        Take { block, how, dtype: o.dtype }
    }

    #[inline(always)]
    fn value(&self, blocks: &[Vec<u8>], order: WordOrder) -> Value {
        let b = &blocks[self.block];
        let raw = match self.how {
            How::Word(at) => u16::from_be_bytes([b[at], b[at + 1]]) as u32,
            How::Byte(at) => b[at] as u32,
            How::Span { op, off, count, bits } => modbus_map::decode_reply(&op, bits, b, off, count, order),
        };
        self.dtype.decode(raw)
    }
}

impl ReadPlan {
    /// Maps every operand (refusing SM, T, C before anything is sent) and plans the requests.
    fn new(space: &K2Space, ops: &[Operand], costs: Costs) -> Result<ReadPlan> {
        let k2: Vec<K2Operand> = ops.iter().map(|o| K2Operand::from_key(o.key)).collect();
        let spans: Vec<Span> = k2.iter().map(|o| modbus_map::locate_read(space, o)).collect::<Result<_>>()?;
        let requests = coalesce::plan_reads(&spans, costs);
        let takes = ops
            .iter()
            .zip(&k2)
            .zip(&spans)
            .map(|((o, k), s)| {
                let (r, off) = coalesce::find(&requests, s).expect("every span is planned");
                Take::new(o, k, s, &requests[r], r, off)
            })
            .collect();
        Ok(ReadPlan { ops: ops.to_vec(), k2, spans, requests, takes })
    }
}

/// The URL parameters of a K2 on a wire; a serial line (`rtu:`, `rtu+rfc2217:`) also takes
/// [`LINE_PARAMS`].
pub const PARAMS: &[&str] = &["unit", "model", "word_order", "timeout", "retries", "agent"];
/// The serial line's parameters (`rtu:PORT`, `rtu+rfc2217://…`).
pub const LINE_PARAMS: &[&str] = &["baud", "parity", "stop"];

impl K2Wire {
    /// Opens `tcp://…`, `rtu:…` or `rtu+tcp://…` and connects.
    pub fn open(url: &DeviceUrl) -> Result<K2Wire> {
        let mut known = PARAMS.to_vec();
        let link = match url.scheme.as_str() {
            "tcp" => Link::Tcp { addr: with_port(&url.target) },
            "rtu+tcp" => Link::RtuOverTcp { addr: with_port(&url.target) },
            "rtu" | "rtu+rfc2217" => {
                known.extend(LINE_PARAMS);
                let carrier =
                    Carrier::from_url(url, "rtu:COM3?baud=19200&unit=1 or rtu:/dev/ttyUSB0?baud=19200&unit=1")?;
                let parity = url.param("parity").unwrap_or("none");
                let parity = Parity::parse(parity).ok_or_else(|| {
                    Error::usage(msg!("link-not-parity", parity = parity, url = url.text.as_str()))
                        .hint(msg!("link-hint-parity"))
                })?;
                let stop = match url.param("stop").unwrap_or("1") {
                    "1" => 1,
                    "2" => 2,
                    s => return Err(Error::usage(msg!("link-not-stop-bits", stop = s, url = url.text.as_str()))),
                };
                let baud = url.param_num::<u32>("baud")?.unwrap_or(9600);
                if baud == 0 {
                    return Err(Error::usage(msg!("link-baud-zero", url = url.text.as_str())));
                }
                let line = LineSettings { baud, data_bits: 8, parity, stop_bits: stop };
                match carrier {
                    Carrier::Rfc2217(addr) => Link::RtuRfc2217 { addr, line },
                    c => Link::Rtu { path: c.key(), line },
                }
            }
            s => return Err(Error::usage(msg!("k2-not-scheme", scheme = s))),
        };
        url.expect_params(&known)?;
        let default_model = if matches!(link, Link::Tcp { .. }) { "K204ET-16DT" } else { catalog::DEFAULT_MODEL };
        let model = catalog::lookup(url.param("model").unwrap_or(default_model))?;
        let unit = url.param_num::<u8>("unit")?.unwrap_or(1);
        if unit == 0 || unit > 247 {
            return Err(Error::usage(msg!("link-not-unit-id", unit = unit, url = url.text.as_str()))
                .hint(msg!("link-hint-unit-id")));
        }
        let settings = Settings {
            unit,
            word_order: url.param("word_order").map(WordOrder::parse).transpose()?.unwrap_or_default(),
            timeout: url.param("timeout").map(parse_timeout).transpose()?.unwrap_or_else(|| link.default_timeout()),
            retries: url.param_num::<u32>("retries")?.unwrap_or(2),
        };
        let mut dev = K2Wire::with_link(link, model, settings, url.text.clone())?;
        if let Some(a) = url.param("agent") {
            dev.agent = Some(sm::client(a, dev.settings.timeout, dev.space.model)?);
        }
        dev.connect().map_err(|e| match e {
            Failure::Link(e) => e,
            Failure::Exception(_) => unreachable!("connecting sends no request"),
        })?;
        Ok(dev)
    }

    /// A driver for `link` that connects on first use.
    pub fn with_link(link: Link, model: &'static Model, settings: Settings, name: String) -> Result<K2Wire> {
        Ok(K2Wire {
            info: DeviceInfo { family: "k2", model: model.name.to_string(), link: name, simulated: false },
            space: K2Space::new(model),
            link,
            settings,
            ctx: None,
            requests: 0,
            blocks: Vec::new(),
            last_read: None,
            agent: None,
            sm_shadow: sm::shadow(catalog::SM_BYTES),
            peer_closed: Default::default(),
        })
    }

    /// A driver on a byte stream the caller opened (any transport, an in-memory pipe in
    /// tests), with RTU (`rtu = true`) or Modbus TCP framing. The driver polls it on a
    /// runtime of its own.
    pub fn attach<T>(transport: T, rtu: bool, model: &'static Model, settings: Settings, name: String) -> Result<K2Wire>
    where
        T: tokio::io::AsyncRead + tokio::io::AsyncWrite + Send + Unpin + 'static,
    {
        let mut dev = K2Wire::with_link(Link::Attached { rtu }, model, settings, name.clone())?;
        let proto = if rtu { Proto::ModbusRtu } else { Proto::ModbusTcp };
        let port = AsyncPort::new(Box::new(transport), &name, proto, "attached stream")
            .map_err(|e| Error::io(msg!("k2-cannot-start-runtime")).cause(e))?;
        dev.ctx = Some(ModbusClient::new(Box::new(port), rtu, dev.settings.unit));
        Ok(dev)
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    fn connect(&mut self) -> std::result::Result<(), Failure> {
        let unit = self.settings.unit;
        let name = self.info.link.clone();
        let timeout = self.settings.timeout;
        self.peer_closed.store(false, std::sync::atomic::Ordering::Relaxed);
        let closed = self.peer_closed.clone();
        let link = &self.link;
        let ctx = (|| -> Result<ModbusClient> {
            match link {
                Link::Tcp { addr } | Link::RtuOverTcp { addr } => {
                    let stream = tcp_connect(addr, timeout)?;
                    let tcp = matches!(link, Link::Tcp { .. });
                    let proto = if tcp { Proto::ModbusTcp } else { Proto::RtuOverTcp };
                    port::tcp_port(stream, &name, proto, addr)
                        .map(|mut p| {
                            p.watch_eof(closed);
                            ModbusClient::new(p, !tcp, unit)
                        })
                        .map_err(|e| Error::link(msg!("link-cannot-use-connection", addr = addr.as_str())).cause(e))
                }
                Link::Attached { .. } => Err(Error::link(msg!("k2-attached-failed"))),
                Link::Rtu { path, line } => {
                    let p = port::serial_port(path, *line, &name, Proto::ModbusRtu).map_err(|e| {
                        let h = e.hint.clone().unwrap_or_default();
                        e.hint(msg!("k2-hint-reopen", hint = h))
                    })?;
                    Ok(ModbusClient::new(p, true, unit))
                }
                Link::RtuRfc2217 { addr, line } => {
                    let t = crate::core::link::rfc2217::Rfc2217::connect(addr, *line, timeout)?;
                    let mut p = port::TransportPort::new(Box::new(t), &name, Proto::ModbusRtu, addr);
                    p.watch_eof(closed);
                    Ok(ModbusClient::new(Box::new(p), true, unit))
                }
            }
        })();
        match ctx {
            Ok(c) => {
                self.ctx = Some(c);
                Ok(())
            }
            Err(e) if e.hint.is_some() => Err(Failure::Link(e)),
            Err(e) => Err(Failure::Link(e.hint(self.link.hint()))),
        }
    }

    /// Sends one request, retrying link failures; exceptions come back at once.
    fn call(&mut self, req: Request<'static>) -> std::result::Result<tokio_modbus::Response, Failure> {
        Ok(self.exchange(Op::Call(&req))?.expect("a call decodes its reply"))
    }

    /// Reads `span` (one planned request) into `out`: the reply's data as it travelled.
    fn read_request(&mut self, span: &Span, out: &mut Vec<u8>) -> std::result::Result<(), Failure> {
        let (table, start, n) = (span.table(), span.start, span.count);
        self.exchange(Op::Read(table.read_fc(), start, n))?;
        let data = self.ctx.as_ref().expect("a reply was taken").data();
        // Registers: exactly 2 bytes each; coils: at least one bit each, packed.
        let want = if table.is_bits() { (n as usize).div_ceil(8) } else { 2 * n as usize };
        let fits = data.len() == 1 + data[0] as usize
            && if table.is_bits() { data.len() > want } else { data.len() == want + 1 };
        if !fits {
            return Err(Failure::Link(Error::link(msg!("k2-reply-too-short", span = span.describe()))));
        }
        out.clear();
        out.extend_from_slice(&data[1..]);
        Ok(())
    }

    /// Runs one exchange on the connection (connecting first when needed), retrying link
    /// failures with backoff; exceptions come back at once.
    fn exchange(&mut self, op: Op<'_>) -> std::result::Result<Option<tokio_modbus::Response>, Failure> {
        let mut last = None;
        for attempt in 0..=self.settings.retries {
            if attempt > 0 {
                std::thread::sleep(Duration::from_millis(50 << (attempt - 1).min(4)));
            }
            if self.ctx.is_none() {
                if let Err(f) = self.connect() {
                    last = Some(f);
                    continue;
                }
            }
            let ctx = self.ctx.as_mut().expect("connected");
            self.requests += 1;
            let timeout = self.settings.timeout;
            let deadline = std::time::Instant::now() + timeout;
            let r = match op {
                Op::Read(fc, start, n) => ctx.read(fc, start, n, deadline).map(|r| r.map(|()| None)),
                Op::Call(req) => ctx.call(req, deadline).map(|r| r.map(Some)),
            };
            match r {
                Ok(Ok(resp)) => return Ok(resp),
                Ok(Err(code)) => return Err(Failure::Exception(code)),
                Err(e) if e.kind() == std::io::ErrorKind::TimedOut => {
                    self.ctx = None;
                    last = Some(Failure::Link(Error::link(msg!(
                        "link-no-reply",
                        unit = self.settings.unit,
                        timeout = ms(timeout)
                    ))));
                }
                Err(e) if client::garbled(&e).is_some() => {
                    // Something arrived, but not a reply: say what, never "did not answer".
                    self.ctx = None;
                    let g = client::garbled(&e).expect("checked");
                    let m = msg!(
                        "link-no-valid-reply",
                        unit = self.settings.unit,
                        timeout = ms(timeout),
                        what = g.to_string()
                    );
                    last = Some(Failure::Link(Error::link(m).hint(self.link.garbled_hint(g.bad_crc.is_some()))));
                }
                Err(e) => {
                    // Dropped connection, garbled or mismatched reply: start afresh.
                    self.ctx = None;
                    last = Some(Failure::Link(if self.peer_closed.load(std::sync::atomic::Ordering::Relaxed) {
                        // The stream saw the end of file (a read or a write may report it).
                        Error::link(msg!("link-closed")).hint(msg!("k2-hint-closed"))
                    } else {
                        Error::link(msg!("link-failed")).cause(e)
                    }));
                }
            }
        }
        let attempts = self.settings.retries + 1;
        Err(match last.expect("at least one attempt") {
            Failure::Link(mut e) => {
                if attempts > 1 {
                    e.message = msg!("link-attempts", message = e.message.as_str(), attempts = attempts).text;
                }
                if e.hint.is_none() {
                    e = e.hint(self.link.hint());
                }
                Failure::Link(e)
            }
            f => f,
        })
    }

    /// Puts a failure in the user's terms: what was asked, for which operand.
    /// `doing` is `reading` or `writing` (the `$doing` selector of `k2-request`).
    fn explain(&self, f: Failure, doing: &str, span: &Span, fc: u8, op: &K2Operand, more: usize) -> Error {
        let what = msg!(
            "k2-request",
            doing = doing,
            operand = op.canonical(),
            more = more,
            span = span.describe(),
            fc = format!("{fc:02}")
        )
        .text;
        match f {
            Failure::Link(e) => {
                let mut e = e.operand(op.canonical());
                e.message = msg!("k2-while", what = what, message = e.message.as_str()).text;
                e
            }
            Failure::Exception(code) => {
                let c = u8::from(code);
                let hint = match c {
                    1 => msg!("k2-hint-exception-1"),
                    2 => msg!("k2-hint-exception-2", model = self.space.model.name),
                    3 => msg!("k2-hint-exception-3"),
                    _ => msg!("k2-hint-exception"),
                };
                Error::new(
                    ErrorKind::Refused,
                    msg!(
                        "k2-refused",
                        what = what,
                        exception = modbus_map::exception_name(c),
                        code = format!("{c:02}")
                    ),
                )
                .operand(op.canonical())
                .hint(hint)
            }
        }
    }

    /// Reads planned requests; errors name the first operand each request was for.
    /// `blocks` gets one buffer per request (kept buffers are refilled).
    fn read_plan(&mut self, plan: &[Span], spans: &[Span], ops: &[K2Operand], blocks: &mut Vec<Vec<u8>>) -> Result<()> {
        blocks.resize_with(plan.len().max(blocks.len()), Vec::new);
        for (req, block) in plan.iter().zip(blocks.iter_mut()) {
            match self.read_request(req, block) {
                Ok(()) => {}
                Err(f) => {
                    let mine: Vec<usize> = (0..spans.len())
                        .filter(|&i| coalesce::find(std::slice::from_ref(req), &spans[i]).is_some())
                        .collect();
                    let first = mine.first().copied().unwrap_or(0);
                    return Err(self.explain(
                        f,
                        "reading",
                        req,
                        req.table().read_fc(),
                        &ops[first],
                        mine.len().saturating_sub(1),
                    ));
                }
            }
        }
        Ok(())
    }
}

/// `a == b`, without a branch per field (a polling loop asks this of every read).
fn same_batch(a: &[Operand], b: &[Operand]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).fold(0u64, |d, (x, y)| {
            // Every field (a new one fails to compile here until it is compared).
            let Operand { key, dtype, bits } = *x;
            d | (key ^ y.key) | (dtype as u64 ^ y.dtype as u64) | (bits ^ y.bits) as u64
        }) == 0
}

/// Connects to `addr` (`HOST:PORT`) within `timeout` ([`crate::core::link::tcp::connect`]).
fn tcp_connect(addr: &str, timeout: Duration) -> Result<std::net::TcpStream> {
    crate::core::link::tcp::connect(addr, timeout, || msg!("k2-hint-connect").into())
}

fn with_port(target: &str) -> String {
    let t = target.trim_end_matches('/');
    if t.rsplit_once(':').is_some_and(|(_, p)| p.parse::<u16>().is_ok()) {
        t.to_string()
    } else {
        format!("{t}:502")
    }
}

/// A timeout in a message, as exact as the user gave it (`timeout=0.5` is `0.5 ms`).
fn ms(d: Duration) -> String {
    crate::core::literal::millis_text(d)
}

impl Device for K2Wire {
    fn info(&self) -> &DeviceInfo {
        &self.info
    }

    fn operands(&self) -> &dyn OperandSpace {
        &self.space
    }

    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        // The common case (no SM through the helper) goes straight to Modbus, with no extra pass.
        if self.agent.is_none() || !ops.iter().any(|o| self.uses_agent(&K2Operand::from_key(o.key))) {
            return self.read_modbus(ops);
        }
        let via_agent: Vec<bool> = ops.iter().map(|o| self.uses_agent(&K2Operand::from_key(o.key))).collect();
        // Check the Modbus part first, so a bad operand fails before any helper command.
        let (sm_ops, bus_ops): (Vec<Operand>, Vec<Operand>) = {
            let (a, b): (Vec<_>, Vec<_>) = ops.iter().zip(&via_agent).partition(|(_, v)| **v);
            (a.into_iter().map(|(o, _)| *o).collect(), b.into_iter().map(|(o, _)| *o).collect())
        };
        let bus = if bus_ops.is_empty() { Vec::new() } else { self.read_modbus(&bus_ops)? };
        let sm = self.read_sm(&sm_ops)?;
        let (mut bi, mut si) = (bus.into_iter(), sm.into_iter());
        Ok(via_agent.iter().map(|v| if *v { si.next() } else { bi.next() }.expect("one value per operand")).collect())
    }

    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        if self.agent.is_none() || !items.iter().any(|(o, _)| self.uses_agent(&K2Operand::from_key(o.key))) {
            return self.write_modbus(items);
        }
        let via_agent: Vec<bool> = items.iter().map(|(o, _)| self.uses_agent(&K2Operand::from_key(o.key))).collect();
        // Validate the Modbus items before anything is sent; then write runs in the user's order.
        for ((o, _), v) in items.iter().zip(&via_agent) {
            if !v {
                modbus_map::locate_write(&self.space, &K2Operand::from_key(o.key))?;
            }
        }
        let mut i = 0;
        while i < items.len() {
            let kind = via_agent[i];
            let mut j = i;
            while j < items.len() && via_agent[j] == kind {
                j += 1;
            }
            if kind {
                self.write_sm(&items[i..j])?;
            } else {
                self.write_modbus(&items[i..j])?;
            }
            i = j;
        }
        Ok(())
    }

    fn requests(&self) -> u64 {
        self.requests
    }

    /// The K2 operations (`k2::ops`): this connection permits everything.
    fn family(&mut self, _changes: &[crate::core::device::Change]) -> Result<Option<&mut dyn std::any::Any>> {
        Ok(Some(self))
    }

    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        check_option(key, value)?;
        match key {
            "word_order" => self.settings.word_order = WordOrder::parse(value)?,
            "timeout" => self.settings.timeout = parse_timeout(value)?,
            "retries" => self.settings.retries = parse_retries(value)?,
            "agent" => self.agent = Some(sm::client(value, self.settings.timeout, self.space.model)?),
            _ => unreachable!("check_option knows every option"),
        }
        Ok(())
    }
}

impl K2Wire {
    fn read_modbus(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        // Polling loops read the same batch again and again: keep its plan.
        let plan = match self.last_read.take() {
            Some(p) if same_batch(&p.ops, ops) => p,
            _ => ReadPlan::new(&self.space, ops, self.link.costs())?,
        };
        let mut blocks = std::mem::take(&mut self.blocks);
        let read = self.read_plan(&plan.requests, &plan.spans, &plan.k2, &mut blocks);
        let order = self.settings.word_order;
        let values = read.map(|()| plan.takes.iter().map(|t| t.value(&blocks, order)).collect());
        self.blocks = blocks;
        self.last_read = Some(plan);
        values
    }

    fn write_modbus(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        let k2: Vec<K2Operand> = items.iter().map(|(o, _)| K2Operand::from_key(o.key)).collect();
        let spans: Vec<Span> = k2.iter().map(|o| modbus_map::locate_write(&self.space, o)).collect::<Result<_>>()?;
        let raws: Vec<u32> = items.iter().map(|(o, v)| o.dtype.encode(v)).collect();
        let order = self.settings.word_order;

        // Read the registers that byte, bit and odd-address writes only partly cover.
        let rmw: Vec<usize> = (0..k2.len()).filter(|&i| modbus_map::write_needs_read(&k2[i], &spans[i])).collect();
        let mut image: HashMap<(u8, u16), u16> = HashMap::new();
        if !rmw.is_empty() {
            let rspans: Vec<Span> = rmw.iter().map(|&i| spans[i]).collect();
            let rops: Vec<K2Operand> = rmw.iter().map(|&i| k2[i]).collect();
            let plan = coalesce::plan_reads(&rspans, self.link.costs());
            let mut blocks = Vec::new();
            self.read_plan(&plan, &rspans, &rops, &mut blocks)?;
            for (req, block) in plan.iter().zip(&blocks) {
                if !req.table().is_bits() {
                    for (k, v) in block.chunks_exact(2).enumerate() {
                        image.insert((req.region, req.start + k as u16), u16::from_be_bytes([v[0], v[1]]));
                    }
                }
            }
        }

        for (n, run) in coalesce::plan_writes(&spans).into_iter().enumerate() {
            let s = run.span;
            let req = if s.table().is_bits() {
                let mut bits = vec![false; s.count as usize];
                for &i in &run.items {
                    let off = (spans[i].start - s.start) as usize;
                    let part = &mut bits[off..off + spans[i].count as usize];
                    modbus_map::encode(&k2[i], raws[i], DataMut::Bits(part), order);
                }
                if bits.len() == 1 {
                    Request::WriteSingleCoil(s.start, bits[0])
                } else {
                    Request::WriteMultipleCoils(s.start, bits.into())
                }
            } else {
                let mut words: Vec<u16> =
                    (0..s.count).map(|k| image.get(&(s.region, s.start + k)).copied().unwrap_or(0)).collect();
                for &i in &run.items {
                    let off = (spans[i].start - s.start) as usize;
                    let part = &mut words[off..off + spans[i].count as usize];
                    modbus_map::encode(&k2[i], raws[i], DataMut::Words(part), order);
                }
                for (k, w) in words.iter().enumerate() {
                    image.insert((s.region, s.start + k as u16), *w);
                }
                if words.len() == 1 {
                    Request::WriteSingleRegister(s.start, words[0])
                } else {
                    Request::WriteMultipleRegisters(s.start, words.into())
                }
            };
            let fc = req.function_code().value();
            if let Err(f) = self.call(req) {
                let first = run.items[0];
                let mut e = self.explain(f, "writing", &s, fc, &k2[first], run.items.len() - 1);
                if n > 0 {
                    e.message = msg!("k2-writes-before", message = e.message.as_str(), sent = n).text;
                }
                return Err(e);
            }
        }
        Ok(())
    }
}

/// The instructions run through the helper program (without one they explain how to get it).
impl super::K2Ops for K2Wire {
    fn model(&self) -> &'static Model {
        self.space.model
    }
    fn pls(&mut self, channel: u8) -> Result<String> {
        self.instruction(super::agent::protocol::Command::Pls(channel), &format!("PLS {channel}"))
    }
    fn hdef(&mut self, counter: u8, mode: u8) -> Result<String> {
        self.instruction(
            super::agent::protocol::Command::Hdef { hsc: counter, mode },
            &format!("HDEF {counter}, {mode}"),
        )
    }
    fn hsc(&mut self, counter: u8) -> Result<String> {
        self.instruction(super::agent::protocol::Command::Hsc(counter), &format!("HSC {counter}"))
    }
    fn pstop(&mut self, channel: u8) -> Result<String> {
        self.instruction(super::agent::protocol::Command::Pstop(channel), &format!("PSTOP {channel}"))
    }
    fn read_rtc(&mut self) -> Result<super::instr::RtcTime> {
        self.rtc_read()
    }
    fn helper_status(&mut self) -> Result<String> {
        self.agent_status()
    }
    fn set_rtc(&mut self, t: super::instr::RtcTime) -> Result<()> {
        self.agent_run(&super::agent::protocol::Command::SetRtc(t.to_bcd8()), "SET_RTC").map(|_| ())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};

    /// The driver attached over an in-memory pipe to the simulator's RTU server (on a thread
    /// of its own), with the simulator shared for checks.
    fn served(sim: crate::k2::sim::K2Sim) -> (K2Wire, Arc<Mutex<crate::k2::sim::K2Sim>>, std::thread::JoinHandle<()>) {
        use crate::k2::sim::modbus_net::serve_rtu_stream;
        use crate::k2::sim::modbus_server::K2Service;
        let (client, server) = tokio::io::duplex(1024);
        let model = sim.model();
        let sim = Arc::new(Mutex::new(sim));
        let service = K2Service::new(sim.clone(), 1);
        let srv = std::thread::spawn(move || {
            let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
            let _ = rt.block_on(serve_rtu_stream(server, service));
        });
        let settings =
            Settings { unit: 1, word_order: WordOrder::HighFirst, timeout: Duration::from_secs(2), retries: 0 };
        (K2Wire::attach(client, true, model, settings, "pipe".into()).unwrap(), sim, srv)
    }

    /// A numeric address connects without a lookup; a name (`localhost`, from the hosts
    /// file) is looked up off the caller's thread and connects too; a closed port is a link
    /// error that says what to check.
    #[test]
    fn tcp_connect_by_address_and_by_name() {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        let port = l.local_addr().unwrap().port();
        let t = Duration::from_secs(5);
        tcp_connect(&format!("127.0.0.1:{port}"), t).unwrap();
        tcp_connect(&format!("localhost:{port}"), t).unwrap();
        drop(l);
        let e = tcp_connect(&format!("127.0.0.1:{port}"), t).unwrap_err();
        assert!(e.message.contains(&format!("127.0.0.1:{port}")), "{}", e.message);
        assert!(e.hint.as_deref().unwrap_or("").contains("firewall"), "{:?}", e.hint);
    }

    /// The driver against the simulator's RTU server over an in-memory pipe: the same map
    /// in both directions, no sockets.
    #[test]
    fn driver_and_simulator_server_agree_over_a_pipe() {
        let model = catalog::find("K205-16DT").unwrap();
        let (mut dev, sim, srv) = served(crate::k2::sim::K2Sim::new(model, crate::core::Clock::stepped()));
        let ops = dev.operands().parse("VW300").unwrap();
        let more = dev.operands().parse("VB301").unwrap();
        dev.write(&[(ops[0], Value::Int(0x1234)), (more[0], Value::Int(0xAB))]).unwrap();
        assert_eq!(dev.read(&ops).unwrap(), vec![Value::Int(0x12AB)]);
        assert_eq!(&sim.lock().unwrap().mem.v[300..302], &[0x12, 0xAB], "the simulator holds what the driver wrote");
        assert_eq!(dev.requests(), 3, "one read for VB301's read-modify-write, one write of register 250, one read");
        let sm = dev.operands().parse("SMB67").unwrap();
        assert_eq!(dev.read(&sm).unwrap_err().kind, ErrorKind::Unsupported);
        assert_eq!(dev.requests(), 3, "nothing was sent for SMB67");
        drop(dev);
        srv.join().unwrap();
    }

    /// Every operand shape read over the wire equals the simulator's own read of it, polled
    /// twice (the second read reuses the plan and the reply buffers).
    #[test]
    fn a_mixed_batch_reads_as_the_simulator_reads_it() {
        let model = catalog::find("K205-16DT").unwrap();
        let mut sim = crate::k2::sim::K2Sim::new(model, crate::core::Clock::stepped());
        for (k, b) in sim.mem.v.iter_mut().enumerate().take(400) {
            *b = (k * 37 + 11) as u8;
        }
        for (k, b) in sim.mem.m.iter_mut().enumerate().take(16) {
            *b = (k * 53 + 7) as u8;
        }
        let (mut dev, sim, srv) = served(sim);
        let text = "VB0 VB1 VW0 VW1 VW2/INT VD4 VD5 VD8/REAL V3.5 K4V10.2 M1.2 MB1 MW2 MD3 K3M0.5 VW100[5] VB300";
        let ops: Vec<Operand> =
            text.split(' ').flat_map(|t| dev.operands().parse(t).unwrap_or_else(|e| panic!("{t}: {e}"))).collect();
        let want = sim.lock().unwrap().read(&ops).unwrap();
        for _ in 0..2 {
            assert_eq!(dev.read(&ops).unwrap(), want, "{text}");
        }
        drop(dev);
        srv.join().unwrap();
    }

    #[test]
    fn a_kept_plan_is_reused_only_for_the_same_batch() {
        let space = K2Space::new(catalog::find("K205-16DT").unwrap());
        let p = |t: &str| -> Vec<Operand> { t.split(' ').flat_map(|o| space.parse(o).unwrap()).collect() };
        assert!(same_batch(&p("VW0 VW2"), &p("VW0 VW2")));
        assert!(!same_batch(&p("VW0 VW2"), &p("VW0 VW4")));
        assert!(!same_batch(&p("VW0"), &p("VW0/INT")), "another type");
        assert!(!same_batch(&p("VW0"), &p("VW0 VW2")));
    }

    #[test]
    fn urls_give_links_defaults_and_clear_errors() {
        let u = |t: &str| DeviceUrl::parse(t).unwrap();
        assert_eq!(with_port("10.0.0.5"), "10.0.0.5:502");
        assert_eq!(with_port("10.0.0.5:1502"), "10.0.0.5:1502");
        assert_eq!(parse_timeout("250").unwrap(), Duration::from_millis(250));
        assert_eq!(parse_timeout("2s").unwrap(), Duration::from_secs(2));
        assert!(parse_timeout("0").is_err());
        // 18446744073709552 ms × 1000 wrapped to 384 µs in a release build.
        let e = parse_timeout("18446744073709552").unwrap_err();
        assert!(e.message.contains("longer than a day (86400000 ms)"), "{e}");
        let rtu = Link::Rtu { path: "/dev/null".into(), line: LineSettings::n81(9600) };
        assert_eq!(
            rtu.default_timeout(),
            Duration::from_millis(200) + Duration::from_micros(533_334),
            "512 characters of 10 bits at 9600 baud"
        );
        for (url, needle) in [
            ("tcp://127.0.0.1:1?unit=0", "unit"),
            ("tcp://127.0.0.1:1?bogus=1", "unknown parameter"),
            ("tcp://127.0.0.1:1?word_order=middle", "word order"),
            ("rtu:/dev/null?parity=mark", "parity"),
            ("rtu:?baud=9600", "no serial port"),
            ("tcp://127.0.0.1:1?model=K999", "unknown K2 model"),
        ] {
            let e = K2Wire::open(&u(url)).err().unwrap_or_else(|| panic!("{url} opened"));
            assert_eq!(e.kind, ErrorKind::Usage, "{url}: {e}");
            assert!(e.to_string().contains(needle), "{url}: {e}");
        }
    }
}
