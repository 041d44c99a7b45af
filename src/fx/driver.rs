//! The FX drivers: one [`Device`] that speaks either the programming-port protocol
//! (`fx:/dev/ttyUSB0`, 9600 7E1) or the computer link (`fxlink:/dev/ttyUSB0?station=0&pc=FF&wait=0`)
//! over any [`Transport`] — a serial port, a pty served by `plcsh sim serve`, or the
//! in-process simulator (`sim-fx:FX2N`, which therefore runs this same code).
//!
//! - Programming port: the first request probes ENQ; a PLC that answers ACK gets the ENQ/ACK
//!   handshake before the conversation (and again after a failure), one that leaves ENQ
//!   unanswered gets its frames without it (what public drivers send); NAK to ENQ is a real
//!   answer. Each operand goes through the model's address table ([`Table::of`]): the classic
//!   commands 0/1/7/8 on an FX1S/FX1N/FX2N, the E-commands E00/E10/E7/E8 on an FX3U. Reads
//!   coalesce into the fewest frames of at most 64 bytes within one region of the address
//!   table; words are written with command 1 (adjacent words in one frame),
//!   bits are forced ON/OFF (commands 7/8), a `Kn` group that covers whole bytes is written
//!   as bytes and any other group bit by bit — never a read-modify-write of the PLC's bytes.
//! - Computer link: bits read with BR (≤ 256 points a frame), words with WR (≤ 64); writes
//!   with BW and WW, and WT when single words at scattered devices are written together.
//! - Transactions sit on the line's timing ([`LineSettings`]): before every request the line
//!   must be quiet for a few character times (a late reply or a tail of noise is dropped,
//!   never read as this request's reply); each request's timeout is both frames' time on the
//!   wire plus the link's message wait plus the PLC's turnaround ([`TURNAROUND`]; a device
//!   server adds [`NETWORK_ALLOWANCE`]), unless the URL's `timeout=` says otherwise; after
//!   silence the line must stay quiet for one more timeout, so a late reply is dropped there.
//! - A reply must fit its request: the station and PC number of the request, a data frame
//!   of the asked length for a read, ACK for a write (a write is done only on ACK from the
//!   addressed station). Anything else is "something else" — named, resent, reported as a
//!   link error, never success. Bytes in front of a reply that cannot start one (00H from
//!   parity errors, bytes with bit 7, stray characters) are noise: set aside, and reported as
//!   noise when nothing else comes; a NAK is only a NAK character where the reply starts.
//! - A NAK, a bad sum check, noise or a reply that does not fit is resent up to three times
//!   (the seed's host program: "如重复3次仍不行则显示错误信息"), each resend after the line has
//!   been quiet for at least the frame time; then reported: NAK as the PLC refusing (kind
//!   `refused`, the link's error code in words), the rest as link errors listing what each
//!   attempt got. On the link only NAKs that a resend can cure (sum check 02, protocol 03)
//!   are retried. Silence is reported at once with what to check.
//!
//! URL parameters: `model` (FX2N), `timeout` (computed from the line; a number is ms;
//! `auto`), `retries` (3); `fx:` `baud` (9600);
//! `fxlink:` `station` (0), `pc` (FF), `wait` (0–15, ×10 ms), `baud` (9600), `bits` (7),
//! `parity` (e/o/n), `stop` (1/2), `sum` (1), `format` (1 or 4), `xy` (octal, or decimal for
//! a PLC that numbers X/Y in link frames as the seed literally says). `sim-fx:MODEL` takes
//! `protocol=port|link`, the link's `station`/`sum`/`format`, and `share=NAME`: devices with
//! one share name use one simulated PLC (the port and the link of one PLC).

use super::link::{self as fxlink, Cmd, Dev, Header, Reply, Settings};
use super::memory::Memory;
use super::model::Model;
use super::operand::{system_driven, Area, FxOperand, Width, CN32_FIRST};
use super::port::{self, Request, Table, ACK, ENQ, NAK};
use super::sim::{LinkServer, Plc, PortServer, Server, SimLink};
use super::space::{FxSpace, Proto};
use crate::core::link::line::{self as lines, SharedLine, Transport};
use crate::core::link::serial::{Carrier, LineSettings, Parity};
use crate::core::literal::millis_text;
use crate::core::trace::{self, Dir, Proto as Wire};
use crate::core::url::DeviceUrl;
use crate::core::{Clock, Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, Weak};
use std::time::{Duration, Instant};

/// What the PLC may take to turn a request round, on top of both frames' time on the wire
/// and the message wait: it answers in the END processing of a scan (a scan longer than the
/// watchdog, D8000 = 200 ms by default, stops the PLC), plus a USB adapter's and the
/// operating system's latency.
pub const TURNAROUND: Duration = Duration::from_millis(250);
/// What a serial device server (raw TCP, RFC 2217) adds to every exchange.
pub const NETWORK_ALLOWANCE: Duration = Duration::from_millis(300);
/// Resends after a NAK or a bad sum check (seed 004: three).
pub const DEFAULT_RETRIES: u32 = 3;
/// The line when nothing says otherwise (the in-process simulator): the programming port's
/// 9600 baud 7E1 (seed 004, FX2 article: "传输速率固定为9600bps，奇偶校验位采用偶校验 … 七位有效数据").
pub const DEFAULT_LINE: LineSettings = LineSettings { baud: 9600, data_bits: 7, parity: Parity::Even, stop_bits: 1 };
/// The longest reply of either protocol, in characters: a link BR of 256 points or WR of 64
/// words, with sum check and CR LF (the programming port's 64-byte read reply is 132).
const LONGEST_REPLY: usize = 1 + 4 + 256 + 1 + 2 + 2;
/// A frame that grows past this without ending is garbage, not a reply.
const FRAME_CAP: usize = 2 * LONGEST_REPLY;
/// Bounds of the quiet awaited before a request: a few character times.
const GAP_MIN: Duration = Duration::from_millis(5);
const GAP_MAX: Duration = Duration::from_millis(50);
/// Least quiet awaited before a resend (at least the frame time, and never less than this).
const RESEND_MIN: Duration = Duration::from_millis(20);
/// Longest quiet awaited after silence, for a late reply to be dropped.
const LATE_MAX: Duration = Duration::from_secs(2);

/// What the request must be answered with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Expect {
    /// A data frame of `chars` characters in all, `data` of them the data (port: bytes).
    Data { chars: usize, data: usize },
    /// ACK (`chars`: 1 on the port, `ACK station pc` on the link).
    Ack { chars: usize },
}

impl Expect {
    fn chars(self) -> usize {
        match self {
            Expect::Data { chars, .. } | Expect::Ack { chars } => chars,
        }
    }
}

/// What came back for one frame, judged against the request.
#[derive(Clone, Debug, PartialEq)]
enum Got {
    /// The data asked for.
    Data(Vec<u8>),
    /// ACK from the addressed station, to a write.
    Ack,
    /// NAK from the addressed station (the link's error code).
    Nak(Option<u8>),
    /// A reply whose sum check fails.
    BadSum(String),
    /// A reply that does not answer this request: another station's, the wrong kind (a data
    /// frame to a write, ACK to a read), another length, garbled. In words.
    Other(String),
    /// Nothing but noise within the timeout.
    Noise(Vec<u8>),
    /// A reply that began but was not complete when the timeout ran out.
    Partial(Vec<u8>),
    /// Nothing; `late` characters arrived in the quiet awaited afterwards (and were dropped).
    Silent { late: usize },
}

impl Got {
    /// A few words for the list of attempts in a message.
    fn label(&self) -> String {
        match self {
            Got::Data(_) => "data".into(),
            Got::Ack => "ACK".into(),
            Got::Nak(None) => "NAK".into(),
            Got::Nak(Some(c)) => format!("NAK {c:02X}H"),
            Got::BadSum(_) => "bad sum check".into(),
            Got::Other(_) => "another reply".into(),
            Got::Noise(_) => "noise".into(),
            Got::Partial(_) => "an incomplete reply".into(),
            Got::Silent { .. } => "silence".into(),
        }
    }
}

/// What arrived for one request: noise in front of the reply, set aside, and the reply from
/// its first character.
#[derive(Default)]
struct Heard {
    noise: Vec<u8>,
    frame: Vec<u8>,
    complete: bool,
}

/// `; 12 characters came later …` when a late reply was dropped.
fn late_text(late: usize) -> String {
    if late == 0 {
        return String::new();
    }
    format!("; {late} characters came later and were dropped (a late reply is never taken for the next request's)")
}

/// Bytes for a message: `31 × 00H` for a run of one byte, else hex (the first 12 and the count).
fn show(bytes: &[u8]) -> String {
    match bytes {
        [first, rest @ ..] if bytes.len() >= 4 && rest.iter().all(|b| b == first) => {
            format!("{} × {first:02X}H", bytes.len())
        }
        _ if bytes.len() <= 12 => trace::hex_bytes(bytes),
        _ => format!("{} … ({} characters)", trace::hex_bytes(&bytes[..12]), bytes.len()),
    }
}

/// How long the programming-port reply at the start of `f` is (`f` starts with STX, ACK or
/// NAK): ACK and NAK are one character, a data frame ends two characters after ETX.
fn port_len(f: &[u8]) -> Option<usize> {
    match f.first()? {
        &port::STX => f
            .iter()
            .position(|b| *b == port::ETX)
            .map(|p| p + 3)
            .filter(|n| f.len() >= *n)
            .or((f.len() >= FRAME_CAP).then_some(f.len())),
        _ => Some(1),
    }
}

/// Judges a complete programming-port reply (seed 004: a read is answered `STX data ETX sum`,
/// a write or force ACK, a refused frame NAK — "如传送的命令有错误，PLC返回NAK信号").
fn classify_port(f: &[u8], expect: Expect) -> Got {
    match (f[0], expect) {
        (NAK, _) => Got::Nak(None),
        (ACK, Expect::Ack { .. }) => Got::Ack,
        (ACK, Expect::Data { .. }) => Got::Other("ACK where the data should be".into()),
        (_, Expect::Ack { .. }) => Got::Other(format!("a data frame ({}) where ACK should be", show(f))),
        (_, Expect::Data { data, .. }) => match port::decode_read_reply(f, data) {
            Ok(d) => Got::Data(d),
            Err(port::FrameError::BadSum { got, want }) => {
                Got::BadSum(format!("sum check {got:02X}, the characters add up to {want:02X}"))
            }
            Err(port::FrameError::Malformed(m)) => Got::Other(format!("a garbled frame ({}): {m}", show(f))),
        },
    }
}

