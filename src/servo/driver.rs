//! The Kinco servo driver: a [`Device`] speaking the 10-byte RS232 protocol over any
//! [`Transport`] — a serial port (`kinco:/dev/ttyUSB0?baud=38400&id=1`), a pty served by
//! `plcsh sim serve`, or the in-process simulator (`sim-servo:?id=1`, which therefore runs
//! this same code).
//!
//! Several drives on one line: one device per drive id, sharing the port
//! (`--device ax1=kinco:/dev/ttyUSB0?id=1 --device ax2=kinco:/dev/ttyUSB0?id=2`); the line
//! registry in [`super::link`] opens the port once and serialises requests. This keeps
//! each drive a named device with its own operands, units and `servo` helpers, instead of
//! an id inside every operand.
//!
//! One request, one reply (§2). Before each request the line must be quiet for a few
//! character times, and after a request went unanswered for one more timeout, so a late reply
//! is dropped rather than read as the next request's; a whole frame that answers another id
//! or object while a request waits is stale and skipped. Replies are checked against the
//! request (id, object, function, echoed data); a mismatch or a bad checksum is a link error.
//! A request that got only late or stale replies is diagnosed as such. No reply within
//! the timeout is a link error that lists the manual's three causes (wrong id, unknown
//! object, bad checksum; seed §2.4) and says which is likely, found by asking the same id
//! for its statusword: if that answers, the object is probably unknown; if not, the id is
//! probably wrong. In loop mode (`echo=1`, public notes "RS232 loop") the echoed request is
//! read and compared first; an echo that differs means the line corrupts frames, so the
//! drive sees a bad checksum.
//!
//! URL parameters: `id` (default 1), `baud` (38400), `echo` (0), `timeout` (200ms; a
//! number is milliseconds), `encoder` (10000, or `auto` to read 6410.03 at open);
//! `sim-servo:` also takes `drives=1,2` (the simulated ids on the line, default the `id`).
//! `sim-servo:NAME?…` devices with the same NAME share one simulated line; `strict=1` makes
//! the simulated drives refuse loose write sizes, `baud=`/`latency=` pace replies like a line.
//! `kinco:` takes `control=PATH`, a served simulator's control socket (default `PORT.ctl`
//! when it exists), for `servo sim …`.

