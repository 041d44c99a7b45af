//! The FX drivers: one [`Device`] that speaks either the programming-port protocol
//! (`fx:/dev/ttyUSB0`, 9600 7E1) or the computer link (`fxlink:/dev/ttyUSB0?station=0&pc=FF&wait=0`)
//! over any [`Transport`] — a serial port, a pty served by `plcsh sim serve`, or the
//! in-process simulator (`sim-fx:FX2N`, which therefore runs this same code).
//!
//! This file holds what both protocols share: the [`Driver`], the transaction on the line
//! (quiet, send, collect, judge, resend) and its messages, the [`Device`] face and the URL
//! parameters. What differs lives beside it: the programming port's handshake, address
//! table and frames in `programming_port`, the computer link's commands and frames in
//! `computer_link`, and the in-process simulator as a device in `simulated`.
//!
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

mod computer_link;
mod programming_port;
mod simulated;

pub use computer_link::open_link;
pub use programming_port::open_port;
pub use simulated::{open_sim, sim_plc};

use super::link::{self as fxlink, Header, Settings};
use super::model::Model;
use super::operand::{system_driven, Area, FxOperand};
use super::sim::Plc;
use super::space::{FxSpace, Proto};
use crate::core::link::line::{SharedLine, Transport};
use crate::core::link::serial::{LineSettings, Parity};
use crate::core::literal::millis_text;
use crate::core::trace::{self, Dir, Proto as Wire};
use crate::core::url::DeviceUrl;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::msg;
use computer_link::classify_link;
use programming_port::{classify_port, port_len, Handshake};
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
            Got::Data(_) => msg!("fx-got", got = "data").text,
            Got::Ack => "ACK".into(),
            Got::Nak(None) => "NAK".into(),
            Got::Nak(Some(c)) => format!("NAK {c:02X}H"),
            Got::BadSum(_) => msg!("fx-got", got = "bad-sum").text,
            Got::Other(_) => msg!("fx-got", got = "other").text,
            Got::Noise(_) => msg!("fx-got", got = "noise").text,
            Got::Partial(_) => msg!("fx-got", got = "partial").text,
            Got::Silent { .. } => msg!("fx-got", got = "silence").text,
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
    msg!("fx-late", count = late).text
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
    /// `sim cpu`), reached by the shell through [`ops`].
    pub sim: Option<Plc>,
}

/// The simulated FX PLC's driver behind a device (`sim-fx:`: its CPU, `sim program`, `sim
/// cpu`), for a command about to make `changes`, through the one generic lookup
/// (`core::device::lookup`): the device's write rules check `changes` first. A real FX has no
/// operations of its own and answers `None`.
pub fn ops<'a>(dev: &'a mut dyn Device, changes: &[crate::core::device::Change]) -> Result<Option<&'a mut Driver>> {
    Ok(crate::core::device::lookup(dev, "fx", changes)?.and_then(|a| a.downcast_mut::<Driver>()))
}