/// Judges a complete computer-link reply (seed 004, "FX系列PLC专用协议通信指令格式详解": the
/// reply repeats the station and PC number; data comes as `STX … ETX sum`, a write is
/// acknowledged with ACK, an error is NAK with its code — "若发送码有误，则有以下回应"). A link
/// reply carries no device address, so the station, the kind and the length are all there is
/// to tell this request's reply from another's.
fn classify_link(f: &[u8], h: Header, s: Settings, expect: Expect) -> Got {
    match (fxlink::decode_reply(f, h, s), expect) {
        (Ok(Reply::Data(d)), Expect::Data { data, .. }) if d.len() == data => Got::Data(d),
        (Ok(Reply::Data(d)), Expect::Data { data, .. }) => Got::Other(format!(
            "a data frame with {} characters of data where {data} were asked for (the reply to another request)",
            d.len()
        )),
        (Ok(Reply::Data(_)), Expect::Ack { .. }) => Got::Other(format!(
            "a data frame ({}) where ACK should be: a write is done only when the station answers ACK",
            show(f)
        )),
        (Ok(Reply::Ack), Expect::Ack { .. }) => Got::Ack,
        (Ok(Reply::Ack), Expect::Data { .. }) => Got::Other("ACK where the data should be".into()),
        (Ok(Reply::Nak(c)), _) => Got::Nak(Some(c)),
        (Err(fxlink::ReplyError::BadSum { got, want }), _) => {
            Got::BadSum(format!("sum check {got:02X}, the characters add up to {want:02X}"))
        }
        (Err(fxlink::ReplyError::Station { station, pc }), _) => Got::Other(format!(
            "a reply from station {station} (PC number {pc:02X}) where station {} (PC number {:02X}) should answer",
            h.station, h.pc
        )),
        (Err(fxlink::ReplyError::Malformed(m)), _) => Got::Other(format!("a garbled frame ({}): {m}", show(f))),
    }
}

/// Protocol state.
enum Mode {
    /// `synced`: the conversation is open (ENQ answered, or not wanted).
    Port {
        synced: bool,
        handshake: Handshake,
    },
    Link {
        header: Header,
        settings: Settings,
    },
}

/// Whether the programming port wants ENQ before a frame. The seed's host program opens with
/// ENQ and waits for ACK; public drivers (node-fxplc, KrystianD/fxplc, HslCommunication) send
/// their frames without it, and clones answer frames either way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Handshake {
    /// Not known yet: the next ENQ is a probe, and silence to it is an answer too.
    Probe,
    /// The PLC answers ENQ: ENQ opens the conversation, and opens it again after a failure.
    Enq,
    /// The PLC left the probe unanswered: frames go without ENQ. Silence to a frame makes the
    /// next request probe again.
    Skip,
}

/// An FX PLC on some transport.
pub struct Driver {
    info: DeviceInfo,
    space: FxSpace,
    line: SharedLine,
    mode: Mode,
    /// The line's speed and character format, which the timeouts and pauses follow.
    serial: LineSettings,
    /// Added to every timeout: a device server's network.
    allowance: Duration,
    /// The URL's `timeout=`, when given: it replaces the computed timeout. With the text
    /// the user wrote, which messages quote.
    timeout: Option<Duration>,
    timeout_given: Option<String>,
    retries: u32,
    requests: u64,
    /// Frames resent after a NAK, a bad sum, noise or a reply that did not fit.
    pub resent: u64,
    /// Characters dropped while waiting for the line to be quiet (late replies, noise).
    pub dropped: u64,
    /// The simulated PLC behind an in-process `sim-fx:` device (its CPU: `sim program`,
    /// `sim cpu`), reached by the shell through [`Device::family_ops`].
    pub sim: Option<Plc>,
}

impl Driver {
    /// A programming-port driver on `line`.
    pub fn port(line: SharedLine, model: &'static Model, info: DeviceInfo) -> Driver {
        Driver::new(
            line,
            FxSpace::new(model, Proto::Port),
            Mode::Port { synced: false, handshake: Handshake::Probe },
            info,
        )
    }

    /// A computer-link driver on `line`.
    pub fn link(
        line: SharedLine,
        model: &'static Model,
        header: Header,
        settings: Settings,
        info: DeviceInfo,
    ) -> Driver {
        Driver::new(line, FxSpace::new(model, Proto::Link), Mode::Link { header, settings }, info)
    }

    fn new(line: SharedLine, space: FxSpace, mode: Mode, info: DeviceInfo) -> Driver {
        Driver {
            info,
            space,
            line,
            mode,
            serial: DEFAULT_LINE,
            allowance: Duration::ZERO,
            timeout: None,
            timeout_given: None,
            retries: DEFAULT_RETRIES,
            requests: 0,
            resent: 0,
            dropped: 0,
            sim: None,
        }
    }

    /// Times the driver by its line: `serial` is the line's speed and character format;
    /// `networked`, a line through a device server (its delay is added to every timeout).
    pub fn on_line(mut self, serial: LineSettings, networked: bool) -> Driver {
        self.serial = serial;
        self.allowance = if networked { NETWORK_ALLOWANCE } else { Duration::ZERO };
        self
    }

    /// The message wait (link only): the wait digit 0H–FH in 10 ms steps (seed 004:
    /// "等待延时为0-150毫秒，以十六进制0H-FH表示").
    fn wait(&self) -> Duration {
        match &self.mode {
            Mode::Link { header, .. } => Duration::from_millis(10 * u64::from(header.wait)),
            Mode::Port { .. } => Duration::ZERO,
        }
    }

    /// The reply timeout of a request of `req` characters answered by `reply`: both frames'
    /// time on the wire at the line's speed, the message wait and the PLC's turnaround
    /// ([`TURNAROUND`], and a device server's delay) — or the URL's `timeout=`.
    fn timeout_for(&self, req: usize, reply: usize) -> Duration {
        self.timeout.unwrap_or_else(|| self.serial.time_of(req + reply) + self.wait() + TURNAROUND + self.allowance)
    }

    /// `543 ms (281 characters at 9600 7E1: 293 ms on the wire, …)`: the timeout and where it
    /// comes from, for messages; a timeout the user set is quoted as given
    /// (`250 ms (timeout=250ms)`, `0.5 ms (timeout=0.5)`).
    fn timeout_text(&self, req: usize, reply: usize) -> String {
        if let (Some(t), Some(given)) = (self.timeout, &self.timeout_given) {
            return format!("{} (timeout={given})", millis_text(t));
        }
        let t = self.timeout_for(req, reply).as_millis();
        let mut parts = vec![format!(
            "{} characters at {}: {} ms on the wire",
            req + reply,
            self.serial,
            self.serial.time_of(req + reply).as_millis()
        )];
        if !self.wait().is_zero() {
            parts.push(format!("message wait {} ms", self.wait().as_millis()));
        }
        parts.push(format!("{} ms for the PLC to answer", TURNAROUND.as_millis()));
        if !self.allowance.is_zero() {
            parts.push(format!("{} ms for the device server", self.allowance.as_millis()));
        }
        format!("{t} ms ({})", parts.join(", "))
    }

    /// The quiet awaited before a request: a few character times.
    fn gap(&self) -> Duration {
        self.serial.time_of(4).clamp(GAP_MIN, GAP_MAX)
    }

    /// The quiet awaited before a resend: at least the longer frame's time on the wire.
    fn resend_gap(&self, req: usize, reply: usize) -> Duration {
        self.serial.time_of(req.max(reply)).max(RESEND_MIN).max(self.gap())
    }

    /// How long a line may keep sending before it counts as busy: the longest reply, and the
    /// PLC's turnaround.
    fn busy_limit(&self) -> Duration {
        self.serial.time_of(LONGEST_REPLY) + TURNAROUND + self.allowance
    }

    /// Waits until the line has been quiet for `gap`, dropping what arrives; a line still
    /// sending after `limit` is reported (another master, or a device sending on its own).
    fn quiet(&mut self, t: &mut dyn Transport, gap: Duration, limit: Duration, what: &str) -> Result<usize> {
        let start = Instant::now();
        let n = t.settle(gap, limit).map_err(|e| self.io_err(e))?;
        self.dropped += n as u64;
        if n > 0 && start.elapsed() >= limit {
            return Err(Error::link(format!(
                "the line {} did not go quiet before {what}: {n} characters arrived in {} ms",
                self.line.name,
                limit.as_millis()
            ))
            .hint(match &self.mode {
                Mode::Port { .. } => "only one program may talk to the programming port: close GX Developer, an HMI or a terminal on it; check the cable for noise",
                Mode::Link { .. } => "plcsh must be the only master on the computer link: stop other programs polling it; check the cable for noise and the RS-485 termination",
            }));
        }
        Ok(n)
    }