use super::frame::{self, abort_text, decode_reply, Frame, Reply, Size, FRAME_LEN};
use super::objects::{ObjRef, ServoSpace};
use super::sim::{SimLine, SimLink};
use super::units::{self, Resolution};
use super::ServoOps;
use crate::core::link::line::{self as link, SharedLine, Transport};
use crate::core::link::serial::{Carrier, LineSettings};
use crate::core::literal::parse_option_duration_us;
use crate::core::trace::{self, Dir, Proto};
use crate::core::url::DeviceUrl;
use crate::core::{Clock, Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::msg;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Factory baud rate (seed §1).
pub const DEFAULT_BAUD: u32 = 38_400;
/// Default reply timeout. A frame takes 2.6 ms at 38400 baud each way; drives answer
/// within a few ms.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(200);

/// The manual's three reasons a drive stays silent (seed §2.4).
pub fn silence_causes() -> crate::core::msg::Msg {
    msg!("servo-silence-causes")
}

/// Bounds of the quiet awaited before every request: a few character times.
const GAP_MIN: Duration = Duration::from_millis(2);
const GAP_MAX: Duration = Duration::from_millis(50);
/// Longest quiet awaited after silence, for a late reply to be dropped there.
const LATE_MAX: Duration = Duration::from_secs(2);

/// What came back for one request.
enum Exchange {
    Reply([u8; FRAME_LEN]),
    /// Nothing whole arrived for this request; `partial` holds any stray bytes, `stale` the
    /// whole frames that answered something else (an earlier request's late reply, another
    /// drive's), `late` how many bytes came in the quiet awaited after the timeout.
    Silent {
        partial: Vec<u8>,
        stale: Vec<[u8; FRAME_LEN]>,
        late: usize,
    },
}

/// A frame with a good checksum that is not the reply to `req` (another id or object): a
/// late reply to an earlier request, or another drive's. Never taken as `req`'s reply.
fn is_stale(req: &[u8; FRAME_LEN], got: &[u8; FRAME_LEN]) -> bool {
    Frame::from_bytes(got).is_ok() && (got[0], got[2], got[3], got[4]) != (req[0], req[2], req[3], req[4])
}

/// A Kinco servo drive on some transport.
pub struct Driver {
    info: DeviceInfo,
    space: ServoSpace,
    line: SharedLine,
    id: u8,
    echo: bool,
    timeout: Duration,
    requests: u64,
    /// This id has answered at least once.
    answered: bool,
    /// The quiet awaited before each request (a few character times at the line's baud).
    gap: Duration,
    /// A served simulator's control socket (`control=` in the URL, else `PORT.ctl` if present
    /// when the drive was opened).
    control: Option<std::path::PathBuf>,
}

impl Driver {
    /// A driver for drive `id` on `line`.
    pub fn attach(line: SharedLine, id: u8, echo: bool, timeout: Duration, info: DeviceInfo) -> Driver {
        Driver {
            info,
            space: ServoSpace::default(),
            line,
            id,
            echo,
            timeout,
            requests: 0,
            answered: false,
            gap: Self::gap_at(DEFAULT_BAUD),
            control: None,
        }
    }

    pub fn id(&self) -> u8 {
        self.id
    }

    /// Four character times at `baud` (8N1), within [`GAP_MIN`]…[`GAP_MAX`].
    fn gap_at(baud: u32) -> Duration {
        LineSettings::n81(baud).time_of(4).clamp(GAP_MIN, GAP_MAX)
    }

    pub fn resolution(&self) -> &Resolution {
        &self.space.resolution
    }

    fn read_exact(t: &mut dyn Transport, want: usize, deadline: Instant) -> std::io::Result<Vec<u8>> {
        let mut got = vec![0u8; want];
        let mut n = 0;
        while n < want {
            let left = deadline.saturating_duration_since(Instant::now());
            let k = t.recv(&mut got[n..], left)?;
            if k == 0 {
                break;
            }
            n += k;
        }
        got.truncate(n);
        Ok(got)
    }

    /// Sends one frame and collects the reply (skipping the echo in loop mode). Before the
    /// frame goes out the line must be quiet for a few character times, and after silence it
    /// must stay quiet for one more timeout: what arrives there (a late reply, a tail of
    /// noise) is dropped, never read as this request's or the next one's reply. A whole frame
    /// that answers another id or object is stale and skipped while the timeout runs.
    fn exchange(&mut self, bytes: &[u8; FRAME_LEN]) -> Result<Exchange> {
        self.requests += 1;
        let name = self.line.name.clone();
        let mut t = self.line.transport.lock().unwrap_or_else(|p| p.into_inner());
        let gone = &self.line.gone;
        if gone.load(std::sync::atomic::Ordering::SeqCst) {
            if let Some(reopen) = &self.line.reopen {
                *t = reopen().map_err(|e| {
                    Error::link(msg!("servo-port-still-gone", port = &name))
                        .cause(e.message.clone())
                        .hint(msg!("servo-hint-port-gone"))
                })?;
                gone.store(false, std::sync::atomic::Ordering::SeqCst);
            }
        }
        let reopens = self.line.reopen.is_some();
        let io_err = |e: std::io::Error| {
            // Any I/O failure of the port itself: the next request opens it again.
            gone.store(reopens, std::sync::atomic::Ordering::SeqCst);
            if port_gone(&e) {
                Error::link(msg!("servo-port-gone", port = &name)).cause(e).hint(msg!("servo-hint-port-gone"))
            } else {
                Error::link(msg!("servo-port-io", port = &name)).cause(e).hint(msg!("servo-hint-port-gone"))
            }
        };
        t.discard_input().map_err(io_err)?;
        t.settle(self.gap, self.gap + self.timeout).map_err(io_err)?;
        trace::frame_proto(&name, Proto::KincoServo, Dir::Sent, bytes);
        t.send(bytes).map_err(io_err)?;
        let deadline = Instant::now() + self.timeout;
        if self.echo {
            let echo = Self::read_exact(t.as_mut(), FRAME_LEN, deadline).map_err(io_err)?;
            if echo.len() < FRAME_LEN {
                return Err(Error::link(msg!("servo-no-echo", port = &name)).hint(msg!("servo-hint-no-echo")));
            }
            trace::frame_proto(&name, Proto::KincoServo, Dir::Received, &echo);
            if echo != bytes {
                // A reply where the echo should be: the line is not in loop mode.
                let is_reply = <[u8; FRAME_LEN]>::try_from(echo.as_slice())
                    .ok()
                    .and_then(|b| Frame::from_bytes(&b).ok())
                    .is_some_and(|f| {
                        f.id == bytes[0] && f.index == u16::from_le_bytes([bytes[2], bytes[3]]) && f.sub == bytes[4]
                    });
                if is_reply {
                    return Err(Error::link(msg!(
                        "servo-reply-before-echo",
                        port = &name,
                        bytes = trace::hex_bytes(&echo)
                    ))
                    .hint(msg!("servo-hint-reply-before-echo")));
                }
                return Err(Error::link(msg!(
                    "servo-echo-differs",
                    port = &name,
                    sent = trace::hex_bytes(bytes),
                    echo = trace::hex_bytes(&echo)
                ))
                .hint(msg!("servo-hint-baud-wiring")));
            }
        }
        let mut stale = Vec::new();
        loop {
            let got = Self::read_exact(t.as_mut(), FRAME_LEN, deadline).map_err(io_err)?;
            if !got.is_empty() {
                trace::frame_proto(&name, Proto::KincoServo, Dir::Received, &got);
            }
            match <[u8; FRAME_LEN]>::try_from(got.as_slice()) {
                Ok(b) if is_stale(bytes, &b) && stale.len() < 8 => stale.push(b),
                Ok(b) => return Ok(Exchange::Reply(b)),
                Err(_) => {
                    let quiet = self.timeout.min(LATE_MAX);
                    let late = t.settle(quiet, 2 * quiet + self.gap).map_err(io_err)?;
                    return Ok(Exchange::Silent { partial: got, stale, late });
                }
            }
        }
    }

    /// One request: send, check the reply, decode it; diagnose silence.
    pub fn transact(&mut self, req: Frame, size: Size) -> Result<Reply> {
        match self.exchange(&req.to_bytes())? {
            // Our own request came back: the line is in loop mode and we did not skip it.
            Exchange::Reply(b) if !self.echo && b == req.to_bytes() => {
                Err(Error::link(msg!("servo-reply-is-request", verb = verb(&req), object = req.object()))
                    .hint(msg!("servo-hint-use-echo")))
            }
            Exchange::Reply(b) => match decode_reply(&req, &b, size) {
                Ok(r) => {
                    self.answered = true;
                    Ok(r)
                }
                Err(m) => Err(Error::link(msg!(
                    "servo-bad-reply",
                    verb = verb(&req),
                    object = req.object(),
                    reason = m.to_string()
                ))
                .hint(msg!("servo-hint-bad-reply"))),
            },
            Exchange::Silent { partial, stale, late } => Err(self.silence(&req, &partial, &stale, late, None)),
        }
    }

    /// The link error for a request nobody answered, with the likely cause.
    fn silence(
        &mut self,
        req: &Frame,
        partial: &[u8],
        stale: &[[u8; FRAME_LEN]],
        late: usize,
        bad_checksum: Option<frame::BadChecksum>,
    ) -> Error {
        // As exact as the user gave it (`timeout=0.5` is `0.5 ms`, never `0 ms`).
        let ms = crate::core::literal::millis_text(self.timeout);
        // The cause's own values (`code`, `got`/`want`, `count`/`bytes`); the others are empty.
        let silent = |cause: &str, code: String, got_want: (String, String), count: usize, bytes: String| {
            msg!(
                "servo-silent",
                id = req.id,
                verb = verb(req),
                object = req.object(),
                timeout = &ms,
                cause = cause,
                code = code,
                got = got_want.0,
                want = got_want.1,
                count = count,
                bytes = bytes
            )
        };
        let none = || (String::new(), String::new());
        let likely = if !is_request_func(req.func) {
            silent("function", format!("{:02X}", req.func), none(), 0, String::new())
        } else if let Some(b) = bad_checksum {
            silent("checksum", String::new(), (format!("{:02X}", b.got), format!("{:02X}", b.want)), 0, String::new())
        } else if !stale.is_empty() || late > 0 {
            // A reply came, but too late or to something else: neither the id nor the object
            // is to blame, and no probe is sent.
            let mut what = Vec::new();
            if !stale.is_empty() {
                let frames: Vec<String> = stale.iter().map(|f| trace::hex_bytes(f)).collect();
                what.push(msg!("servo-late-stale", frames = frames.join("; ")).text);
            }
            if late > 0 {
                what.push(msg!("servo-late-bytes", count = late).text);
            }
            return Error::link(msg!(
                "servo-silent-late",
                id = req.id,
                verb = verb(req),
                object = req.object(),
                timeout = &ms,
                what = what.join(", ")
            ))
            .hint(msg!("servo-hint-late", timeout = &ms));
        } else if !partial.is_empty() {
            silent("stray", String::new(), none(), partial.len(), trace::hex_bytes(partial))
        } else {
            silent(self.probe(req), String::new(), none(), 0, String::new())
        };
        Error::link(likely).hint(silence_causes())
    }

    /// Asks the same id for its statusword to tell "wrong id" from "unknown object".
    fn probe(&mut self, req: &Frame) -> &'static str {
        let is_statusword = (req.index, req.sub) == (0x6041, 0) && req.func == frame::func::READ;
        let answers = if is_statusword {
            false
        } else {
            let probe = Frame::read(req.id, 0x6041, 0);
            matches!(self.exchange(&probe.to_bytes()), Ok(Exchange::Reply(b)) if decode_reply(&probe, &b, Size::B2).is_ok())
        };
        if answers {
            "object"
        } else if is_statusword && self.answered && req.id == self.id {
            "stopped"
        } else {
            "id"
        }
    }

    fn refused(&self, req: &Frame, what: &str, code: u32) -> Error {
        Error::new(
            ErrorKind::Refused,
            msg!(
                "servo-refused",
                id = req.id,
                verb = verb(req),
                object = what,
                code = format!("{code:08X}"),
                meaning = abort_text(code)
            ),
        )
        .operand(what)
    }

    /// Reads one object's raw value (masked to its size).
    pub fn read_obj(&mut self, r: ObjRef) -> Result<u32> {
        let req = Frame::read(self.id, r.index, r.sub);
        match self.transact(req, r.size())? {
            Reply::Value(v) => Ok(v),
            Reply::Abort(code) => Err(self.refused(&req, &r.name(), code)),
            Reply::Written => unreachable!("decode_reply refuses a write acknowledgement to a read"),
        }
    }

    /// Writes one object's raw value; the function code follows the object's size.
    pub fn write_obj(&mut self, r: ObjRef, raw: u32) -> Result<()> {
        let req = Frame::write(self.id, r.index, r.sub, r.size(), raw);
        match self.transact(req, r.size())? {
            Reply::Written => Ok(()),
            Reply::Abort(code) => Err(self.refused(&req, &r.name(), code)),
            Reply::Value(_) => unreachable!("decode_reply refuses a read reply to a write"),
        }
    }

    /// Sends a hand-made frame as is; returns the reply bytes. Silence is diagnosed,
    /// including a bad checksum in the frame itself.
    pub fn raw(&mut self, bytes: [u8; FRAME_LEN]) -> Result<[u8; FRAME_LEN]> {
        let bad = Frame::from_bytes(&bytes).err();
        match self.exchange(&bytes)? {
            Exchange::Reply(b) => Ok(b),
            Exchange::Silent { partial, stale, late } => {
                let req = Frame {
                    id: bytes[0],
                    func: bytes[1],
                    index: u16::from_le_bytes([bytes[2], bytes[3]]),
                    sub: bytes[4],
                    data: 0,
                };
                Err(self.silence(&req, &partial, &stale, late, bad))
            }
        }
    }

    fn sim(&self) -> Option<Arc<Mutex<SimLine>>> {
        super::sim::sim_line_of(self.line.transport.lock().unwrap_or_else(|p| p.into_inner()).as_ref())
    }

    /// Reads the encoder resolution from 6410.03 and uses it for unit conversion.
    pub fn read_resolution(&mut self) -> Result<u32> {
        let r = self.read_obj(ObjRef::of(super::objects::named("encoder_resolution")))?;
        if r == 0 {
            return Err(Error::state(msg!("servo-resolution-zero")));
        }
        self.space.resolution.set(r);
        Ok(r)
    }
}