/// The simulated FX PLC behind a device, if it is one (`sim-fx:`; simulation controls).
pub fn simulator(dev: &mut dyn Device) -> Option<Plc> {
    ops(dev, &[]).ok()??.sim.clone()
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
            return msg!("fx-timeout-given", time = millis_text(t), given = given).text;
        }
        let t = self.timeout_for(req, reply).as_millis();
        let mut parts = vec![
            msg!(
                "fx-timeout-wire",
                count = req + reply,
                serial = self.serial.to_string(),
                ms = self.serial.time_of(req + reply).as_millis() as u64
            )
            .text,
        ];
        if !self.wait().is_zero() {
            parts.push(msg!("fx-timeout-wait", ms = self.wait().as_millis() as u64).text);
        }
        parts.push(msg!("fx-timeout-plc", ms = TURNAROUND.as_millis() as u64).text);
        if !self.allowance.is_zero() {
            parts.push(msg!("fx-timeout-server", ms = self.allowance.as_millis() as u64).text);
        }
        msg!("fx-timeout-total", ms = t as u64, parts = parts.join(", ")).text
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
            return Err(Error::link(msg!(
                "fx-not-quiet",
                line = &self.line.name,
                what = what,
                count = n,
                ms = limit.as_millis() as u64
            ))
            .hint(match &self.mode {
                Mode::Port { .. } => msg!("fx-hint-not-quiet-port"),
                Mode::Link { .. } => msg!("fx-hint-not-quiet-link"),
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
                    let timeout = self.timeout_text(frame.len(), expect.chars());
                    let line = self.line.name.clone();
                    let m = match &self.mode {
                        Mode::Link { header, .. } => msg!(
                            "fx-no-reply-station",
                            what = what,
                            station = header.station,
                            line = line,
                            timeout = timeout,
                            late = late_text(late)
                        ),
                        Mode::Port { handshake: Handshake::Skip, .. } => {
                            // Probe again next time: the PLC may want ENQ after all.
                            self.mode = Mode::Port { synced: false, handshake: Handshake::Probe };
                            msg!(
                                "fx-no-reply-no-enq",
                                what = what,
                                line = line,
                                timeout = timeout,
                                late = late_text(late)
                            )
                        }
                        Mode::Port { .. } => {
                            msg!("fx-no-reply", what = what, line = line, timeout = timeout, late = late_text(late))
                        }
                    };
                    return Err(Error::link(m).hint(if late > 0 {
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
            (n, 1) | (n @ 1, _) => msg!("fx-attempts", n = n).text,
            (n, _) => {
                msg!(
                    "fx-attempts-list",
                    n = n,
                    list = labels.iter().map(|(l, k)| format!("{l} ×{k}")).collect::<Vec<_>>().join(", ")
                )
                .text
            }
        };
        let (who, station) = match &self.mode {
            Mode::Link { header, .. } => ("station", header.station),
            Mode::Port { .. } => ("plc", 0),
        };
        match seen.last() {
            Some(Got::Nak(Some(c))) => Error::new(
                ErrorKind::Refused,
                msg!(
                    "fx-nak-code",
                    who = who,
                    station = station,
                    code = format!("{c:02X}"),
                    what = what,
                    line = name,
                    meaning = fxlink::nak_text(*c)
                ),
            )
            .hint(match *c {
                fxlink::code::AREA => msg!("fx-hint-nak-area"),
                fxlink::code::PC_NUMBER => msg!("fx-hint-nak-pc"),
                fxlink::code::SUM | fxlink::code::PROTOCOL => msg!("fx-hint-nak-sum"),
                _ => msg!("fx-hint-nak-other"),
            }),
            Some(Got::Nak(None)) => {
                Error::new(ErrorKind::Refused, msg!("fx-nak", what = what, line = name, tries = &tries)).hint(
                    if self.space.model.extended { msg!("fx-hint-nak-extended") } else { msg!("fx-hint-nak-classic") },
                )
            }
            Some(Got::BadSum(m)) => {
                Error::link(msg!("fx-bad-reply", what = what, line = name, tries = &tries, reason = m)).hint(
                    match &self.mode {
                        Mode::Port { .. } => msg!("fx-hint-bad-sum-port"),
                        Mode::Link { .. } => msg!("fx-hint-bad-sum-link"),
                    },
                )
            }
            Some(Got::Noise(b)) => {
                Error::link(msg!("fx-noise", line = name, what = what, tries = &tries, bytes = show(b)))
                    .hint(msg!("fx-hint-noise", serial = self.serial.to_string()))
            }
            Some(Got::Partial(p)) => Error::link(msg!(
                "fx-incomplete",
                what = what,
                line = name,
                timeout = self.timeout_text(sizes.0, sizes.1),
                tries = &tries,
                bytes = show(p)
            ))
            .hint(msg!("fx-hint-incomplete", serial = self.serial.to_string())),
            Some(Got::Other(m)) => Error::link(msg!(
                "fx-other-reply",
                who = who,
                station = station,
                what = what,
                line = name,
                tries = &tries,
                reason = m
            ))
            .hint(match &self.mode {
                Mode::Port { .. } => msg!("fx-hint-other-port"),
                Mode::Link { header, .. } => msg!("fx-hint-other-link", station = header.station),
            }),
            _ => Error::link(msg!("fx-no-usable-reply", what = what, line = name, tries = &tries)),
        }
    }

    fn late_hint(&self, req: usize, reply: usize) -> String {
        let t = self.timeout_for(req, reply);
        msg!("fx-hint-late", time = millis_text(t), twice = millis_text(2 * t).replace(' ', "")).text
    }

    fn silence_hint(&self) -> String {
        match &self.mode {
            Mode::Port { .. } => msg!("fx-hint-silent-port", serial = self.serial.to_string()).text,
            Mode::Link { header, .. } => msg!("fx-hint-silent-link", station = header.station).text,
        }
    }
}

fn read_only(o: &FxOperand) -> Error {
    Error::unsupported(msg!("fx-read-only", operand = o.canonical(), meaning = o.area.meaning().text))
        .operand(o.canonical())
}

/// A write to a special device the CPU rewrites every scan: a real PLC ignores it, so it is
/// refused here with what to do instead.
fn driven_by_plc(o: &FxOperand, index: u16) -> Error {
    let name = format!("{}{index}", o.area.name());
    let what = super::operand::special_meaning(o.area, index).unwrap_or_else(|| msg!("fx-special-device"));
    let hint = if o.area == Area::M && index <= 8003 { msg!("fx-hint-run-stop") } else { msg!("fx-hint-driven") };
    Error::unsupported(msg!("fx-driven-by-plc", operand = name, meaning = what.text)).operand(o.canonical()).hint(hint)
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

    fn family(&mut self, _changes: &[crate::core::device::Change]) -> Result<Option<&mut dyn std::any::Any>> {
        // Only a simulator has operations of its own (its CPU); a real FX has none here.
        Ok(self.sim.is_some().then_some(self as &mut dyn std::any::Any))
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
                    .ok_or_else(|| Error::usage(msg!("fx-retries", value = value)))?
            }
            _ => return Err(Error::usage(msg!("fx-no-option", key = key)).hint(msg!("fx-hint-options"))),
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

#[cfg(test)]
mod tests;