    /// Reads what arrives until `len` says the reply is complete, or the deadline passes.
    /// Bytes before the first character that can start a reply (STX, ACK, NAK) are noise, set
    /// aside: a burst of 00H (a character with a parity or framing error) or the tail of an
    /// earlier frame is neither a reply nor a NAK.
    fn collect(
        t: &mut dyn Transport,
        deadline: Instant,
        len: &dyn Fn(&[u8]) -> Option<usize>,
    ) -> std::io::Result<Heard> {
        let mut heard = Heard::default();
        let mut buf = [0u8; 256];
        loop {
            if !heard.frame.is_empty() {
                if let Some(n) = len(&heard.frame) {
                    heard.frame.truncate(n);
                    heard.complete = true;
                    return Ok(heard);
                }
            }
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return Ok(heard);
            }
            let k = t.recv(&mut buf, left)?;
            if k == 0 {
                return Ok(heard);
            }
            for &b in &buf[..k] {
                if heard.frame.is_empty() && !fxlink::reply_start(b) {
                    heard.noise.push(b);
                } else {
                    heard.frame.push(b);
                }
            }
        }
    }

    fn io_err(&self, e: std::io::Error) -> Error {
        Error::link(format!("serial I/O on {} failed", self.line.name)).cause(e)
    }

    /// One frame on the line and its reply (one attempt). First the line must be quiet — a
    /// few character times before a first attempt, at least the frame time before a resend —
    /// so that nothing left on it (a late reply, a tail of noise) is read as this request's
    /// reply; then the frame goes out and the reply is read within the request's timeout,
    /// noise in front of it set aside. After silence the line must stay quiet for one more
    /// timeout: a late reply is dropped there, never taken for the next request's.
    fn exchange(&mut self, frame: &[u8], expect: Expect, resend: bool, what: &str) -> Result<Got> {
        let line = self.line.clone();
        let mut guard = line.transport.lock().unwrap_or_else(|p| p.into_inner());
        let t = guard.as_mut();
        let gap = if resend { self.resend_gap(frame.len(), expect.chars()) } else { self.gap() };
        self.quiet(t, gap, gap + self.busy_limit(), what)?;
        let proto = if matches!(self.mode, Mode::Port { .. }) { Wire::FxPort } else { Wire::FxLink };
        trace::frame_proto(&line.name, proto, Dir::Sent, frame);
        t.send(frame).map_err(|e| self.io_err(e))?;
        let timeout = self.timeout_for(frame.len(), expect.chars());
        let deadline = Instant::now() + timeout;
        let heard = match &self.mode {
            Mode::Port { .. } => Self::collect(t, deadline, &port_len),
            Mode::Link { settings, .. } => {
                let s = *settings;
                Self::collect(t, deadline, &move |f: &[u8]| {
                    fxlink::reply_len(f, s).or((f.len() >= FRAME_CAP).then_some(f.len()))
                })
            }
        }
        .map_err(|e| self.io_err(e))?;
        if !heard.noise.is_empty() || !heard.frame.is_empty() {
            trace::frame_proto(
                &line.name,
                proto,
                Dir::Received,
                &[heard.noise.as_slice(), heard.frame.as_slice()].concat(),
            );
        }
        if heard.frame.is_empty() && heard.noise.is_empty() {
            let late = timeout.min(LATE_MAX);
            let late = self.quiet(t, late, 2 * late + self.serial.time_of(LONGEST_REPLY), what)?;
            return Ok(Got::Silent { late });
        }
        Ok(match &self.mode {
            _ if heard.frame.is_empty() => Got::Noise(heard.noise),
            _ if !heard.complete => Got::Partial(heard.frame),
            Mode::Port { .. } => classify_port(&heard.frame, expect),
            Mode::Link { header, settings } => classify_link(&heard.frame, *header, *settings, expect),
        })
    }

    /// The ENQ/ACK handshake (programming port; seed 004: "通过ENQ、ACK和NAK上位机协调与PLC的通信
    /// 应答"). Only ACK opens the conversation; a NAK is a NAK character in reply, noise is
    /// reported as noise. The first ENQ is a probe: a PLC that leaves it unanswered (and
    /// nothing comes late either) is talked to without ENQ from then on. `after_failure`: the
    /// line just carried a failed exchange, so the first ENQ waits as a resend does.
    fn enq(&mut self, after_failure: bool) -> Result<()> {
        let mut seen = Vec::new();
        let ack = Expect::Ack { chars: 1 };
        let probing = matches!(self.mode, Mode::Port { handshake: Handshake::Probe, .. });
        for attempt in 0..=self.retries {
            match self.exchange(&[ENQ], ack, after_failure || attempt > 0, "ENQ")? {
                Got::Ack => {
                    self.mode = Mode::Port { synced: true, handshake: Handshake::Enq };
                    return Ok(());
                }
                Got::Silent { late: 0 } if probing && attempt == 0 => {
                    self.mode = Mode::Port { synced: true, handshake: Handshake::Skip };
                    return Ok(());
                }
                Got::Silent { late } => {
                    let name = &self.line.name;
                    return Err(Error::link(format!(
                        "no ACK to ENQ on {name} within {}{}",
                        self.timeout_text(1, 1),
                        late_text(late)
                    ))
                    .hint(if late > 0 { self.late_hint(1, 1) } else { self.silence_hint() }));
                }
                got => seen.push(got),
            }
        }
        if seen.iter().all(|g| *g == Got::Nak(None)) {
            return Err(Error::link(format!(
                "the PLC answered ENQ with NAK {} times on {}",
                seen.len(),
                self.line.name
            ))
            .hint("another program may be talking to the programming port"));
        }
        Err(self.failure("ENQ", &seen, (1, 1)))
    }

    /// One exchange with retries: returns data (reads) or nothing (writes). A read succeeds
    /// only on a data frame that fits it, a write only on ACK from the addressed station.
    fn transact(&mut self, frame: &[u8], expect: Expect, what: &str) -> Result<Vec<u8>> {
        let mut seen: Vec<Got> = Vec::new();
        for attempt in 0..=self.retries {
            if attempt > 0 {
                self.resent += 1;
            }
            if let Mode::Port { synced: false, handshake } = self.mode {
                if handshake == Handshake::Skip {
                    self.mode = Mode::Port { synced: true, handshake };
                } else {
                    self.enq(attempt > 0)?;
                }
            }
            self.requests += 1;
            let got = self.exchange(frame, expect, attempt > 0, what)?;
            match (got, expect) {
                (Got::Data(d), Expect::Data { .. }) => return Ok(d),
                (Got::Ack, Expect::Ack { .. }) => return Ok(Vec::new()),
                (Got::Silent { late }, _) => {
                    self.desync();
                    let from = match &self.mode {
                        Mode::Link { header, .. } => format!(" (station {})", header.station),
                        Mode::Port { handshake: Handshake::Skip, .. } => {
                            // Probe again next time: the PLC may want ENQ after all.
                            self.mode = Mode::Port { synced: false, handshake: Handshake::Probe };
                            " (sent without ENQ: it answered no ENQ either)".to_string()
                        }
                        Mode::Port { .. } => String::new(),
                    };
                    return Err(Error::link(format!(
                        "no reply to {what}{from} on {} within {}{}",
                        self.line.name,
                        self.timeout_text(frame.len(), expect.chars()),
                        late_text(late)
                    ))
                    .hint(if late > 0 {
                        self.late_hint(frame.len(), expect.chars())
                    } else {
                        self.silence_hint()
                    }));
                }
                (Got::Nak(code), _) => {
                    seen.push(Got::Nak(code));
                    // On the link only a NAK that a resend can cure is retried.
                    if matches!(code, Some(c) if c != fxlink::code::SUM && c != fxlink::code::PROTOCOL) {
                        break;
                    }
                }
                (got, _) => {
                    self.desync();
                    seen.push(got);
                }
            }
        }
        Err(self.failure(what, &seen, (frame.len(), expect.chars())))
    }

    /// The programming port opens the conversation again with ENQ after a failed exchange.
    fn desync(&mut self) {
        if let Mode::Port { handshake, .. } = self.mode {
            self.mode = Mode::Port { synced: false, handshake };
        }
    }

    /// The error after every attempt failed, from the last one, listing what each got;
    /// `sizes`: the request's and the reply's characters.
    fn failure(&self, what: &str, seen: &[Got], sizes: (usize, usize)) -> Error {
        let name = &self.line.name;
        let mut labels: Vec<(String, usize)> = Vec::new();
        for g in seen {
            match labels.iter_mut().find(|(l, _)| *l == g.label()) {
                Some((_, n)) => *n += 1,
                None => labels.push((g.label(), 1)),
            }
        }
        let tries = match (seen.len(), labels.len()) {
            (1, _) => "1 attempt".to_string(),
            (n, 1) => format!("{n} attempts"),
            (n, _) => format!(
                "{n} attempts: {}",
                labels.iter().map(|(l, k)| format!("{l} ×{k}")).collect::<Vec<_>>().join(", ")
            ),
        };
        let who = match &self.mode {
            Mode::Link { header, .. } => format!("station {}", header.station),
            Mode::Port { .. } => "the PLC".to_string(),
        };
        match seen.last() {
            Some(Got::Nak(Some(c))) => Error::new(
                ErrorKind::Refused,
                format!("{who} answered NAK {c:02X}H to {what} on {name}: {}", fxlink::nak_text(*c)),
            )
            .hint(match *c {
                fxlink::code::AREA => "check the operand against the model (`help OPERAND`)",
                fxlink::code::PC_NUMBER => "the PC number of an FX is FF (pc=FF)",
                fxlink::code::SUM | fxlink::code::PROTOCOL => "check the sum check setting (sum=, D8120) and the line's noise",
                _ => "check the PLC's computer-link settings (D8120, D8121)",
            }),
            Some(Got::Nak(None)) => Error::new(
                ErrorKind::Refused,
                format!("the PLC answered NAK to {what} on {name} ({tries}): it refuses a frame with a wrong sum check or an address where it has no device"),
            )
            .hint(if self.space.model.extended {
                "check the operand against the model (`help OPERAND`) and the line's noise; a PLC without the E-commands (E00/E10/E7/E8) answers them NAK: open it as model=FX2N"
            } else {
                "check the operand against the model (`help OPERAND`) and the line's noise"
            }),
            Some(Got::BadSum(m)) => Error::link(format!("bad reply to {what} on {name} ({tries}): {m}"))
                .hint(match &self.mode {
                    Mode::Port { .. } => "noise on the line or a wrong baud rate/parity (the port runs 7E1)",
                    Mode::Link { .. } => "noise on the line, or a baud rate or character format that differs from the PLC's (D8120)",
                }),
            Some(Got::Noise(b)) => Error::link(format!(
                "noise on the line {name} instead of a reply to {what} ({tries}): {} — characters that cannot start a reply (00H is what a serial port delivers for a character with a parity or framing error)",
                show(b)
            ))
            .hint(format!(
                "check the cable's shield and ground, the converter's power and the RS-422/485 termination, and that the PLC runs {} (a different baud rate or format also reads as noise)",
                self.serial
            )),
            Some(Got::Partial(p)) => Error::link(format!(
                "incomplete reply to {what} on {name} within {} ({tries}): only {} came",
                self.timeout_text(sizes.0, sizes.1),
                show(p)
            ))
            .hint(format!("check the baud rate ({}), or raise the timeout (timeout= in the URL)", self.serial)),
            Some(Got::Other(m)) => Error::link(format!("{who} answered {what} on {name} with something else ({tries}): {m}"))
                .hint(match &self.mode {
                    Mode::Port { .. } => "only one program may talk to the programming port: close GX Developer, an HMI or a terminal on it".to_string(),
                    Mode::Link { header, .. } => format!(
                        "check that no other station is set to station {} (D8121) and that no other program polls this line; a reply that comes after the timeout belongs to an earlier request (raise timeout=)",
                        header.station
                    ),
                }),
            _ => Error::link(format!("no usable reply to {what} on {name} ({tries})")),
        }
    }

    fn late_hint(&self, req: usize, reply: usize) -> String {
        let t = self.timeout_for(req, reply);
        format!(
            "the PLC answers later than {}: raise the timeout (timeout={} in the URL), or check its scan time (D8012)",
            millis_text(t),
            millis_text(2 * t).replace(' ', "")
        )
    }

    fn silence_hint(&self) -> String {
        match &self.mode {
            Mode::Port { .. } => {
                format!("check the cable, that this is the programming port, and that it runs {}", self.serial)
            }
            Mode::Link { header, .. } => format!(
                "check station {} (the PLC's D8121), PC number FF, the baud rate and format (D8120), and the sum check setting",
                header.station
            ),
        }
    }

    fn settings(&self) -> Settings {
        match &self.mode {
            Mode::Link { settings, .. } => *settings,
            Mode::Port { .. } => Settings::default(),
        }
    }

    fn link_frame(&self, cmd: &Cmd) -> Vec<u8> {
        match &self.mode {
            Mode::Link { header, settings } => fxlink::encode_request(*header, cmd, *settings),
            Mode::Port { .. } => unreachable!("link frames are built in link mode only"),
        }
    }

    // ----- programming port -----

    fn port_read(&mut self, ops: &[FxOperand]) -> Result<Vec<Value>> {
        let table = Table::of(self.space.model);
        let regions = port::regions(table);
        let places: Vec<port::Place> = ops
            .iter()
            .map(|o| {
                port::place(table, o)
                    .ok_or_else(|| Error::new(ErrorKind::Range, "past the address table").operand(o.canonical()))
            })
            .collect::<Result<_>>()?;
        let mut order: Vec<usize> = (0..ops.len()).collect();
        order.sort_by_key(|&i| places[i].addr);
        // Spans: [start, end) within one region, at most 64 bytes.
        let mut spans: Vec<(u16, u16)> = Vec::new();
        let mut span_of = vec![0usize; ops.len()];
        // A gap is read along only where the model has devices (an FX1S lacks C32–C234).
        let space = self.space;
        let byte_has_device = |addr: u16| {
            port::region_of(&regions, addr).is_some_and(|r| {
                let off = addr - r.start;
                match off.checked_div(r.unit) {
                    Some(k) => space.exists(r.area, r.first + k),
                    None => (0..8).any(|b| space.exists(r.area, r.first + 8 * off + b)),
                }
            })
        };
        for &i in &order {
            let p = places[i];
            let region = port::region_of(&regions, p.addr).map(|r| r.start);
            let merged = spans.last_mut().filter(|(s, e)| {
                port::region_of(&regions, *s).map(|r| r.start) == region
                    && (p.addr + p.len - *s) as usize <= port::MAX_BYTES
                    && (*e..p.addr).all(byte_has_device)
            });
            match merged {
                Some((_, e)) => *e = (*e).max(p.addr + p.len),
                None => spans.push((p.addr, p.addr + p.len)),
            }
            span_of[i] = spans.len() - 1;
        }
        let mut data = Vec::with_capacity(spans.len());
        for (s, e) in &spans {
            let count = (e - s) as u8;
            let req = Request::Read { table, addr: *s, count };
            let expect = Expect::Data { chars: req.reply_len(), data: count as usize };
            let kind = if table == Table::Extended { "an E00 read" } else { "a read" };
            let bytes = self.transact(&req.encode(), expect, &format!("{kind} of {count} bytes at {s:04X}H"))?;
            data.push(bytes);
        }
        Ok(ops
            .iter()
            .enumerate()
            .map(|(i, o)| {
                let p = places[i];
                let bytes = &data[span_of[i]][(p.addr - spans[span_of[i]].0) as usize..][..p.len as usize];
                let raw = bytes.iter().rev().fold(0u64, |a, b| a << 8 | *b as u64);
                let bits = o.bits();
                let v = (raw >> p.bit) & ((1u64 << bits) - 1);
                o.view.decode(v as u32)
            })
            .collect())
    }

    fn port_write(&mut self, items: &[(FxOperand, Value)]) -> Result<()> {
        // Frames in order; adjacent byte writes merge.
        let table = Table::of(self.space.model);
        let mut frames: Vec<(Request, String)> = Vec::new();
        for (o, v) in items {
            let raw = o.view.encode(v) as u64;
            let p = port::place(table, o)
                .ok_or_else(|| Error::new(ErrorKind::Range, "past the address table").operand(o.canonical()))?;
            match o.width {
                Width::Bit => {
                    let addr = port::force_address(table, o.area, o.index).ok_or_else(|| read_only(o))?;
                    frames.push((
                        Request::Force { table, on: raw != 0, addr },
                        format!("forcing {} {}", o.canonical(), on_off(raw)),
                    ));
                }
                Width::Group(n) if p.bit == 0 && (4 * n) % 8 == 0 => {
                    let data: Vec<u8> = (0..p.len).map(|i| (raw >> (8 * i)) as u8).collect();
                    push_write(&mut frames, table, p.addr, data, o);
                }
                Width::Group(n) => {
                    for i in 0..4 * n as u16 {
                        let addr = port::force_address(table, o.area, o.index + i).ok_or_else(|| read_only(o))?;
                        let bit = raw >> i & 1;
                        frames.push((
                            Request::Force { table, on: bit != 0, addr },
                            format!("forcing {} bit {i}", o.canonical()),
                        ));
                    }
                }
                Width::Word | Width::Pair => {
                    let data: Vec<u8> = (0..p.len).map(|i| (raw >> (8 * i)) as u8).collect();
                    push_write(&mut frames, table, p.addr, data, o);
                }
            }
        }
        for (req, what) in frames {
            self.transact(&req.encode(), Expect::Ack { chars: 1 }, &what)?;
        }
        Ok(())
    }

    // ----- computer link -----

    fn link_read(&mut self, ops: &[FxOperand]) -> Result<Vec<Value>> {
        // Classes: bit reads (BR) per area, word reads (WR) per area, 32-bit counters apart.
        #[derive(PartialEq, Eq, Clone, Copy, Hash, PartialOrd, Ord)]
        enum Class {
            Bits(Area),
            Words(Area),
            Long,
        }
        let class = |o: &FxOperand| match o.width {
            Width::Bit | Width::Group(_) => Class::Bits(o.area),
            Width::Pair if o.area == Area::CN => Class::Long,
            _ if o.area == Area::CN && o.index >= CN32_FIRST => Class::Long,
            _ => Class::Words(o.area),
        };
        let mut order: Vec<usize> = (0..ops.len()).collect();
        order.sort_by_key(|&i| (class(&ops[i]), ops[i].index));
        let mut spans: Vec<(Class, u16, u16)> = Vec::new();
        let mut span_of = vec![0usize; ops.len()];
        for &i in &order {
            let o = &ops[i];
            let c = class(o);
            let max = match c {
                Class::Bits(_) => fxlink::MAX_BITS,
                Class::Words(_) => fxlink::MAX_WORDS,
                Class::Long => fxlink::MAX_WORDS / 2,
            } as u32;
            let end = o.index + o.span();
            let space = self.space;
            let gap_ok = |from: u16| (from..o.index).all(|i| space.exists(o.area, i));
            match spans.last_mut().filter(|(k, s, e)| *k == c && (end - *s) as u32 <= max && gap_ok(*e)) {
                Some((_, _, e)) => *e = (*e).max(end),
                None => spans.push((c, o.index, end)),
            }
            span_of[i] = spans.len() - 1;
        }
        let mut data: Vec<Vec<u32>> = Vec::with_capacity(spans.len());
        for (c, s, e) in &spans {
            let count = (e - s) as usize;
            let (area, bits) = match c {
                Class::Bits(a) => (*a, true),
                Class::Words(a) => (*a, false),
                Class::Long => (Area::CN, false),
            };
            let dev = Dev { area, index: *s };
            let cmd = if bits { Cmd::Br { dev, count } } else { Cmd::Wr { dev, count } };
            let what =
                format!("{} of {count} point(s) from {}", if bits { "BR" } else { "WR" }, dev.text(self.settings()));
            let frame = self.link_frame(&cmd);
            let chars = if bits { count } else { count * dev.unit() };
            let expect = Expect::Data { chars: fxlink::data_reply_chars(chars, self.settings()), data: chars };
            let d = self.transact(&frame, expect, &what)?;
            let values = if bits {
                if d.len() != count || !d.iter().all(|c| *c == b'0' || *c == b'1') {
                    return Err(Error::link(format!("bad reply to {what}: {} characters of 0/1 expected", count)));
                }
                d.iter().map(|c| (*c == b'1') as u32).collect()
            } else {
                let v = fxlink::parse_values(&d, dev.unit()).filter(|v| v.len() == count);
                v.ok_or_else(|| Error::link(format!("bad reply to {what}: {count} hex values expected")))?
            };
            data.push(values);
        }
        Ok(ops
            .iter()
            .enumerate()
            .map(|(i, o)| {
                let span = &spans[span_of[i]];
                let vals = &data[span_of[i]][(o.index - span.1) as usize..];
                let raw: u64 = match o.width {
                    Width::Bit => vals[0] as u64,
                    Width::Group(n) => (0..4 * n as usize).fold(0u64, |a, k| a | (vals[k] as u64) << k),
                    Width::Pair if o.area == Area::D => vals[0] as u64 | (vals[1] as u64) << 16,
                    _ => vals[0] as u64,
                };
                o.view.decode(raw as u32)
            })
            .collect())
    }

    fn link_write(&mut self, items: &[(FxOperand, Value)]) -> Result<()> {
        let mut cmds: Vec<Cmd> = Vec::new();
        let singles =
            items.iter().all(|(o, _)| o.width == Width::Word && !(o.area == Area::CN && o.index >= CN32_FIRST));
        let runs =
            items.windows(2).filter(|w| !(w[1].0.area == w[0].0.area && w[1].0.index == w[0].0.index + 1)).count() + 1;
        if singles && items.len() > 1 && runs > 1 {
            for chunk in items.chunks(fxlink::MAX_WT) {
                let list = chunk
                    .iter()
                    .map(|(o, v)| (Dev { area: o.area, index: o.index }, o.view.encode(v) & 0xFFFF))
                    .collect();
                cmds.push(Cmd::Wt { items: list });
            }
        } else {
            for (o, v) in items {
                let raw = o.view.encode(v);
                let dev = Dev { area: o.area, index: o.index };
                let next = match o.width {
                    Width::Bit => Cmd::Bw { dev, bits: vec![raw != 0] },
                    Width::Group(n) => Cmd::Bw { dev, bits: (0..4 * n as u32).map(|k| raw >> k & 1 != 0).collect() },
                    Width::Pair if o.area == Area::D => Cmd::Ww { dev, values: vec![raw & 0xFFFF, raw >> 16] },
                    _ => Cmd::Ww { dev, values: vec![raw] },
                };
                merge_link(&mut cmds, next);
            }
        }
        let st = self.settings();
        for c in cmds {
            let what = match &c {
                Cmd::Bw { dev, bits } => format!("BW of {} point(s) at {}", bits.len(), dev.text(st)),
                Cmd::Ww { dev, values } => format!("WW of {} value(s) at {}", values.len(), dev.text(st)),
                Cmd::Wt { items } => format!("WT of {} value(s)", items.len()),
                _ => String::new(),
            };
            let frame = self.link_frame(&c);
            self.transact(&frame, Expect::Ack { chars: fxlink::ack_chars(st) }, &what)?;
        }
        Ok(())
    }
}

