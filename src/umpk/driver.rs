//! The UMPK driver: a [`Device`] speaking the terminal protocol (manual §4.1) and Intel HEX
//! programming (§4.2) over any byte transport — a serial port (`umpk:/dev/ttyUSB0`, default
//! 57600 8N1, §3.6), a pty served by `plcsh sim serve --umpk-pty`, or the in-process
//! simulator (`sim-umpk:UMPK16`, which therefore runs this same code).
//!
//! Rules it keeps:
//! - one command at a time, and never before the previous reply is complete (echo, reply
//!   and CR LF read to the end) — sending early is the manual's error 255;
//! - echo is detected on every exchange, not assumed: the first command at open finds the
//!   mode, and the `R` CR LF a reset or power-up sends (echo on again) is recognised;
//! - monitor packets already on their way when a command goes out are skipped (any
//!   command stops the monitor, §4.1.12);
//! - every refusal letter becomes a sentence ([`codec::letter_text`]), with what to try;
//! - bytes that are no reply (the tail of a monitor packet cut by the input flush, when
//!   someone else left the monitor running) are waited out until the line is quiet, and a
//!   command that changes nothing is asked once more.
//!
//! Reading operands: `I…` and `Q…` come from `?05FB`/`?06FA`; `T…`, `C…` and `M…` only from
//! the real-time monitor (one packet: start, read, stop). The terminal protocol has no
//! write commands, so `set` is refused with a message that says so.
//!
//! URL parameters: `baud` (57600), `timeout` (500ms), `model` (checked against the
//! controller's own report), `status_bits=W,H,R,E,P,T` (bit numbers of the status word,
//! default 5,4,3,2,1,0; [`codec::StatusLayout`]).
//!
//! The byte line is the transport layer's ([`crate::core::link`]): a port, a device server
//! (`umpk+tcp://`, `umpk+rfc2217://`) or an in-process pipe.

use super::codec::{
    self, parse_exchange, Command, Exchange, Info, Monitor, Progress, Reply, Shape, StatusLayout, Timing,
};
use super::hex::{self, Record};
use super::model::{self, Model};
use super::sim::{Umpk, RESET_TIME};
use super::space::{UmpkOperand, UmpkSpace};
use crate::core::link::line::Transport;
use crate::core::link::serial::{Carrier, LineSettings};
use crate::core::msg::Msg;
use crate::core::trace::{self, Dir, Proto};
use crate::core::url::DeviceUrl;
use crate::core::{Clock, Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::msg;
use std::collections::VecDeque;
use std::io;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Default reply timeout: the longest reply is 139 echoed bytes + 3 (a 64-byte page),
/// 25 ms at 57600 baud, plus a flash write.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(500);

/// The in-process transport: bytes go straight to a simulated UMPK.
pub struct SimLink {
    sim: Arc<Mutex<Umpk>>,
    rx: VecDeque<u8>,
}

impl SimLink {
    pub fn new(sim: Arc<Mutex<Umpk>>) -> SimLink {
        SimLink { sim, rx: VecDeque::new() }
    }
    fn lock(&self) -> std::sync::MutexGuard<'_, Umpk> {
        self.sim.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl Transport for SimLink {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.lock().receive(bytes);
        Ok(())
    }
    /// Returns what the simulator has sent by now, at once (the driver advances a stepped
    /// clock itself while it waits).
    fn recv(&mut self, buf: &mut [u8], _timeout: Duration) -> io::Result<usize> {
        if self.rx.is_empty() {
            let out = self.lock().take_all();
            self.rx.extend(out);
        }
        let n = buf.len().min(self.rx.len());
        for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.rx.clear();
        self.lock().take_all();
        Ok(())
    }
}

/// What `program` did.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ProgramReport {
    pub records: usize,
    pub pages: usize,
    pub bytes: usize,
    pub info: String,
    /// The controller was running a program (Work mode) when programming began: it stopped
    /// and its outputs went off.
    pub was_running: bool,
}