/// Function codes a master may send (seed §2).
fn is_request_func(f: u8) -> bool {
    matches!(f, frame::func::READ | frame::func::WRITE_1 | frame::func::WRITE_2 | frame::func::WRITE_4)
}

fn verb(f: &Frame) -> &'static str {
    match f.func {
        frame::func::READ => "read",
        func if is_request_func(func) => "write",
        _ => "request",
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
        ops.iter()
            .map(|op| {
                let r = ObjRef::from_operand(op);
                if let Some(o) = r.object().filter(|o| !o.readable()) {
                    return Err(Error::unsupported(format!("{} is write-only", o.name)).operand(o.name));
                }
                Ok(r.dtype.decode(self.read_obj(r)?))
            })
            .collect()
    }

    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        for (op, _) in items {
            self.space.check_writable(&ObjRef::from_operand(op))?;
        }
        for (op, v) in items {
            let r = ObjRef::from_operand(op);
            self.write_obj(r, r.dtype.encode(v))?;
        }
        Ok(())
    }

    fn requests(&self) -> u64 {
        self.requests
    }

    /// The drive operations and simulation controls (`servo::ops`, `servo::simulator`): the
    /// driver itself permits everything.
    fn family(&mut self, _changes: &[crate::core::device::Change]) -> Result<Option<&mut dyn std::any::Any>> {
        Ok(Some(self))
    }

    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        match key {
            "encoder" if value == "auto" => self.read_resolution().map(|_| ()),
            "encoder" => {
                self.space.resolution.set(units::parse_resolution(value).map_err(Error::usage)?);
                Ok(())
            }
            "timeout" => {
                self.timeout = parse_timeout(value)?;
                Ok(())
            }
            _ => Err(Error::usage(msg!("servo-no-option", key = key)).hint(msg!("servo-hint-options"))),
        }
    }
}