fn on_off(raw: u64) -> &'static str {
    if raw != 0 {
        "ON"
    } else {
        "OFF"
    }
}

fn read_only(o: &FxOperand) -> Error {
    Error::unsupported(format!("{} ({}) cannot be set", o.canonical(), o.area.spec().meaning)).operand(o.canonical())
}

/// A write to a special device the CPU rewrites every scan: a real PLC ignores it, so it is
/// refused here with what to do instead.
fn driven_by_plc(o: &FxOperand, index: u16) -> Error {
    let name = format!("{}{index}", o.area.name());
    let what = super::operand::special_meaning(o.area, index).unwrap_or("a special device");
    let hint = if o.area == Area::M && index <= 8003 {
        "RUN/STOP is the PLC's switch: on the simulator `sim cpu stop` / `sim cpu run`"
    } else {
        "the PLC sets it every scan; read it, or use an ordinary M or D for your own flags"
    };
    Error::unsupported(format!("{name} — {what} — is driven by the PLC: a write would be ignored"))
        .operand(o.canonical())
        .hint(hint)
}

fn push_write(frames: &mut Vec<(Request, String)>, table: Table, addr: u16, data: Vec<u8>, o: &FxOperand) {
    if let Some((Request::Write { addr: a, data: d, .. }, what)) = frames.last_mut() {
        if *a as usize + d.len() == addr as usize && d.len() + data.len() <= port::MAX_BYTES {
            d.extend(data);
            *what = format!("{} of {} bytes at {a:04X}H", write_kind(table), d.len());
            return;
        }
    }
    frames.push((Request::Write { table, addr, data }, format!("{} of {}", write_kind(table), o.canonical())));
}