/// A UMPK on some transport.
pub struct Driver {
    info: DeviceInfo,
    space: UmpkSpace,
    t: Box<dyn Transport>,
    link: String,
    /// The echo mode last seen (`None` before the first exchange).
    pub echo: Option<bool>,
    pub layout: StatusLayout,
    /// Virtual time for the in-process simulator, the wall clock otherwise.
    clock: Clock,
    in_process: bool,
    sim: Option<Arc<Mutex<Umpk>>>,
    pub timeout: Duration,
    requests: u64,
    monitor_on: bool,
    rx: Vec<u8>,
    /// The controller sent a reset's `R` since this was last cleared.
    pub reset_seen: bool,
    /// The last exchange read bytes that were no reply (and the line was then let settle).
    garbled: bool,
}

impl Driver {
    /// A driver on `t` for `model` (until the controller says otherwise).
    pub fn attach(t: Box<dyn Transport>, link: &str, model: &'static Model, info: DeviceInfo) -> Driver {
        Driver {
            info,
            space: UmpkSpace { model },
            t,
            link: link.to_string(),
            echo: None,
            layout: StatusLayout::default(),
            clock: Clock::following(),
            in_process: false,
            sim: None,
            timeout: DEFAULT_TIMEOUT,
            requests: 0,
            monitor_on: false,
            rx: Vec::new(),
            reset_seen: false,
            garbled: false,
        }
    }