impl ServoOps for Driver {
    fn drive_id(&self) -> u8 {
        self.id
    }
    fn resolution(&self) -> Resolution {
        self.space.resolution.clone()
    }
    fn read_raw(&mut self, obj: ObjRef) -> Result<u32> {
        self.read_obj(obj)
    }
    fn write_raw(&mut self, obj: ObjRef, raw: u32) -> Result<()> {
        self.write_obj(obj, raw)
    }
    fn raw_frame(&mut self, bytes: [u8; FRAME_LEN]) -> Result<[u8; FRAME_LEN]> {
        self.raw(bytes)
    }
    fn read_resolution(&mut self) -> Result<u32> {
        Driver::read_resolution(self)
    }
    fn simulator(&mut self) -> Option<Arc<Mutex<SimLine>>> {
        self.sim()
    }
    fn sim_control(&self) -> Option<std::path::PathBuf> {
        self.control.clone()
    }
}

fn parse_timeout(v: &str) -> Result<Duration> {
    crate::core::literal::parse_timeout(v).map_err(Error::usage)
}

/// Shared URL settings of both schemes.
struct Common {
    id: u8,
    echo: bool,
    timeout: Duration,
    encoder: Option<String>,
}

fn common(u: &DeviceUrl) -> Result<Common> {
    let id = u.param_num::<u8>("id")?.unwrap_or(1);
    let echo = match u.param("echo").or(u.param("loop")) {
        None | Some("0") | Some("false") | Some("off") => false,
        Some("1") | Some("true") | Some("on") | Some("") => true,
        Some(v) => return Err(Error::usage(msg!("servo-flag-param", key = "echo", value = v, url = &u.text))),
    };
    let timeout = u.param("timeout").map(parse_timeout).transpose()?.unwrap_or(DEFAULT_TIMEOUT);
    Ok(Common { id, echo, timeout, encoder: u.param("encoder").map(str::to_string) })
}