fn write_kind(table: Table) -> &'static str {
    match table {
        Table::Classic => "a write",
        Table::Extended => "an E10 write",
    }
}

/// Appends `next` to the last command when it continues it on the next devices.
fn merge_link(cmds: &mut Vec<Cmd>, next: Cmd) {
    match (cmds.last_mut(), &next) {
        (Some(Cmd::Bw { dev: d0, bits: b0 }), Cmd::Bw { dev, bits })
            if d0.area == dev.area
                && d0.index as usize + b0.len() == dev.index as usize
                && b0.len() + bits.len() <= 160 =>
        {
            b0.extend(bits);
        }
        (Some(Cmd::Ww { dev: d0, values: v0 }), Cmd::Ww { dev, values })
            if d0.area == dev.area
                && d0.unit() == dev.unit()
                && d0.index as usize + v0.len() == dev.index as usize
                && v0.len() + values.len() <= fxlink::MAX_WORDS =>
        {
            v0.extend(values);
        }
        _ => cmds.push(next),
    }
}

impl Device for Driver {
    fn info(&self) -> &DeviceInfo {
        &self.info
    }

    fn operands(&self) -> &dyn OperandSpace {
        &self.space
    }

    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        let fx: Vec<FxOperand> = ops.iter().map(|o| FxOperand::from_key(o.key)).collect();
        for o in &fx {
            self.space.check(o)?;
        }
        if fx.is_empty() {
            return Ok(Vec::new());
        }
        match self.mode {
            Mode::Port { .. } => self.port_read(&fx),
            Mode::Link { .. } => self.link_read(&fx),
        }
    }

    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        let fx: Vec<(FxOperand, Value)> = items.iter().map(|(o, v)| (FxOperand::from_key(o.key), *v)).collect();
        // Everything is checked before anything is sent.
        for (o, _) in &fx {
            self.space.check(o)?;
            if !o.area.spec().writable {
                return Err(read_only(o));
            }
            if let Some(i) = (o.index..o.index.saturating_add(o.span())).find(|i| system_driven(o.area, *i)) {
                return Err(driven_by_plc(o, i));
            }
        }
        if fx.is_empty() {
            return Ok(());
        }
        match self.mode {
            Mode::Port { .. } => self.port_write(&fx),
            Mode::Link { .. } => self.link_write(&fx),
        }
    }

    fn requests(&self) -> u64 {
        self.requests
    }

    fn family_ops(&mut self) -> Option<&mut dyn std::any::Any> {
        // Only a simulator has operations of its own (its CPU); a real FX has none here.
        self.sim.is_some().then_some(self as &mut dyn std::any::Any)
    }

    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        match key {
            "timeout" if value == "auto" => (self.timeout, self.timeout_given) = (None, None),
            "timeout" => {
                (self.timeout, self.timeout_given) = (Some(parse_timeout(value)?), Some(value.trim().to_string()))
            }
            "retries" => {
                self.retries = value
                    .parse()
                    .ok()
                    .filter(|r| *r <= 10)
                    .ok_or_else(|| Error::usage(format!("retries `{value}` must be 0–10")))?
            }
            _ => {
                return Err(Error::usage(format!("fx devices have no option `{key}`")).hint("options: timeout, retries"))
            }
        }
        Ok(())
    }
}

fn parse_timeout(v: &str) -> Result<Duration> {
    crate::core::literal::parse_timeout(v).map_err(Error::usage)
}

fn model_of(u: &DeviceUrl, default: Option<&str>) -> Result<&'static Model> {
    let name = u.param("model").or(default).unwrap_or("FX2N");
    Model::find(name).ok_or_else(|| {
        Error::usage(format!("unknown FX model `{name}` in {}", u.text)).hint(format!("models: {}", Model::names()))
    })
}

fn hex_param(u: &DeviceUrl, key: &str, default: u8, max: u8) -> Result<u8> {
    match u.param(key) {
        None => Ok(default),
        Some(v) => {
            let n = if key == "pc" { u8::from_str_radix(v, 16).ok() } else { v.parse::<u8>().ok() };
            n.filter(|n| *n <= max).ok_or_else(|| {
                Error::usage(format!("`{key}={v}` in {} is out of range", u.text)).hint(match key {
                    "station" => "station numbers are 0–31".to_string(),
                    "wait" => "the wait is 0–15 (×10 ms, 0–150 ms)".to_string(),
                    _ => "the PC number is two hex digits, FF for FX".to_string(),
                })
            })
        }
    }
}

fn link_settings(u: &DeviceUrl) -> Result<Settings> {
    let sum = match u.param("sum") {
        None | Some("1") | Some("on") | Some("true") => true,
        Some("0") | Some("off") | Some("false") => false,
        Some(v) => return Err(Error::usage(format!("`sum={v}` in {} is not 0 or 1", u.text))),
    };
    let format4 = match u.param("format") {
        None | Some("1") => false,
        Some("4") => true,
        Some(v) => return Err(Error::usage(format!("`format={v}` in {}: formats 1 and 4 are supported", u.text))),
    };
    let decimal_xy = match u.param("xy") {
        None | Some("octal") => false,
        Some("decimal") => true,
        Some(v) => return Err(Error::usage(format!("`xy={v}` in {}: octal or decimal", u.text))),
    };
    Ok(Settings { sum, format4, decimal_xy })
}

fn finish(mut d: Driver, u: &DeviceUrl) -> Result<Box<dyn Device>> {
    for key in ["timeout", "retries"] {
        if let Some(v) = u.param(key) {
            d.set_option(key, v)?;
        }
    }
    Ok(Box::new(d))
}

/// The URL parameters of the programming port (`fx:`), the computer link (`fxlink:`) and the
/// simulator (`sim-fx:`).
pub const PORT_PARAMS: &[&str] = &["baud", "model", "timeout", "retries"];
pub const LINK_PARAMS: &[&str] =
    &["station", "pc", "wait", "baud", "bits", "parity", "stop", "sum", "format", "xy", "model", "timeout", "retries"];
pub const SIM_PARAMS: &[&str] =
    &["model", "protocol", "station", "pc", "wait", "sum", "format", "xy", "share", "timeout", "retries", "program"];

/// Opens `fx:PORT?baud=9600&model=FX2N&timeout=500ms&retries=3`: the programming port, 7E1.
pub fn open_port(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(PORT_PARAMS)?;
    let carrier = Carrier::from_url(u, "fx:COM6 or fx:/dev/ttyUSB0")?;
    let model = model_of(u, None)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(9600);
    if baud == 0 {
        return Err(Error::usage(format!("`baud=0` in {}: the baud rate must be positive", u.text)));
    }
    let settings = LineSettings { baud, data_bits: 7, parity: Parity::Even, stop_bits: 1 };
    let line = lines::shared_serial(&carrier, settings)?;
    let info = DeviceInfo {
        family: "fx",
        model: format!("{} (programming port)", model.name),
        link: format!("{} ({settings})", carrier.key()),
        simulated: false,
    };
    finish(Driver::port(line, model, info).on_line(settings, carrier.networked()), u)
}

/// Opens `fxlink:PORT?station=0&pc=FF&wait=0&baud=9600&bits=7&parity=e&stop=1&sum=1&format=1`.
pub fn open_link(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(LINK_PARAMS)?;
    let carrier = Carrier::from_url(u, "fxlink:COM7?station=0 or fxlink:/dev/ttyUSB0?station=0")?;
    let model = model_of(u, None)?;
    let header = Header {
        station: hex_param(u, "station", 0, 31)?,
        pc: hex_param(u, "pc", 0xFF, 0xFF)?,
        wait: hex_param(u, "wait", 0, 15)?,
    };
    let settings = link_settings(u)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(9600);
    let bits = u.param_num::<u8>("bits")?.unwrap_or(7);
    let parity = Parity::parse(u.param("parity").unwrap_or("e"));
    let stop = u.param_num::<u8>("stop")?.unwrap_or(1);
    let (Some(parity), true, true, true) = (parity, matches!(bits, 7 | 8), matches!(stop, 1 | 2), baud > 0) else {
        return Err(Error::usage(format!("{}: bits=7|8, parity=e|o|n, stop=1|2, baud above 0", u.text)));
    };
    let line_settings = LineSettings { baud, data_bits: bits, parity, stop_bits: stop };
    let line = lines::shared_serial(&carrier, line_settings)?;
    let info = DeviceInfo {
        family: "fx",
        model: format!("{} (computer link, station {})", model.name, header.station),
        link: format!(
            "{} ({line_settings}, format {}, sum {})",
            carrier.key(),
            if settings.format4 { 4 } else { 1 },
            if settings.sum { "on" } else { "off" }
        ),
        simulated: false,
    };
    finish(Driver::link(line, model, header, settings, info).on_line(line_settings, carrier.networked()), u)
}