    pub fn model(&self) -> &'static Model {
        self.space.model
    }

    /// The simulated controller behind an in-process device.
    pub fn simulator(&self) -> Option<Arc<Mutex<Umpk>>> {
        self.sim.clone()
    }

    pub fn monitor_running(&self) -> bool {
        self.monitor_on
    }

    fn io_err(&self, e: io::Error) -> Error {
        Error::link(format!("serial I/O on {} failed", self.link)).cause(e)
    }

    /// Reads what arrives before `deadline` (clock time) into the buffer; false on timeout.
    fn fill(&mut self, deadline: Duration) -> Result<bool> {
        let mut buf = [0u8; 512];
        loop {
            let now = self.clock.now();
            if now >= deadline {
                return Ok(false);
            }
            let wait = (deadline - now).min(Duration::from_millis(50));
            let n = self.t.recv(&mut buf, wait).map_err(|e| self.io_err(e))?;
            if n > 0 {
                trace::frame_proto(&self.link, Proto::Umpk, Dir::Received, &buf[..n]);
                self.rx.extend_from_slice(&buf[..n]);
                return Ok(true);
            }
            if self.in_process {
                // The simulator answers in virtual time: let it pass.
                let never = std::sync::atomic::AtomicBool::new(false);
                self.clock.sleep(Duration::from_millis(1).min(deadline - now), &never);
            }
        }
    }

    /// Waits until the line has been quiet for 50 ms (after a confused exchange, so the
    /// next command does not start while the controller is still sending).
    fn settle(&mut self) {
        self.rx.clear();
        let mut quiet_until = self.clock.now() + Duration::from_millis(50);
        let give_up = self.clock.now() + Duration::from_secs(1);
        while self.clock.now() < give_up {
            match self.fill(quiet_until) {
                Ok(true) => {
                    self.rx.clear();
                    quiet_until = self.clock.now() + Duration::from_millis(50);
                }
                _ => break,
            }
        }
        self.rx.clear();
    }

    /// Sends `sent` and reads its whole exchange.
    pub fn exchange(&mut self, sent: &[u8], shape: Shape, crlf: Option<bool>, wait: Duration) -> Result<Exchange> {
        self.requests += 1;
        if !self.monitor_on {
            self.rx.clear();
            self.t.discard_input().map_err(|e| self.io_err(e))?;
        }
        trace::frame_proto(&self.link, Proto::Umpk, Dir::Sent, sent);
        self.t.send(sent).map_err(|e| self.io_err(e))?;
        let deadline = self.clock.now() + wait;
        loop {
            match parse_exchange(&self.rx, sent, shape, crlf) {
                Progress::NeedMore => {
                    if !self.fill(deadline)? {
                        let partial = codec::show(&self.rx);
                        self.rx.clear();
                        let (sent, link) = (codec::show(sent), &self.link);
                        let timeout = crate::core::literal::millis_text(wait);
                        let m = if partial.len() > 2 {
                            msg!(
                                "umpk-no-complete-reply-partial",
                                sent = sent,
                                link = link,
                                timeout = timeout,
                                partial = partial
                            )
                        } else {
                            msg!("umpk-no-complete-reply", sent = sent, link = link, timeout = timeout)
                        };
                        return Err(Error::link(m).hint(msg!("umpk-hint-silent")));
                    }
                }
                Progress::Done(x) => {
                    self.rx.drain(..x.consumed);
                    self.monitor_on = false;
                    if x.reset_seen {
                        self.reset_seen = true;
                    }
                    self.echo = Some(match crlf {
                        Some(on) => on,
                        None => x.echoed,
                    });
                    return Ok(x);
                }
                Progress::Bad(m) => {
                    self.settle();
                    self.garbled = true;
                    self.monitor_on = false;
                    return Err(Error::link(msg!(
                        "umpk-unexpected-reply",
                        sent = codec::show(sent),
                        link = &self.link,
                        what = m
                    ))
                    .hint(msg!("umpk-hint-garbled")));
                }
            }
        }
    }

    fn refused(&self, what: Msg, hint: Option<Msg>) -> Error {
        let e = Error::new(ErrorKind::Refused, what);
        match hint {
            Some(h) => e.hint(h),
            None => e,
        }
    }

    /// Runs one terminal command; a refusal letter is an error in words.
    pub fn command(&mut self, c: Command) -> Result<Reply> {
        let crlf = match c {
            Command::EchoOn | Command::Reset => Some(true),
            Command::EchoOff => Some(false),
            _ => None,
        };
        let wait = if c == Command::Reset { RESET_TIME + self.timeout } else { self.timeout };
        self.garbled = false;
        let x = match self.exchange(&c.encode(), c.shape(), crlf, wait) {
            // A monitor stream someone else started: our command stopped it, but the tail
            // of a packet cut by the input flush came first. The line is quiet now (the
            // exchange waited for that); a command that changes nothing is asked again.
            Err(_) if self.garbled && c.repeatable() => self.exchange(&c.encode(), c.shape(), crlf, wait)?,
            r => r?,
        };
        if c == Command::Reset {
            self.reset_seen = false;
        }
        match x.reply {
            Reply::Letter(l) => {
                let what = msg!(
                    "umpk-refused-command",
                    code = format!("{:02X}", c.code()),
                    command = c.name().text,
                    letter = codec::letter_text(l).text
                );
                let hint = match l {
                    b'U' if !c.in_programming() => Some(msg!("umpk-hint-programming-mode")),
                    b'E' | b'C' => Some(msg!("umpk-hint-corrupted")),
                    _ => None,
                };
                Err(self.refused(what, hint))
            }
            r => Ok(r),
        }
    }

    fn packet(&mut self, c: Command) -> Result<Vec<u8>> {
        match self.command(c)? {
            Reply::Packet(d) | Reply::Text(d) => Ok(d),
            r => Err(Error::link(msg!(
                "umpk-answered-other",
                reply = format!("{r:?}"),
                code = format!("{:02X}", c.code()),
                command = c.name().text
            ))),
        }
    }

    /// Controller info (§4.1.4).
    pub fn controller_info(&mut self) -> Result<Info> {
        let d = self.packet(Command::Info)?;
        Info::from_data(&d).ok_or_else(|| Error::link(msg!("umpk-packet-size", what = "info")))
    }

    /// The 22 program-info characters (§4.1.5; spaces in Wait mode).
    pub fn program_info(&mut self) -> Result<Vec<u8>> {
        self.packet(Command::ProgramInfo)
    }

    fn word(&mut self, c: Command) -> Result<u32> {
        let d = self.packet(c)?;
        Ok(u32::from_le_bytes(d.try_into().map_err(|_| Error::link(msg!("umpk-packet-size", what = "other")))?))
    }

    pub fn inputs(&mut self) -> Result<u32> {
        self.word(Command::Inputs)
    }

    pub fn outputs(&mut self) -> Result<u32> {
        self.word(Command::Outputs)
    }

    /// The error history, newest first (§4.1.8).
    pub fn errors(&mut self) -> Result<[u8; 8]> {
        let d = self.packet(Command::Errors)?;
        d.try_into().map_err(|_| Error::link(msg!("umpk-packet-size", what = "errors")))
    }

    pub fn clear_errors(&mut self) -> Result<()> {
        self.command(Command::ClearErrors).map(|_| ())
    }

    pub fn timing(&mut self) -> Result<Timing> {
        let d = self.packet(Command::Timing)?;
        Timing::from_data(&d).ok_or_else(|| Error::link(msg!("umpk-packet-size", what = "timing")))
    }

    /// Resets the controller and waits for its `R` (§4.1.1).
    pub fn reset(&mut self) -> Result<()> {
        self.command(Command::Reset).map(|_| ())
    }

    pub fn set_echo(&mut self, on: bool) -> Result<()> {
        self.command(if on { Command::EchoOn } else { Command::EchoOff }).map(|_| ())
    }

    /// Starts the real-time monitor (§4.1.11).
    pub fn monitor_start(&mut self) -> Result<()> {
        self.command(Command::MonitorStart)?;
        self.monitor_on = true;
        Ok(())
    }

    /// Stops it; packets still on their way are skipped.
    pub fn monitor_stop(&mut self) -> Result<()> {
        self.command(Command::MonitorStop).map(|_| ())
    }

    /// The next monitor packet, or `None` if none came within `wait`.
    pub fn monitor_next(&mut self, wait: Duration) -> Result<Option<Monitor>> {
        let deadline = self.clock.now() + wait;
        loop {
            match self.rx.iter().position(|&b| b == codec::MONITOR_HEADER) {
                None => self.rx.clear(),
                Some(p) => {
                    self.rx.drain(..p);
                    if self.rx.len() >= codec::MONITOR_LEN {
                        match Monitor::decode(&self.rx) {
                            Some(m) => {
                                self.rx.drain(..codec::MONITOR_LEN);
                                return Ok(Some(m));
                            }
                            None => {
                                self.rx.remove(0);
                                continue;
                            }
                        }
                    }
                }
            }
            if !self.fill(deadline)? {
                return Ok(None);
            }
        }
    }

    /// One monitor packet: from the running monitor, or by starting and stopping it.
    pub fn snapshot(&mut self) -> Result<Monitor> {
        let was_on = self.monitor_on;
        if !was_on {
            self.monitor_start()?;
        }
        let m = self.monitor_next(self.timeout);
        if !was_on {
            self.monitor_stop()?;
        }
        m?.ok_or_else(|| {
            Error::link(msg!(
                "umpk-no-monitor-packet",
                link = &self.link,
                timeout = crate::core::literal::millis_text(self.timeout)
            ))
        })
    }

    /// Sends a command or record as typed and returns the exchange (for `umpk send`).
    pub fn send_raw(&mut self, text: &str) -> Result<Exchange> {
        let bytes = text.trim().as_bytes().to_vec();
        if bytes.is_empty() || bytes.len() > 600 {
            return Err(Error::usage(msg!("umpk-send-empty")));
        }
        // A form the controller would wait on in silence is refused before it is sent: the
        // silence would be blamed on the cable.
        codec::check_form(&bytes).map_err(|m| Error::usage(msg!("umpk-not-sent", link = &self.link, reason = m)))?;
        let shape = match bytes.get(1..3).and_then(codec::hex_pair).and_then(Command::from_code) {
            Some(c) if bytes[0] == b'?' => c.shape(),
            _ => Shape::Ack,
        };
        let wait = if bytes == Command::Reset.encode() { RESET_TIME + self.timeout } else { self.timeout };
        self.exchange(&bytes, shape, None, wait)
    }

    /// Programs a validated file (§4.2): Programming mode, start, info, 64-byte pages, end;
    /// each record acknowledged before the next. `progress(done, total)` after each record.
    pub fn program(
        &mut self,
        prog: &hex::Program,
        info: Option<&[u8]>,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<ProgramReport> {
        let pages = hex::pages(prog);
        let info = info.map(<[u8]>::to_vec).or_else(|| prog.info.clone());
        let mut records = vec![Record::start()];
        if let Some(i) = &info {
            records.push(Record::info(i));
        }
        records.extend(pages.iter().cloned());
        records.push(Record::end());
        let word = self.controller_info()?.status;
        let status = self.layout.decode(word);
        if !status.programming {
            self.command(Command::Programming)?;
        }
        let total = records.len();
        for (k, r) in records.iter().enumerate() {
            let x = self.exchange(&r.encode(), Shape::Ack, None, self.timeout)?;
            match x.reply {
                Reply::Ok => progress(k + 1, total),
                Reply::Letter(l) => {
                    let record = match r.kind {
                        hex::kind::START => "start",
                        hex::kind::INFO => "info",
                        hex::kind::END => "end",
                        _ => "data",
                    };
                    let what = msg!(
                        "umpk-refused-record",
                        n = k + 1,
                        total = total,
                        record = record,
                        first = format!("{:04X}", r.offset),
                        last = format!("{:04X}", (r.offset as usize + r.data.len()).saturating_sub(1)),
                        letter = codec::letter_text(l).text
                    );
                    return Err(self.refused(what, None).hint(msg!("umpk-hint-program-incomplete")));
                }
                r => return Err(Error::link(msg!("umpk-answered-record", reply = format!("{r:?}")))),
            }
        }
        Ok(ProgramReport {
            records: total,
            pages: pages.len(),
            bytes: prog.bytes.len(),
            info: info.map(|i| String::from_utf8_lossy(&i).into_owned()).unwrap_or_default(),
            was_running: status.work,
        })
    }

    /// Finds the echo mode and the model: the first exchange at open.
    fn identify(&mut self, want: Option<&'static Model>) -> Result<()> {
        // A controller just powered up or reset is silent for ~0.6 s: wait that out too.
        let saved = self.timeout;
        self.timeout += RESET_TIME;
        let info = self.controller_info();
        self.timeout = saved;
        let info = info?;
        let found = model::from_info(info.model, info.inputs).ok_or_else(|| {
            Error::unsupported(msg!(
                "umpk-unknown-model-reported",
                model = format!("{:02X}", info.model),
                inputs = info.inputs,
                outputs = info.outputs,
                models = model::names()
            ))
        })?;
        if let Some(w) = want {
            if w.name != found.name {
                return Err(Error::usage(msg!("umpk-model-mismatch", given = w.name, found = found.name))
                    .hint(msg!("umpk-hint-model-mismatch", found = found.name)));
            }
        }
        self.space.model = found;
        self.info.model = found.name.to_string();
        Ok(())
    }
}