fn finish(mut d: Driver, c: &Common) -> Result<Box<dyn Device>> {
    if let Some(e) = &c.encoder {
        d.set_option("encoder", e)?;
    }
    Ok(Box::new(d))
}

/// Errors that mean the port itself is gone (not a slow or silent drive).
fn port_gone(e: &std::io::Error) -> bool {
    crate::core::link::port_gone(e)
}

/// The URL parameters of a drive on a serial line (`kinco:`) and of the simulator (`sim-servo:`).
pub const SERIAL_PARAMS: &[&str] = &["id", "baud", "echo", "loop", "timeout", "encoder", "control"];
pub const SIM_PARAMS: &[&str] = &["id", "drives", "echo", "loop", "timeout", "encoder", "strict", "baud", "latency"];

/// Opens `kinco:PORT?baud=38400&id=1&echo=0&timeout=200ms&encoder=10000`.
///
/// The line may be a port (`kinco:COM4`, `kinco:/dev/ttyUSB0`), a serial device server's
/// raw TCP port (`kinco+tcp://HOST:PORT`) or its RFC 2217 port (`kinco+rfc2217://HOST:PORT`).
pub fn open_serial(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(SERIAL_PARAMS)?;
    let c = common(u)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(DEFAULT_BAUD);
    if baud == 0 {
        return Err(Error::usage(msg!("servo-baud-zero", url = &u.text)));
    }
    let carrier = Carrier::from_url(u, "kinco:COM4?id=1 or kinco:/dev/ttyUSB0?id=1")?;
    let line = link::shared_serial(&carrier, LineSettings::n81(baud))?;
    let settings = format!("{}{}", line.settings, if c.echo { ", loop" } else { "" });
    let info = DeviceInfo {
        family: "servo",
        model: format!("Kinco servo, id {}", c.id),
        link: format!("{} ({settings})", carrier.key()),
        simulated: false,
    };
    let mut d = Driver::attach(line, c.id, c.echo, c.timeout, info);
    d.gap = Driver::gap_at(baud);
    // A served simulator's control socket: as given, else `PORT.ctl` if the server made one.
    d.control = u.param("control").map(std::path::PathBuf::from).or_else(|| {
        let p = super::sim::serve::control_path(std::path::Path::new(&d.line.name));
        p.exists().then_some(p)
    });
    finish(d, &c)
}