fn shared_plcs() -> &'static Mutex<HashMap<String, Weak<Mutex<Memory>>>> {
    static R: OnceLock<Mutex<HashMap<String, Weak<Mutex<Memory>>>>> = OnceLock::new();
    R.get_or_init(|| Mutex::new(HashMap::new()))
}

/// A simulated PLC's memory on `clock`, shared under `share` when given.
pub fn sim_plc(model: &'static Model, share: Option<&str>, clock: &Clock) -> Result<Plc> {
    let fresh = || Arc::new(Mutex::new(Memory::with_clock(model, clock.clone())));
    let Some(name) = share else { return Ok(fresh()) };
    let mut reg = shared_plcs().lock().unwrap_or_else(|p| p.into_inner());
    reg.retain(|_, w| w.strong_count() > 0);
    if let Some(p) = reg.get(name).and_then(Weak::upgrade) {
        let m = p.lock().unwrap_or_else(|e| e.into_inner()).model.name;
        if m != model.name {
            return Err(Error::usage(format!("simulated PLC `{name}` is an {m}, not an {}", model.name)));
        }
        return Ok(p);
    }
    let p = fresh();
    reg.insert(name.to_string(), Arc::downgrade(&p));
    Ok(p)
}

/// Opens `sim-fx:MODEL?protocol=port|link&station=0&sum=1&format=1&share=NAME&program=FILE.il`
/// on the session's clock; `program` loads an FX list into the PLC ([`super::program`]).
pub fn open_sim(u: &DeviceUrl, clock: &Clock) -> Result<Box<dyn Device>> {
    u.expect_params(SIM_PARAMS)?;
    let model = model_of(u, Some(if u.target.is_empty() { "FX2N" } else { &u.target }))?;
    let plc = sim_plc(model, u.param("share"), clock)?;
    if let Some(p) = u.param("program") {
        let text = crate::core::encoding::read_source(p)
            .map_err(|e| Error::io(format!("{}: cannot read {p}: {e}", u.text)))?;
        let loaded = super::program::Loaded::load(&text, p, model)?;
        plc.lock().unwrap_or_else(|e| e.into_inner()).load_program(loaded);
    }
    let sim = plc.clone();
    let link = match u.param("protocol") {
        None | Some("port") => false,
        Some("link") => true,
        Some(p) => return Err(Error::usage(format!("`protocol={p}` in {}: port or link", u.text))),
    };
    let info = |what: &str| DeviceInfo {
        family: "fx",
        model: format!("simulated {} ({what})", model.name),
        link: u.text.clone(),
        simulated: true,
    };
    let d = if link {
        let header = Header {
            station: hex_param(u, "station", 0, 31)?,
            pc: hex_param(u, "pc", 0xFF, 0xFF)?,
            wait: hex_param(u, "wait", 0, 15)?,
        };
        let settings = link_settings(u)?;
        let server: Box<dyn Server> = Box::new(LinkServer::new(header.station, settings));
        let line = lines::private(&u.text, Box::new(SimLink::new(plc, server)));
        Driver::link(line, model, header, settings, info("computer link"))
    } else {
        let line = lines::private(&u.text, Box::new(SimLink::new(plc, Box::new(PortServer::default()))));
        Driver::port(line, model, info("programming port"))
    };
    let mut d = d;
    d.sim = Some(sim);
    finish(d, u)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io;

    fn sim(url: &str) -> Box<dyn Device> {
        open_sim(&DeviceUrl::parse(url).unwrap(), &Clock::stepped()).unwrap_or_else(|e| panic!("{url}: {e}"))
    }

    fn ops(d: &dyn Device, names: &[&str]) -> Vec<Operand> {
        names.iter().flat_map(|n| d.operands().parse(n).unwrap()).collect()
    }

    fn set(d: &mut dyn Device, name: &str, v: i64) {
        let o = ops(d, &[name])[0];
        let v = d.operands().check(&o, Value::Int(v)).unwrap();
        d.write(&[(o, v)]).unwrap();
    }

    fn get(d: &mut dyn Device, name: &str) -> i64 {
        let o = ops(d, &[name]);
        d.read(&o).unwrap()[0].as_i64()
    }

    #[test]
    fn port_and_link_read_and_write_every_kind() {
        for url in ["sim-fx:FX2N", "sim-fx:FX2N?protocol=link", "sim-fx:FX3U"] {
            let mut d = sim(url);
            let d = d.as_mut();
            set(d, "D100", -5);
            assert_eq!(get(d, "D100"), -5, "{url}");
            assert_eq!(get(d, "D100/WORD"), 65531);
            set(d, "D10/DINT", 100_000);
            assert_eq!(get(d, "D10/WORD"), 100_000 & 0xFFFF, "low word first");
            assert_eq!(get(d, "D11"), 1);
            assert_eq!(get(d, "D10/DINT"), 100_000);
            set(d, "D20/REAL", 0);
            set(d, "Y10", 1);
            assert_eq!(get(d, "Y10"), 1);
            assert_eq!(get(d, "K2Y10"), 1);
            set(d, "K4M0/WORD", 0xA5F0);
            assert_eq!(get(d, "M4"), 1);
            assert_eq!(get(d, "M0"), 0);
            assert_eq!(get(d, "K4M0/WORD"), 0xA5F0);
            assert_eq!(get(d, "K1M4"), 0xF, "K1 is 4 bits");
            assert_eq!(get(d, "K3M0"), 0x5F0, "M12–M15 are on, but a K3 group's high bits are zero");
            assert_eq!(get(d, "K4M0"), 0xA5F0 - 0x10000, "a full K4 group is a signed 16-bit value");
            assert_eq!(get(d, "K4M0/DINT"), 0xA5F0, "K4 in a 32-bit operation: high 16 bits zero");
            assert_eq!(get(d, "K8M0"), 0xA5F0, "K8 in 32 bits: M16–M31 are off");
            set(d, "K4M0", -1);
            assert_eq!(get(d, "K4M0/WORD"), 0xFFFF);
            set(d, "K4M0/DINT", 0xA5F0);
            assert_eq!(get(d, "K8M0"), 0xA5F0, "a 32-bit write to K4 writes 16 bits");
            set(d, "K2M3", 0xFF);
            assert_eq!(get(d, "K4M0/WORD"), 0xA5F0 | 0x7F8, "an unaligned group writes exactly its bits");
            set(d, "CN200", -7);
            assert_eq!(get(d, "CN200"), -7);
            set(d, "TN3", 42);
            assert_eq!(get(d, "TN3"), 42);
            assert_eq!(get(d, "M8000"), 1, "RUN");
            assert_eq!(get(d, "D8000"), 200);
            let tc = ops(d, &["TS0"])[0];
            d.write(&[(tc, Value::Bool(true))]).unwrap();
            assert_eq!(get(d, "TS0"), 1);
        }
    }

    #[test]
    fn coils_are_read_only_and_nothing_is_sent() {
        let mut d = sim("sim-fx:FX2N");
        let o = ops(d.as_ref(), &["TC0"])[0];
        let before = d.requests();
        let e = d.write(&[(o, Value::Bool(true))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unsupported);
        assert_eq!(d.requests(), before);
    }

    #[test]
    fn port_reads_coalesce_within_64_bytes() {
        let mut d = sim("sim-fx:FX2N");
        // D0..D40: 41 words = 82 bytes → 2 frames; plus M0 (another region) → 3.
        let o = ops(d.as_ref(), &["D0..D40", "M0", "D100"]);
        let before = d.requests();
        d.read(&o).unwrap();
        assert_eq!(d.requests() - before, 4, "D0–D31, D32–D40, D100, M0");
        let o = ops(d.as_ref(), &["D0", "D31", "D5", "D16"]);
        let before = d.requests();
        d.read(&o).unwrap();
        assert_eq!(d.requests() - before, 1, "64 bytes in one frame, out of order");
    }

    #[test]
    fn an_fx1s_counter_gap_is_not_read_across() {
        let mut d = sim("sim-fx:FX1S");
        let o = ops(d.as_ref(), &["CS0", "CS31", "CS235", "CS255"]);
        let before = d.requests();
        assert_eq!(d.read(&o).unwrap().len(), 4, "C32–C234 do not exist: no NAK");
        assert_eq!(d.requests() - before, 2);
        let mut l = sim("sim-fx:FX1S?protocol=link");
        let o = ops(l.as_ref(), &["CS0", "CS31", "CS235", "CS255"]);
        assert_eq!(l.read(&o).unwrap().len(), 4);
        assert_eq!(l.requests(), 2);
    }

    #[test]
    fn link_reads_and_writes_coalesce() {
        let mut d = sim("sim-fx:FX2N?protocol=link");
        let o = ops(d.as_ref(), &["D0..D63", "D64", "X0..X7", "K4M0", "M16"]);
        let before = d.requests();
        d.read(&o).unwrap();
        assert_eq!(d.requests() - before, 4, "WR D0–D63, WR D64, BR X0–X7, BR M0–M16");
        // Scattered single words go in one WT frame.
        let w: Vec<(Operand, Value)> =
            ops(d.as_ref(), &["D1", "D50", "D7"]).into_iter().zip([1, 2, 3].map(Value::Int)).collect();
        let before = d.requests();
        d.write(&w).unwrap();
        assert_eq!(d.requests() - before, 1);
        assert_eq!(get(d.as_mut(), "D50"), 2);
    }

    #[test]
    fn decimal_xy_link_frames_reach_the_same_devices() {
        let mut l = sim("sim-fx:FX2N?protocol=link&xy=decimal&share=unit-test-xy");
        let mut p = sim("sim-fx:FX2N?share=unit-test-xy");
        set(l.as_mut(), "Y22", 1); // sent as BW Y0018
        assert_eq!(get(p.as_mut(), "Y22"), 1);
        assert_eq!(get(l.as_mut(), "K2Y20"), 4);
        assert!(open_sim(&DeviceUrl::parse("sim-fx:FX2N?protocol=link&xy=hex").unwrap(), &Clock::stepped()).is_err());
    }

    #[test]
    fn both_ports_share_one_plc() {
        let mut a = sim("sim-fx:FX1N?share=unit-test-a");
        let mut b = sim("sim-fx:FX1N?protocol=link&share=unit-test-a");
        set(a.as_mut(), "D5", 77);
        assert_eq!(get(b.as_mut(), "D5"), 77);
        set(b.as_mut(), "D1000", 9); // written over the link, read on the port
        assert_eq!(get(a.as_mut(), "D1000"), 9);
        assert!(
            open_sim(&DeviceUrl::parse("sim-fx:FX2N?share=unit-test-a").unwrap(), &Clock::stepped()).is_err(),
            "model differs"
        );
    }

    /// A transport in front of the in-process simulator that spoils the replies to the first
    /// `bad` data frames: a wrong sum-check digit, or NAK instead of the answer.
    struct Faulty {
        inner: SimLink,
        rx: std::collections::VecDeque<u8>,
        bad: u32,
        nak: bool,
        frames: u32,
    }
    impl Transport for Faulty {
        fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
            self.inner.send(bytes)?;
            let mut buf = [0u8; 512];
            let n = self.inner.recv(&mut buf, Duration::ZERO)?;
            let mut reply = buf[..n].to_vec();
            if bytes != [ENQ] {
                self.frames += 1;
                if self.bad > 0 {
                    self.bad -= 1;
                    if self.nak {
                        reply = vec![NAK];
                    } else {
                        let last = reply.len() - 1;
                        reply[last] = if reply[last] == b'0' { b'1' } else { b'0' };
                    }
                }
            }
            self.rx.extend(reply);
            Ok(())
        }
        fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
            let n = buf.len().min(self.rx.len());
            for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
                *slot = b;
            }
            Ok(n)
        }
    }

    fn faulty(bad: u32, nak: bool, link: bool) -> (Driver, Arc<Mutex<Memory>>) {
        let model = Model::find("FX2N").unwrap();
        let plc = sim_plc(model, None, &Clock::stepped()).unwrap();
        let s = Settings::default();
        let h = Header { station: 0, pc: 0xFF, wait: 0 };
        let server: Box<dyn Server> =
            if link { Box::new(LinkServer::new(0, s)) } else { Box::new(PortServer::default()) };
        let t = Faulty { inner: SimLink::new(plc.clone(), server), rx: Default::default(), bad, nak, frames: 0 };
        let line = lines::private("faulty", Box::new(t));
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "faulty".into(), simulated: true };
        let d = if link { Driver::link(line, model, h, s, info) } else { Driver::port(line, model, info) };
        (d, plc)
    }

    #[test]
    fn bad_sums_and_naks_are_retried_three_times_then_reported() {
        for link in [false, true] {
            // Three spoiled replies: the fourth attempt succeeds.
            let (mut d, plc) = faulty(3, false, link);
            plc.lock().unwrap().set_word(Area::D, 5, 1234).unwrap();
            assert_eq!(get(&mut d, "D5"), 1234, "link={link}");
            assert_eq!((d.requests(), d.resent), (4, 3));
            // Four: reported as a link error naming the bad sum.
            let (mut d, _) = faulty(4, false, link);
            let o = ops(&d, &["D5"]);
            let e = d.read(&o).unwrap_err();
            assert_eq!(e.kind, ErrorKind::Link, "{e}");
            assert!(e.message.contains("sum check") && e.message.contains("4 attempts"), "{e}");
            assert_eq!(d.requests(), 4);
            // The link recovers afterwards.
            assert_eq!(get(&mut d, "D5"), 0);
        }
        // NAK four times on the programming port: the PLC refuses.
        let (mut d, _) = faulty(4, true, false);
        let o = ops(&d, &["M500"]);
        let e = d.write(&[(o[0], Value::Bool(true))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused, "{e}");
        assert!(e.message.contains("NAK") && e.message.contains("forcing M500 ON"), "{e}");
        let (mut d, plc) = faulty(2, true, false);
        let o = ops(&d, &["M500"]);
        d.write(&[(o[0], Value::Bool(true))]).unwrap();
        assert_eq!(plc.lock().unwrap().bit(Area::M, 500), Some(true));
    }

    #[test]
    fn link_nak_codes_are_reported_in_words() {
        // The device table says D7999 exists on an FX2N; a simulated FX1S lacks D300, but the
        // space refuses it before sending — so build a link driver whose model is larger than
        // the simulated PLC to see the PLC's own NAK.
        let big = Model::find("FX2N").unwrap();
        let plc = sim_plc(Model::find("FX1S").unwrap(), None, &Clock::stepped()).unwrap();
        let s = Settings::default();
        let line = lines::private("mismatch", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
        let mut d = Driver::link(line, big, Header { station: 0, pc: 0xFF, wait: 0 }, s, info);
        let e = d.read(&ops(&d, &["D300"])).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused);
        assert!(e.message.contains("NAK 06H") && e.message.contains("device number"), "{e}");
        assert_eq!(d.requests(), 1, "an area error is not retried");
    }

    #[test]
    fn silence_is_reported_with_what_to_check() {
        // A link request for station 3 on a line where only station 0 answers.
        let model = Model::find("FX2N").unwrap();
        let plc = sim_plc(model, None, &Clock::stepped()).unwrap();
        let s = Settings::default();
        let line = lines::private("one-station", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
        let mut d = Driver::link(line, model, Header { station: 3, pc: 0xFF, wait: 0 }, s, info.clone());
        let e = d.read(&ops(&d, &["D0"])).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(e.message.contains("no reply to WR"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("station 3"), "{e:?}");
        assert_eq!(d.requests(), 1, "silence is not retried");
        // A programming port that answers nothing: the ENQ probe goes unanswered, the frame
        // goes without it, and the silence is reported naming both; the next request probes again.
        let (mut p, sent) = scripted(None, vec![]);
        let e = p.read(&ops(&p, &["D0"])).unwrap_err();
        assert!(e.message.contains("no reply to a read of 2 bytes at 1000H"), "{e}");
        assert!(e.message.contains("it answered no ENQ either"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("7E1"), "{e:?}");
        assert_eq!(p.requests(), 1);
        p.read(&ops(&p, &["D0"])).unwrap_err();
        let sent = sent.lock().unwrap().clone();
        assert_eq!(sent.iter().map(|f| f[0]).collect::<Vec<_>>(), vec![ENQ, port::STX, ENQ, port::STX], "{sent:?}");
    }

    /// A timeout the user set is quoted as given in the no-reply message, to the
    /// microsecond (never `timeout=` with the value lost, never `0 ms`).
    #[test]
    fn a_no_reply_message_keeps_the_timeout_the_user_gave() {
        let model = Model::find("FX2N").unwrap();
        let plc = sim_plc(model, None, &Clock::stepped()).unwrap();
        let s = Settings::default();
        let line = lines::private("one-station", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
        let mut d = Driver::link(line, model, Header { station: 3, pc: 0xFF, wait: 0 }, s, info);
        for (given, shown) in
            [("40ms", "40 ms (timeout=40ms)"), ("2.5", "2.5 ms (timeout=2.5)"), ("0.03s", "30 ms (timeout=0.03s)")]
        {
            d.set_option("timeout", given).unwrap();
            let e = d.read(&ops(&d, &["D0"])).unwrap_err();
            assert!(e.message.contains(&format!("within {shown}")), "{given}: {e}");
        }
        // `auto` goes back to the timeout computed from the line, with its parts.
        d.set_option("timeout", "auto").unwrap();
        let e = d.read(&ops(&d, &["D0"])).unwrap_err();
        assert!(e.message.contains("characters at 9600") && !e.message.contains("timeout="), "{e}");
    }

    // Public drivers (node-fxplc `FXPLCClient._sendCommand`, KrystianD/fxplc `_send_command`)
    // send their frames without ENQ, and clones answer them: a PLC that leaves the ENQ probe
    // unanswered is talked to without ENQ from then on.
    #[test]
    fn enq_is_probed_once_and_skipped_when_unanswered() {
        let read = port::encode_read_reply(&[0x34, 0x12]);
        let (mut d, sent) = scripted(None, vec![vec![], read.clone(), read.clone(), read.clone()]);
        assert_eq!(get(&mut d, "D123"), 0x1234);
        assert_eq!(get(&mut d, "D123"), 0x1234);
        assert_eq!(get(&mut d, "D123"), 0x1234);
        let firsts: Vec<u8> = sent.lock().unwrap().iter().map(|f| f[0]).collect();
        assert_eq!(firsts, vec![ENQ, port::STX, port::STX, port::STX], "one probe, then frames alone");
        // A PLC that answers ENQ keeps getting it after a failure (here a bad sum check).
        let mut bad = read.clone();
        bad[7] ^= 1;
        let (mut d, sent) = scripted(None, vec![vec![ACK], bad, vec![ACK], read.clone()]);
        assert_eq!(get(&mut d, "D123"), 0x1234);
        let firsts: Vec<u8> = sent.lock().unwrap().iter().map(|f| f[0]).collect();
        assert_eq!(firsts, vec![ENQ, port::STX, ENQ, port::STX]);
    }

    /// A line that answers each frame sent with the next scripted bytes (nothing once the
    /// script runs out), keeping what was sent.
    struct Scripted {
        replies: std::collections::VecDeque<Vec<u8>>,
        rx: std::collections::VecDeque<u8>,
        sent: Arc<Mutex<Vec<Vec<u8>>>>,
    }
    impl Transport for Scripted {
        fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
            self.sent.lock().unwrap().push(bytes.to_vec());
            self.rx.extend(self.replies.pop_front().unwrap_or_default());
            Ok(())
        }
        fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
            let n = buf.len().min(self.rx.len());
            for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
                *slot = b;
            }
            Ok(n)
        }
    }

    /// A driver (computer link for `station`, or the programming port) on a scripted line.
    fn scripted(station: Option<u8>, replies: Vec<Vec<u8>>) -> (Driver, Arc<Mutex<Vec<Vec<u8>>>>) {
        let sent = Arc::new(Mutex::new(Vec::new()));
        let t = Scripted { replies: replies.into(), rx: Default::default(), sent: sent.clone() };
        let line = lines::private("scripted", Box::new(t));
        let model = Model::find("FX2N").unwrap();
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "scripted".into(), simulated: true };
        let d = match station {
            Some(st) => Driver::link(line, model, Header { station: st, pc: 0xFF, wait: 0 }, Settings::default(), info),
            None => Driver::port(line, model, info),
        };
        (d, sent)
    }

    fn reply(station: u8, r: Reply) -> Vec<u8> {
        fxlink::encode_reply(Header { station, pc: 0xFF, wait: 0 }, &r, Settings::default())
    }

    // Seed 004, "FX系列PLC专用协议通信指令格式详解": the reply repeats the station number, data
    // comes in STX … ETX, a write is acknowledged with ACK, an error is NAK and a code
    // ("若发送码有误，则有以下回应"). A reply carries no device address: a reply from another
    // station, or of the wrong kind or length, is never taken for this request's.
    #[test]
    fn link_replies_must_fit_the_request() {
        let data = |st, v: &str| reply(st, Reply::Data(v.as_bytes().to_vec()));
        // Station 3's data (9999 = 270FH) to station 5's read of D100: resent, and D100's own value used.
        let (mut d, sent) = scripted(Some(5), vec![data(3, "270F"), data(5, "0064")]);
        assert_eq!(get(&mut d, "D100"), 100);
        assert_eq!((sent.lock().unwrap().len(), d.resent), (2, 1));
        // Two words where one was asked for (the reply to another request), then ACK: never a value.
        let (mut d, _) = scripted(Some(5), vec![data(5, "00640065"), reply(5, Reply::Ack), data(5, "0064")]);
        assert_eq!(get(&mut d, "D100"), 100, "the third reply fits");
        let (mut d, _) = scripted(Some(5), vec![data(5, "00640065"); 4]);
        let e = d.read(&ops(&d, &["D100"])).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link, "{e}");
        assert!(e.message.contains("another request") && e.message.contains("4 attempts"), "{e}");
        // A write answered by a data frame, by another station's ACK: not done, and said so.
        let o = ops(&d, &["D100"])[0];
        for wrong in [data(5, "0064"), reply(3, Reply::Ack)] {
            let (mut d, sent) = scripted(Some(5), vec![wrong.clone(); 4]);
            let e = d.write(&[(o, Value::Int(1))]).unwrap_err();
            assert_eq!(e.kind, ErrorKind::Link, "{e}");
            assert!(e.message.contains("WW of 1 value(s) at D0100") && e.message.contains("4 attempts"), "{e}");
            assert_eq!(sent.lock().unwrap().len(), 4);
        }
        // ... and ACK from the addressed station after one of them: done.
        let (mut d, _) = scripted(Some(5), vec![data(5, "0064"), reply(5, Reply::Ack)]);
        d.write(&[(o, Value::Int(1))]).unwrap();
        // NAK 06 to a write: refused at once, never success.
        let (mut d, sent) = scripted(Some(5), vec![reply(5, Reply::Nak(6))]);
        let e = d.write(&[(o, Value::Int(1))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused, "{e}");
        assert!(e.message.contains("station 5 answered NAK 06H to WW"), "{e}");
        assert_eq!(sent.lock().unwrap().len(), 1, "a resend cannot cure an area error");
        // Another station's NAK is not this station's refusal.
        let (mut d, _) = scripted(Some(5), vec![reply(3, Reply::Nak(6)), reply(5, Reply::Ack)]);
        d.write(&[(o, Value::Int(1))]).unwrap();
    }

    // Seed 004: the PLC answers ENQ with ACK when ready and NAK on error ("通过ENQ、ACK和NAK上位机
    // 协调与PLC的通信应答"). A burst of 00H — what a serial port delivers for characters with
    // parity errors — is neither; it is set aside, and reported as noise when nothing else comes.
    #[test]
    fn noise_is_set_aside_and_never_called_a_nak() {
        let burst = vec![0u8; 31];
        let with = |mut a: Vec<u8>, b: &[u8]| {
            a.extend_from_slice(b);
            a
        };
        // Noise in front of the ACK and of the data: the exchange succeeds at once.
        let read = port::encode_read_reply(&[0x34, 0x12]);
        let (mut d, sent) = scripted(None, vec![with(burst.clone(), &[ACK]), with(burst.clone(), &read)]);
        assert_eq!(get(&mut d, "D123"), 0x1234);
        assert_eq!(sent.lock().unwrap().len(), 2, "ENQ and one read");
        // Nothing but noise to every ENQ: noise, not NAK.
        let (mut d, sent) = scripted(None, vec![burst.clone(); 4]);
        let e = d.read(&ops(&d, &["D123"])).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link, "{e}");
        assert!(e.message.contains("noise") && e.message.contains("31 × 00H"), "{e}");
        assert!(!e.message.contains("NAK"), "{e}");
        assert_eq!(sent.lock().unwrap().as_slice(), vec![vec![ENQ]; 4].as_slice());
        // Real NAKs are still NAKs.
        let (mut d, _) = scripted(None, vec![vec![NAK]; 4]);
        let e = d.read(&ops(&d, &["D123"])).unwrap_err();
        assert!(e.message.contains("answered ENQ with NAK 4 times"), "{e}");
        // Bytes with the parity bit and a stray tail in front of a link reply: set aside.
        let mut noisy = vec![0x80, 0xFF, b'3', b'B'];
        noisy.extend(reply(0, Reply::Data(b"0007".to_vec())));
        let (mut d, _) = scripted(Some(0), vec![noisy]);
        assert_eq!(get(&mut d, "D5"), 7);
        assert_eq!(d.resent, 0);
        // Only noise on the link, four times: reported as noise.
        let (mut d, _) = scripted(Some(0), vec![vec![0x00, 0x80, 0x00]; 4]);
        let e = d.read(&ops(&d, &["D5"])).unwrap_err();
        assert!(e.message.contains("noise on the line") && !e.message.contains("NAK"), "{e}");
        // A mix is listed attempt by attempt.
        let (mut d, _) = scripted(Some(0), vec![vec![0x00], vec![0x00], reply(0, Reply::Nak(2)), vec![0x00]]);
        let e = d.read(&ops(&d, &["D5"])).unwrap_err();
        assert!(e.message.contains("4 attempts: noise ×3, NAK 02H ×1"), "{e}");
    }

    #[test]
    fn timeouts_follow_the_line_the_frames_and_the_wait() {
        let model = Model::find("FX2N").unwrap();
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
        let link = |baud: u32, wait: u8, networked: bool| {
            let line = lines::private(
                "t",
                Box::new(SimLink::new(
                    sim_plc(model, None, &Clock::stepped()).unwrap(),
                    Box::new(PortServer::default()),
                )),
            );
            let serial = LineSettings { baud, data_bits: 7, parity: Parity::Even, stop_bits: 1 };
            Driver::link(line, model, Header { station: 0, pc: 0xFF, wait }, Settings::default(), info.clone())
                .on_line(serial, networked)
        };
        // A WR of 64 words: a 17-character request, a 264-character reply (seed 004's frame:
        // STX, station, PC number, 4 hex per word, ETX, sum).
        let wr64 = (17, fxlink::data_reply_chars(256, Settings::default()));
        assert_eq!(wr64.1, 264);
        // 281 characters of 10 bits at 4800 baud: 585.4 ms on the wire, then the turnaround.
        let t4800 = link(4800, 0, false).timeout_for(wr64.0, wr64.1);
        assert_eq!(t4800, Duration::from_micros(585_417) + TURNAROUND);
        assert!(t4800 > Duration::from_millis(550), "a 64-word WR at 4800 baud fits");
        let t9600 = link(9600, 0, false).timeout_for(wr64.0, wr64.1);
        let t19200 = link(19200, 0, false).timeout_for(wr64.0, wr64.1);
        assert!(t4800 > t9600 && t9600 > t19200, "{t4800:?} {t9600:?} {t19200:?}");
        // 2810 bits: 292 709 µs at 9600 baud, 146 355 µs at 19200 (each rounded up).
        assert_eq!(t9600 - t19200, Duration::from_micros(292_709 - 146_355), "the wire time halves");
        // A smaller frame, the wait digit (×10 ms) and a device server each change it.
        assert!(link(9600, 0, false).timeout_for(17, 12) < t9600);
        assert_eq!(
            link(9600, 5, false).timeout_for(17, 12) - link(9600, 0, false).timeout_for(17, 12),
            Duration::from_millis(50)
        );
        assert_eq!(
            link(9600, 0, true).timeout_for(17, 12) - link(9600, 0, false).timeout_for(17, 12),
            NETWORK_ALLOWANCE
        );
        // The URL's timeout= replaces it; `auto` brings the computed one back.
        let mut d = link(4800, 0, false);
        d.set_option("timeout", "200ms").unwrap();
        assert_eq!(d.timeout_for(wr64.0, wr64.1), Duration::from_millis(200));
        assert!(d.timeout_text(17, 12).contains("timeout="));
        d.set_option("timeout", "auto").unwrap();
        assert_eq!(d.timeout_for(wr64.0, wr64.1), t4800);
        assert!(d.timeout_text(wr64.0, wr64.1).starts_with("835 ms (281 characters at 4800 7E1: 585 ms on the wire"));
        // Resends wait at least the frame time.
        assert!(d.resend_gap(wr64.0, wr64.1) >= Duration::from_millis(550));
    }

    /// A line that never falls quiet: a character every millisecond.
    struct Chatter(Arc<std::sync::atomic::AtomicUsize>);
    impl Transport for Chatter {
        fn send(&mut self, _: &[u8]) -> io::Result<()> {
            self.0.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
            Ok(())
        }
        fn recv(&mut self, buf: &mut [u8], t: Duration) -> io::Result<usize> {
            std::thread::sleep(t.min(Duration::from_millis(1)));
            buf[0] = b'7';
            Ok(1)
        }
    }

    #[test]
    fn a_line_that_never_falls_quiet_gets_no_frame() {
        let sent = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        let model = Model::find("FX2N").unwrap();
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
        let line = lines::private("chatter", Box::new(Chatter(sent.clone())));
        let mut d = Driver::link(line, model, Header { station: 0, pc: 0xFF, wait: 0 }, Settings::default(), info)
            .on_line(LineSettings { baud: 19200, data_bits: 7, parity: Parity::Even, stop_bits: 1 }, false);
        let e = d.read(&ops(&d, &["D0"])).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(e.message.contains("did not go quiet before WR of 1 point(s) from D0000"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("only master"), "{e:?}");
        assert_eq!(sent.load(std::sync::atomic::Ordering::SeqCst), 0, "nothing is sent into a busy line");
    }
}