fn not_writable(op: &str) -> Error {
    Error::unsupported(msg!("umpk-not-writable", operand = op)).operand(op).hint(msg!("umpk-hint-not-writable"))
}

impl Device for Driver {
    fn info(&self) -> &DeviceInfo {
        &self.info
    }

    fn operands(&self) -> &dyn OperandSpace {
        &self.space
    }

    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        let parsed: Vec<UmpkOperand> = ops.iter().map(UmpkOperand::from_core).collect();
        let needs_monitor = parsed.iter().any(|o| o.area >= 2);
        let (mut inputs, mut outputs, mut mon) = (None, None, None);
        if needs_monitor {
            mon = Some(self.snapshot()?);
        }
        let mut out = Vec::with_capacity(ops.len());
        for o in parsed {
            let on = match (o.area().letter, &mon) {
                ('I', Some(m)) => m.inputs >> o.index & 1,
                ('Q', Some(m)) => m.outputs >> o.index & 1,
                ('T', Some(m)) => (m.timers >> o.index & 1) as u32,
                ('C', Some(m)) => (m.counters >> o.index & 1) as u32,
                ('M', Some(m)) => (m.markers >> o.index & 1) as u32,
                ('I', None) => {
                    let w = match inputs {
                        Some(w) => w,
                        None => *inputs.insert(self.inputs()?),
                    };
                    w >> o.index & 1
                }
                (_, None) => {
                    let w = match outputs {
                        Some(w) => w,
                        None => *outputs.insert(self.outputs()?),
                    };
                    w >> o.index & 1
                }
                _ => 0,
            };
            out.push(Value::Bool(on != 0));
        }
        Ok(out)
    }

    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        match items.first() {
            Some((op, _)) => Err(not_writable(&self.space.name(op))),
            None => Ok(()),
        }
    }

    fn requests(&self) -> u64 {
        self.requests
    }

    /// The controller's own operations (`umpk::ops`): the driver itself permits everything.
    fn family(&mut self, _changes: &[crate::core::device::Change]) -> Result<Option<&mut dyn std::any::Any>> {
        Ok(Some(self))
    }

    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        match key {
            "timeout" => {
                self.timeout = parse_timeout(value)?;
                Ok(())
            }
            "status_bits" => {
                self.layout = StatusLayout::parse(value).map_err(Error::usage)?;
                Ok(())
            }
            _ => Err(Error::usage(msg!("umpk-no-option", key = key)).hint(msg!("umpk-hint-options"))),
        }
    }
}