/// Opens `sim-servo:[NAME]?id=1&drives=1,2&echo=0`: the in-process simulator.
pub fn open_sim(u: &DeviceUrl, clock: &Clock) -> Result<Box<dyn Device>> {
    u.expect_params(SIM_PARAMS)?;
    let c = common(u)?;
    let strict = match u.param("strict") {
        None | Some("0") | Some("false") | Some("off") => false,
        Some("1") | Some("true") | Some("on") | Some("") => true,
        Some(v) => return Err(Error::usage(msg!("servo-flag-param", key = "strict", value = v, url = &u.text))),
    };
    // Line timing in-process: off unless baud= or latency= asks for it.
    let pace = match (u.param_num::<u32>("baud")?, u.param("latency")) {
        (None, None) => None,
        (baud, latency) => {
            let latency = match latency {
                None => super::sim::Pace::REALISTIC.latency,
                Some(l) => Duration::from_micros(
                    parse_option_duration_us(l)
                        .ok()
                        .filter(|us| *us >= 0)
                        .ok_or_else(|| Error::usage(msg!("servo-latency-param", value = l, url = &u.text)))?
                        as u64,
                ),
            };
            let baud = baud.unwrap_or(DEFAULT_BAUD);
            if baud == 0 {
                return Err(Error::usage(msg!("servo-baud-zero", url = &u.text)));
            }
            Some(super::sim::Pace { baud, latency })
        }
    };
    let ids = match u.param("drives") {
        None => vec![c.id],
        Some(list) => {
            parse_ids(list).map_err(|m| Error::usage(msg!("servo-ids-in-url", message = m, url = &u.text)))?
        }
    };
    let make = || -> Result<Box<dyn Transport>> {
        let mut l = SimLine::new(&ids, clock.clone());
        l.echo = c.echo;
        l.pace = pace;
        l.set_strict(strict);
        Ok(Box::new(SimLink::new(Arc::new(Mutex::new(l)))))
    };
    let name = if u.target.is_empty() { "sim-servo".to_string() } else { format!("sim-servo:{}", u.target) };
    let line = if u.target.is_empty() {
        link::private(&name, make()?)
    } else {
        let settings = if c.echo { "loop" } else { "" };
        let line = link::shared(&name, settings, make)?;
        if let Some(sim) = super::sim::sim_line_of(line.transport.lock().unwrap_or_else(|p| p.into_inner()).as_ref()) {
            let mut s = sim.lock().unwrap_or_else(|p| p.into_inner());
            for id in &ids {
                s.add_drive(*id);
            }
        }
        line
    };
    let info = DeviceInfo {
        family: "servo",
        model: format!("simulated Kinco servo, id {}", c.id),
        link: u.text.clone(),
        simulated: true,
    };
    finish(Driver::attach(line, c.id, c.echo, c.timeout, info), &c)
}

/// Parses `1,2,5` (drive ids 0–255).
pub fn parse_ids(list: &str) -> std::result::Result<Vec<u8>, String> {
    let ids: std::result::Result<Vec<u8>, _> = list.split(',').map(|s| s.trim().parse::<u8>()).collect();
    match ids {
        Ok(v) if !v.is_empty() => Ok(v),
        _ => Err(msg!("servo-not-ids", list = list).text),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::servo::objects;
    use crate::servo::sim::serve;

    fn sim(url: &str) -> Box<dyn Device> {
        open_sim(&DeviceUrl::parse(url).unwrap(), &Clock::stepped()).unwrap()
    }

    fn op(d: &dyn Device, name: &str) -> Operand {
        d.operands().parse(name).unwrap()[0]
    }

    #[test]
    fn reads_and_writes_through_the_frame_codec() {
        let mut d = sim("sim-servo:?id=1");
        let sw = op(d.as_ref(), "statusword");
        assert_eq!(d.read(&[sw]).unwrap(), vec![Value::Int(0x4231)]);
        let tv = op(d.as_ref(), "target_velocity");
        d.write(&[(tv, Value::Int(-5))]).unwrap();
        assert_eq!(d.read(&[tv]).unwrap(), vec![Value::Int(-5)]);
        assert_eq!(d.requests(), 3);
        let e = d.write(&[(sw, Value::Int(1))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unsupported, "refused before sending");
        assert_eq!(d.requests(), 3, "nothing went on the wire");
    }

    #[test]
    fn a_no_reply_message_keeps_the_timeout_the_user_gave() {
        // Drive 3 is addressed but only drive 1 exists: the message says the timeout as given,
        // to the microsecond (`timeout=2.5` is 2.5 ms, not 2).
        for (given, shown) in [("2.5", "within 2.5 ms"), ("40ms", "within 40 ms"), ("1500us", "within 1.5 ms")] {
            let mut d = sim(&format!("sim-servo:?id=3&drives=1&timeout={given}"));
            let e = d.read(&[op(d.as_ref(), "statusword")]).unwrap_err();
            assert!(e.message.contains(shown), "{given}: {e}");
        }
    }

    #[test]
    fn silence_is_diagnosed() {
        // Drive 3 is addressed but only drive 1 exists on the line.
        let mut d = sim("sim-servo:?id=3&drives=1");
        let e = d.read(&[op(d.as_ref(), "statusword")]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(e.message.contains("likely cause: wrong id"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("(2) an object that does not exist"));
        let mut d = sim("sim-servo:?id=1");
        let e = d.read(&[op(d.as_ref(), "3FFF.01/u16")]).unwrap_err();
        assert!(e.message.contains("likely cause: unknown object"), "{e}");
        let mut s = crate::servo::ops(d.as_mut()).unwrap();
        let mut bad = Frame::read(1, 0x6041, 0).to_bytes();
        bad[9] = bad[9].wrapping_add(1);
        let e = s.raw_frame(bad).unwrap_err();
        assert!(e.message.contains("likely cause: bad checksum"), "{e}");
        // The shell stays usable: the next request works.
        assert_eq!(d.read(&[op(d.as_ref(), "statusword")]).unwrap(), vec![Value::Int(0x4231)]);
    }

    #[test]
    fn read_only_write_through_the_low_level_path_gets_the_abort_in_words() {
        let mut d = sim("sim-servo:?id=1");
        let mut s = crate::servo::ops(d.as_mut()).unwrap();
        let e = s.write_raw(ObjRef::of(objects::named("statusword")), 1).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused);
        assert!(e.message.contains("16#06010002") && e.message.contains("read-only"), "{e}");
    }

    #[test]
    fn drives_on_a_named_simulated_line_share_it() {
        let clock = Clock::stepped();
        let open = |u: &str| open_sim(&DeviceUrl::parse(u).unwrap(), &clock).unwrap();
        let mut a = open("sim-servo:shared-test?id=1");
        let mut b = open("sim-servo:shared-test?id=2");
        let ids = crate::servo::ops(a.as_mut()).unwrap().simulator().unwrap().lock().unwrap().ids();
        assert_eq!(ids, vec![1, 2]);
        let cw = op(a.as_ref(), "controlword");
        b.write(&[(cw, Value::Int(0x0F))]).unwrap();
        let sw = op(a.as_ref(), "statusword");
        assert_eq!(a.read(&[sw]).unwrap()[0].as_i64() & 0x6F, 0x21, "drive 1 untouched");
        assert_eq!(b.read(&[sw]).unwrap()[0].as_i64() & 0x6F, 0x27, "drive 2 enabled");
        assert!(open_sim(&DeviceUrl::parse("sim-servo:shared-test?id=3&echo=1").unwrap(), &clock).is_err());
    }

    #[test]
    fn in_process_line_timing_strictness_and_their_url_errors() {
        let mut d = sim("sim-servo:?id=1&baud=38400&latency=2ms");
        let sw = op(d.as_ref(), "statusword");
        let t = Instant::now();
        d.read(&[sw]).unwrap();
        // Two frames at 38400 baud (5.2 ms) plus the 2 ms think-time.
        assert!(t.elapsed() >= Duration::from_micros(7_208), "{:?}", t.elapsed());
        let mut strict = sim("sim-servo:?id=1&strict=1");
        let e = crate::servo::ops(strict.as_mut())
            .unwrap()
            .raw_frame(Frame::write(1, 0x607A, 0, Size::B1, 5).to_bytes())
            .unwrap();
        assert_eq!(Frame::from_bytes(&e).unwrap().data, frame::abort::LENGTH_MISMATCH);
        let mut lenient = sim("sim-servo:?id=1");
        let ok = crate::servo::ops(lenient.as_mut())
            .unwrap()
            .raw_frame(Frame::write(1, 0x607A, 0, Size::B1, 5).to_bytes())
            .unwrap();
        assert_eq!(ok[1], frame::func::WRITE_OK);
        for bad in ["sim-servo:?strict=maybe", "sim-servo:?baud=0", "sim-servo:?latency=soon"] {
            assert!(open_sim(&DeviceUrl::parse(bad).unwrap(), &Clock::stepped()).is_err(), "{bad}");
        }
    }

    #[test]
    fn loop_mode_skips_the_echo() {
        let mut d = sim("sim-servo:?id=1&echo=1");
        assert_eq!(d.read(&[op(d.as_ref(), "statusword")]).unwrap(), vec![Value::Int(0x4231)]);
    }

    #[test]
    fn encoder_resolution_from_the_url_option_or_the_drive() {
        let mut d = sim("sim-servo:?id=1&encoder=65536");
        let tv = op(d.as_ref(), "target_velocity");
        assert_eq!(d.operands().value(&tv, "1rpm").unwrap(), Value::Int(17_896));
        d.set_option("encoder", "auto").unwrap();
        assert_eq!(d.operands().value(&tv, "1rpm").unwrap(), Value::Int(2731), "the simulator says 10000");
        assert!(d.set_option("encoder", "0").is_err());
        assert!(d.set_option("colour", "red").is_err());
    }

    #[test]
    fn over_a_pipe_with_the_served_simulator() {
        // The transport-generic path: the driver on one end of an in-process pipe, the
        // simulator's serve loop on the other.
        let (a, b) = crate::core::link::pipe::pair();
        let clock = Clock::stepped();
        let line = Arc::new(Mutex::new(SimLine::new(&[1], clock)));
        let stop = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let (l2, s2) = (line.clone(), stop.clone());
        let server = std::thread::spawn(move || {
            let mut b = b;
            serve::serve_line(&mut b, &l2, &s2, "pair")
        });
        let info = DeviceInfo { family: "servo", model: "test".into(), link: "pair".into(), simulated: false };
        let mut d = Driver::attach(link::private("pair", Box::new(a)), 1, false, Duration::from_secs(5), info);
        let sw = ObjRef::of(objects::named("statusword"));
        assert_eq!(d.read_obj(sw).unwrap(), 0x4231);
        d.timeout = Duration::from_millis(50);
        let e = d.read_obj(ObjRef { index: 0x3FFF, sub: 1, dtype: crate::core::DataType::Word }).unwrap_err();
        assert!(e.message.contains("unknown object"), "{e}");
        stop.store(true, std::sync::atomic::Ordering::Relaxed);
        server.join().unwrap().unwrap();
        drop(d);
    }
}