fn parse_timeout(v: &str) -> Result<Duration> {
    crate::core::literal::parse_timeout(v).map_err(Error::usage)
}

fn model_param(u: &DeviceUrl, text: Option<&str>) -> Result<Option<&'static Model>> {
    text.filter(|t| !t.is_empty())
        .map(|t| {
            model::find(t).ok_or_else(|| {
                Error::usage(msg!("umpk-not-model", model = t, url = &u.text))
                    .hint(msg!("umpk-hint-models", models = model::names()))
            })
        })
        .transpose()
}

fn options(d: &mut Driver, u: &DeviceUrl) -> Result<()> {
    for key in ["timeout", "status_bits"] {
        if let Some(v) = u.param(key) {
            d.set_option(key, v)?;
        }
    }
    Ok(())
}

/// The URL parameters of a UMPK on a serial line (`umpk:`) and of the simulator (`sim-umpk:`).
pub const SERIAL_PARAMS: &[&str] = &["baud", "timeout", "model", "status_bits"];
pub const SIM_PARAMS: &[&str] = &["model", "timeout", "status_bits", "state", "program"];

/// Opens `umpk:/dev/ttyUSB0?baud=57600&timeout=500ms&model=UMPK16&status_bits=5,4,3,2,1,0`
/// (or `umpk:COM5`, `umpk+tcp://HOST:PORT`, `umpk+rfc2217://HOST:PORT`).
pub fn open_serial(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(SERIAL_PARAMS)?;
    let carrier = Carrier::from_url(u, "umpk:COM5 or umpk:/dev/ttyUSB0")?;
    let want = model_param(u, u.param("model"))?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(codec::BAUD);
    if baud == 0 {
        return Err(Error::usage(msg!("umpk-baud-zero", url = &u.text)));
    }
    let line = LineSettings::n81(baud);
    let t = crate::core::link::serial::open(&carrier, line)?;
    let m = want.unwrap_or(&model::MODELS[1]);
    let info = DeviceInfo {
        family: "umpk",
        model: m.name.into(),
        link: format!("{} ({line})", carrier.key()),
        simulated: false,
    };
    let mut d = Driver::attach(t, &carrier.key(), m, info);
    options(&mut d, u)?;
    d.identify(want)?;
    Ok(Box::new(d))
}

/// Opens `sim-umpk:UMPK16?status_bits=…&state=FILE&program=FILE.il`: the in-process
/// simulator on the session's clock (`state` keeps its flash, as `--umpk-state` does for
/// the served one; `program` loads an IL lab program, as `sim program load` does).
pub fn open_sim(u: &DeviceUrl, clock: &Clock) -> Result<Box<dyn Device>> {
    u.expect_params(SIM_PARAMS)?;
    let m = model_param(u, u.param("model").or(Some(u.target.as_str())))?.unwrap_or(&model::MODELS[1]);
    let mut sim = Umpk::new(m, clock.clone());
    if let Some(v) = u.param("status_bits") {
        sim.layout = StatusLayout::parse(v).map_err(Error::usage)?;
    }
    if let Some(p) = u.param("state") {
        sim.open_state(std::path::Path::new(p))?;
    }
    if let Some(p) = u.param("program") {
        let text = crate::core::encoding::read_source(p).map_err(|e| {
            Error::io(msg!("umpk-cannot-read-program", url = &u.text, file = p, reason = e.to_string()))
        })?;
        sim.load_logic(Box::new(super::sim::program::IlRunner::load(&text, p, m)?));
    }
    let sim = Arc::new(Mutex::new(sim));
    let info = DeviceInfo { family: "umpk", model: m.name.into(), link: u.text.clone(), simulated: true };
    let mut d = Driver::attach(Box::new(SimLink::new(sim.clone())), "sim-umpk", m, info);
    d.clock = clock.clone();
    d.in_process = true;
    d.sim = Some(sim);
    options(&mut d, u)?;
    d.identify(Some(m))?;
    Ok(Box::new(d))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sim(url: &str) -> Box<dyn Device> {
        open_sim(&DeviceUrl::parse(url).unwrap(), &Clock::stepped()).unwrap()
    }

    fn drv(d: &mut Box<dyn Device>) -> &mut Driver {
        crate::umpk::ops(d.as_mut(), &[]).unwrap().unwrap()
    }

    #[test]
    fn in_process_commands_go_through_the_codec() {
        let mut d = sim("sim-umpk:UMPK8");
        assert_eq!(d.info().model, "UMPK8");
        let u = drv(&mut d);
        assert_eq!(u.echo, Some(true));
        let i = u.controller_info().unwrap();
        assert_eq!((i.inputs, i.outputs, i.version.to_string()), (8, 4, "1.2B".to_string()));
        assert_eq!(u.program_info().unwrap(), vec![b' '; 22]);
        u.set_echo(false).unwrap();
        assert_eq!(u.echo, Some(false));
        assert_eq!(u.errors().unwrap(), [0; 8]);
        u.reset().unwrap();
        assert_eq!(u.echo, Some(true), "a reset turns echo on");
        assert!((u.timing().unwrap().firmware_us() - 271.0).abs() < 1e-9);
    }

    #[test]
    fn operands_read_from_commands_and_the_monitor_and_set_is_refused() {
        let mut d = sim("sim-umpk:UMPK16");
        drv(&mut d).simulator().unwrap().lock().unwrap().set_input(3, true);
        let ops: Vec<Operand> =
            ["I3", "I2", "Q0", "M5", "T0", "C3"].iter().map(|t| d.operands().parse(t).unwrap()[0]).collect();
        let v = d.read(&ops[..3]).unwrap();
        assert_eq!(v, vec![Value::Bool(true), Value::Bool(false), Value::Bool(false)]);
        let v = d.read(&ops).unwrap();
        assert_eq!(v[0], Value::Bool(true), "from the monitor too");
        assert!(!drv(&mut d).monitor_running(), "the snapshot stopped the monitor");
        let e = d.write(&[(ops[2], Value::Bool(true))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unsupported);
        assert!(e.message.contains("no write commands"), "{e}");
        assert!(sim("sim-umpk:UMPK8").operands().parse("I8").is_err());
    }

    #[test]
    fn refusals_in_programming_mode_are_explained() {
        let mut d = sim("sim-umpk:UMPK16");
        let u = drv(&mut d);
        u.command(Command::Programming).unwrap();
        let e = u.inputs().unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused);
        assert!(e.message.contains("U: unknown command"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("umpk reset"));
        u.reset().unwrap();
        assert_eq!(u.inputs().unwrap(), 0);
    }

    #[test]
    fn programming_and_each_refusal_in_words() {
        let mut d = sim("sim-umpk:UMPK16");
        let u = drv(&mut d);
        let text = format!(
            "{}\n{}\n:00000001FF\n",
            String::from_utf8(Record::data(0, &[0x5A; 16]).encode()).unwrap(),
            String::from_utf8(Record::data(0x90, &[0xA5; 16]).encode()).unwrap()
        );
        let p = hex::parse_file(&text, u.model().program_bytes).unwrap();
        let mut seen = Vec::new();
        let r = u.program(&p, Some(b"LAB1"), &mut |k, n| seen.push((k, n))).unwrap();
        assert_eq!((r.records, r.pages, r.bytes), (5, 2, 32));
        assert_eq!(seen.last(), Some(&(5, 5)));
        u.reset().unwrap();
        assert_eq!(&u.program_info().unwrap()[..4], b"LAB1");
        let sim = u.simulator().unwrap();
        sim.lock().unwrap().fail_flash_page(Some(2)).unwrap();
        let e = u.program(&p, None, &mut |_, _| {}).unwrap_err();
        assert!(e.message.contains("record 3 of 4") && e.message.contains("W: the flash (IAP) write failed"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("again from the start"));
        for (raw, letter) in [(":00000001FE", "E: checksum"), (":0100000000FF", "X: programming is not allowed")] {
            let x = u.send_raw(raw).unwrap();
            let Reply::Letter(l) = x.reply else { panic!("{raw}: {:?}", x.reply) };
            assert!(codec::letter_text(l).starts_with(letter), "{raw}");
        }
    }

    /// A transport that puts `junk` in front of the first thing the controller sends after
    /// the first command (arriving after the driver flushed its input).
    struct Junk(SimLink, Vec<u8>, bool);

    impl Transport for Junk {
        fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
            self.2 = true;
            self.0.send(bytes)
        }
        fn recv(&mut self, buf: &mut [u8], t: Duration) -> io::Result<usize> {
            if self.2 && !self.1.is_empty() {
                let n = self.1.len().min(buf.len());
                buf[..n].copy_from_slice(&self.1[..n]);
                self.1.drain(..n);
                return Ok(n);
            }
            self.0.recv(buf, t)
        }
    }

    #[test]
    fn a_garbled_reply_is_waited_out_and_a_repeatable_command_asked_again() {
        let clock = Clock::stepped();
        let sim = Arc::new(Mutex::new(Umpk::new(&model::MODELS[1], clock.clone())));
        // The last 12 bytes of a monitor packet: no reply starts like that.
        let tail = codec::Monitor::default().encode()[18..].to_vec();
        let info = DeviceInfo { family: "umpk", model: "UMPK16".into(), link: "junk".into(), simulated: true };
        let mut d = Driver::attach(
            Box::new(Junk(SimLink::new(sim.clone()), tail.clone(), false)),
            "junk",
            &model::MODELS[1],
            info,
        );
        d.clock = clock.clone();
        d.in_process = true;
        assert_eq!(d.controller_info().unwrap().inputs, 16);
        assert_eq!(d.requests, 2, "asked twice");
        // A command that changes something is not repeated: the error is reported.
        let mut d = Driver::attach(
            Box::new(Junk(SimLink::new(sim), tail, false)),
            "junk",
            &model::MODELS[1],
            DeviceInfo { family: "umpk", model: "UMPK16".into(), link: "junk".into(), simulated: true },
        );
        d.clock = clock;
        d.in_process = true;
        let e = d.clear_errors().unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(e.message.contains("unexpected reply"), "{e}");
        assert_eq!(d.requests, 1);
    }

    /// A line where nothing answers.
    struct Deaf;

    impl Transport for Deaf {
        fn send(&mut self, _: &[u8]) -> io::Result<()> {
            Ok(())
        }
        fn recv(&mut self, _: &mut [u8], _: Duration) -> io::Result<usize> {
            Ok(0)
        }
    }

    #[test]
    fn a_no_reply_message_keeps_the_timeout_the_user_gave() {
        let info = DeviceInfo { family: "umpk", model: "UMPK16".into(), link: "deaf".into(), simulated: true };
        let mut d = Driver::attach(Box::new(Deaf), "deaf", &model::MODELS[1], info);
        d.clock = Clock::stepped();
        d.in_process = true;
        for (given, shown) in [("2.5", "within 2.5 ms"), ("40ms", "within 40 ms"), ("0.25s", "within 250 ms")] {
            d.set_option("timeout", given).unwrap();
            let e = d.controller_info().unwrap_err();
            assert!(e.message.contains("no complete reply") && e.message.contains(shown), "{given}: {e}");
            // With the monitor on (as `umpk monitor` leaves it), no packet comes either.
            d.monitor_on = true;
            let e = d.snapshot().unwrap_err();
            d.monitor_on = false;
            assert!(e.message.contains("no real-time monitor packet") && e.message.contains(shown), "{given}: {e}");
        }
    }

    #[test]
    fn monitor_rate_in_virtual_time() {
        let clock = Clock::stepped();
        let mut d = open_sim(&DeviceUrl::parse("sim-umpk:UMPK16").unwrap(), &clock).unwrap();
        let u = drv(&mut d);
        u.monitor_start().unwrap();
        let t0 = clock.now();
        let mut n = 0;
        while clock.now() - t0 < Duration::from_secs(1) {
            if u.monitor_next(Duration::from_millis(100)).unwrap().is_some() {
                n += 1;
            }
        }
        assert!((99..=101).contains(&n), "{n} packets in one virtual second");
        u.monitor_stop().unwrap();
        assert!(u.monitor_next(Duration::from_millis(100)).unwrap().is_none(), "stopped");
    }
}
