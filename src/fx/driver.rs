//! The FX drivers: one [`Device`] that speaks either the programming-port protocol
//! (`fx:/dev/ttyUSB0`, 9600 7E1) or the computer link (`fxlink:/dev/ttyUSB0?station=0&pc=FF&wait=0`)
//! over any [`Transport`] — a serial port, a pty served by `plcsh sim serve`, or the
//! in-process simulator (`sim-fx:FX2N`, which therefore runs this same code).
//!
//! - Programming port: the ENQ/ACK handshake opens the conversation (and reopens it after a
//!   failure); reads coalesce into the fewest frames of at most 64 bytes within one region
//!   of the address table; words are written with command 1 (adjacent words in one frame),
//!   bits are forced ON/OFF (commands 7/8), a `Kn` group that covers whole bytes is written
//!   as bytes and any other group bit by bit — never a read-modify-write of the PLC's bytes.
//! - Computer link: bits read with BR (≤ 256 points a frame), words with WR (≤ 64); writes
//!   with BW and WW, and WT when single words at scattered devices are written together.
//! - A NAK or a reply with a bad sum check is retried up to three times (the seed's host
//!   program: "如重复3次仍不行则显示错误信息"), then reported: NAK as the PLC refusing
//!   (kind `refused`, the link's error code in words), a bad sum as a link error. On the
//!   link only NAKs that a resend can cure (sum check 02, protocol 03) are retried.
//!   Silence is reported at once with what to check.
//!
//! URL parameters: `model` (FX2N), `timeout` (500ms), `retries` (3); `fx:` `baud` (9600);
//! `fxlink:` `station` (0), `pc` (FF), `wait` (0–15, ×10 ms), `baud` (9600), `bits` (7),
//! `parity` (e/o/n), `stop` (1/2), `sum` (1), `format` (1 or 4), `xy` (octal, or decimal for
//! a PLC that numbers X/Y in link frames as the seed literally says). `sim-fx:MODEL` takes
//! `protocol=port|link`, the link's `station`/`sum`/`format`, and `share=NAME`: devices with
//! one share name use one simulated PLC (the port and the link of one PLC).

use super::link::{self as fxlink, Cmd, Dev, Header, Reply, Settings};
use super::memory::Memory;
use super::model::Model;
use super::operand::{Area, FxOperand, Width, CN32_FIRST};
use super::port::{self, Request, ACK, ENQ, NAK};
use super::sim::{LinkServer, Plc, PortServer, Server, SimLink};
use super::space::{FxSpace, Proto};
use crate::core::trace::{self, Dir};
use crate::core::url::DeviceUrl;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::servo::link::{self as lines, SharedLine, Transport};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, Weak};
use std::time::{Duration, Instant};

/// Default reply timeout: a 64-byte read reply is 132 characters, 138 ms at 9600 baud.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(500);
/// Resends after a NAK or a bad sum check (seed 004: three).
pub const DEFAULT_RETRIES: u32 = 3;

/// What came back for one frame.
enum Got {
    Data(Vec<u8>),
    Ack,
    Nak(Option<u8>),
    BadSum(String),
    Silent(Vec<u8>),
}

/// Protocol state.
enum Mode {
    Port { synced: bool },
    Link { header: Header, settings: Settings },
}

/// An FX PLC on some transport.
pub struct Driver {
    info: DeviceInfo,
    space: FxSpace,
    line: SharedLine,
    mode: Mode,
    timeout: Duration,
    retries: u32,
    requests: u64,
    /// Frames resent after a NAK or a bad sum.
    pub resent: u64,
}

impl Driver {
    /// A programming-port driver on `line`.
    pub fn port(line: SharedLine, model: &'static Model, info: DeviceInfo) -> Driver {
        Driver::new(line, FxSpace::new(model, Proto::Port), Mode::Port { synced: false }, info)
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
        Driver { info, space, line, mode, timeout: DEFAULT_TIMEOUT, retries: DEFAULT_RETRIES, requests: 0, resent: 0 }
    }

    /// Collects bytes until `complete` says how long the reply is, or the deadline passes.
    fn collect(
        t: &mut dyn Transport,
        deadline: Instant,
        complete: &dyn Fn(&[u8]) -> Option<usize>,
    ) -> std::io::Result<Vec<u8>> {
        let mut got = Vec::new();
        let mut buf = [0u8; 256];
        loop {
            if let Some(n) = complete(&got) {
                got.truncate(n);
                return Ok(got);
            }
            let left = deadline.saturating_duration_since(Instant::now());
            let k = t.recv(&mut buf, left)?;
            if k == 0 {
                return Ok(got);
            }
            got.extend_from_slice(&buf[..k]);
        }
    }

    fn io_err(&self, e: std::io::Error) -> Error {
        Error::link(format!("serial I/O on {} failed", self.line.name)).cause(e)
    }

    /// The ENQ/ACK handshake (programming port).
    fn enq(&mut self) -> Result<()> {
        let name = self.line.name.clone();
        for _ in 0..=self.retries {
            let mut t = self.line.transport.lock().unwrap_or_else(|p| p.into_inner());
            t.discard_input().map_err(|e| self.io_err(e))?;
            trace::frame(&name, Dir::Sent, &[ENQ]);
            t.send(&[ENQ]).map_err(|e| self.io_err(e))?;
            let got = Self::collect(t.as_mut(), Instant::now() + self.timeout, &|b| (!b.is_empty()).then_some(1))
                .map_err(|e| self.io_err(e))?;
            drop(t);
            if !got.is_empty() {
                trace::frame(&name, Dir::Received, &got);
            }
            match got.first() {
                Some(&ACK) => {
                    self.mode = Mode::Port { synced: true };
                    return Ok(());
                }
                Some(_) => continue,
                None => {
                    return Err(Error::link(format!("no ACK to ENQ on {name} within {} ms", self.timeout.as_millis()))
                        .hint(
                            "check the cable and converter, that this is the PLC's programming port, and 9600 baud 7E1",
                        ))
                }
            }
        }
        Err(Error::link(format!("the PLC answered ENQ with NAK {} times on {name}", self.retries + 1))
            .hint("another program may be talking to the programming port"))
    }

    /// Sends one frame and reads its reply (one attempt).
    fn attempt(&mut self, frame: &[u8], expect: usize) -> Result<Got> {
        self.requests += 1;
        let name = self.line.name.clone();
        let mut t = self.line.transport.lock().unwrap_or_else(|p| p.into_inner());
        t.discard_input().map_err(|e| self.io_err(e))?;
        trace::frame(&name, Dir::Sent, frame);
        t.send(frame).map_err(|e| self.io_err(e))?;
        let deadline = Instant::now() + self.timeout;
        let got = match &self.mode {
            Mode::Port { .. } => Self::collect(t.as_mut(), deadline, &|b: &[u8]| match b.first() {
                None => None,
                Some(&NAK) | Some(&ACK) => Some(1),
                Some(_) => (b.len() >= expect).then_some(expect),
            }),
            Mode::Link { settings, .. } => {
                let s = *settings;
                Self::collect(t.as_mut(), deadline, &move |b: &[u8]| fxlink::reply_len(b, s))
            }
        }
        .map_err(|e| self.io_err(e))?;
        drop(t);
        if !got.is_empty() {
            trace::frame(&name, Dir::Received, &got);
        }
        Ok(match &self.mode {
            Mode::Port { .. } => match got.first() {
                None => Got::Silent(got),
                Some(&NAK) => Got::Nak(None),
                Some(&ACK) if expect == 1 => Got::Ack,
                Some(_) if expect == 1 => Got::BadSum(format!("unexpected reply {}", trace::hex_bytes(&got))),
                Some(_) => match port::decode_read_reply(&got, (expect - 4) / 2) {
                    Ok(d) => Got::Data(d),
                    Err(port::FrameError::BadSum { got: g, want }) => {
                        Got::BadSum(format!("sum check {g:02X}, the characters add up to {want:02X}"))
                    }
                    Err(port::FrameError::Malformed(_)) if got.len() < expect => Got::Silent(got),
                    Err(port::FrameError::Malformed(m)) => Got::BadSum(m.to_string()),
                },
            },
            Mode::Link { header, settings } => {
                if got.is_empty() || fxlink::reply_len(&got, *settings).is_none() {
                    Got::Silent(got)
                } else {
                    match fxlink::decode_reply(&got, *header, *settings) {
                        Ok(Reply::Data(d)) => Got::Data(d),
                        Ok(Reply::Ack) => Got::Ack,
                        Ok(Reply::Nak(c)) => Got::Nak(Some(c)),
                        Err(fxlink::ReplyError::BadSum { got: g, want }) => {
                            Got::BadSum(format!("sum check {g:02X}, the characters add up to {want:02X}"))
                        }
                        Err(fxlink::ReplyError::Malformed(m)) => Got::BadSum(m.to_string()),
                    }
                }
            }
        })
    }

    /// One exchange with retries: returns data (reads) or nothing (writes).
    fn transact(&mut self, frame: &[u8], expect: usize, what: &str) -> Result<Vec<u8>> {
        let mut last = String::new();
        let mut nak = None;
        for attempt in 0..=self.retries {
            if attempt > 0 {
                self.resent += 1;
            }
            if let Mode::Port { synced: false } = self.mode {
                self.enq()?;
            }
            match self.attempt(frame, expect)? {
                Got::Data(d) => return Ok(d),
                Got::Ack => return Ok(Vec::new()),
                Got::Nak(code) => {
                    nak = Some(code);
                    last = "NAK".into();
                    if let Some(c) = code {
                        if c != fxlink::code::SUM && c != fxlink::code::PROTOCOL {
                            break; // a resend cannot cure it
                        }
                    }
                }
                Got::BadSum(m) => {
                    nak = None;
                    last = m;
                    if let Mode::Port { .. } = self.mode {
                        self.mode = Mode::Port { synced: false };
                    }
                }
                Got::Silent(partial) => {
                    if let Mode::Port { .. } = self.mode {
                        self.mode = Mode::Port { synced: false };
                    }
                    let tail = if partial.is_empty() {
                        String::new()
                    } else {
                        format!(" (only {} came back)", trace::hex_bytes(&partial))
                    };
                    return Err(Error::link(format!(
                        "no reply to {what} within {} ms on {}{tail}",
                        self.timeout.as_millis(),
                        self.line.name
                    ))
                    .hint(self.silence_hint()));
                }
            }
        }
        let tries = self.requests_for_message();
        match nak {
            Some(None) => Err(Error::new(
                ErrorKind::Refused,
                format!("the PLC answered NAK to {what} ({tries}): it refuses a frame with a wrong sum check or an address where it has no device"),
            )
            .hint("check the operand against the model (`help OPERAND`) and the line's noise")),
            Some(Some(c)) => Err(Error::new(
                ErrorKind::Refused,
                format!("the PLC answered NAK {c:02X}H to {what}: {}", fxlink::nak_text(c)),
            )),
            None => Err(Error::link(format!("bad reply to {what} ({tries}): {last}"))
                .hint("noise on the line or a wrong baud rate/parity (the port runs 7E1)")),
        }
    }

    fn requests_for_message(&self) -> String {
        format!("{} attempts", self.retries + 1)
    }

    fn silence_hint(&self) -> String {
        match &self.mode {
            Mode::Port { .. } => "check the cable, 9600 baud 7E1, and that this is the programming port".into(),
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
        let regions = port::regions();
        let places: Vec<port::Place> = ops
            .iter()
            .map(|o| {
                port::place(o)
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
            let req = Request::Read { addr: *s, count };
            let bytes =
                self.transact(&req.encode(), req.reply_len(), &format!("a read of {count} bytes at {s:04X}H"))?;
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
        let mut frames: Vec<(Request, String)> = Vec::new();
        for (o, v) in items {
            let raw = o.view.encode(v) as u64;
            let p = port::place(o)
                .ok_or_else(|| Error::new(ErrorKind::Range, "past the address table").operand(o.canonical()))?;
            match o.width {
                Width::Bit => {
                    let addr = port::force_address(o.area, o.index).ok_or_else(|| read_only(o))?;
                    frames.push((
                        Request::Force { on: raw != 0, addr },
                        format!("forcing {} {}", o.canonical(), on_off(raw)),
                    ));
                }
                Width::Group(n) if p.bit == 0 && (4 * n) % 8 == 0 => {
                    let data: Vec<u8> = (0..p.len).map(|i| (raw >> (8 * i)) as u8).collect();
                    push_write(&mut frames, p.addr, data, o);
                }
                Width::Group(n) => {
                    for i in 0..4 * n as u16 {
                        let addr = port::force_address(o.area, o.index + i).ok_or_else(|| read_only(o))?;
                        let bit = raw >> i & 1;
                        frames.push((
                            Request::Force { on: bit != 0, addr },
                            format!("forcing {} bit {i}", o.canonical()),
                        ));
                    }
                }
                Width::Word | Width::Pair => {
                    let data: Vec<u8> = (0..p.len).map(|i| (raw >> (8 * i)) as u8).collect();
                    push_write(&mut frames, p.addr, data, o);
                }
            }
        }
        for (req, what) in frames {
            self.transact(&req.encode(), 1, &what)?;
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
            let d = self.transact(&frame, 0, &what)?;
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
            self.transact(&frame, 0, &what)?;
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

fn push_write(frames: &mut Vec<(Request, String)>, addr: u16, data: Vec<u8>, o: &FxOperand) {
    if let Some((Request::Write { addr: a, data: d }, what)) = frames.last_mut() {
        if *a as usize + d.len() == addr as usize && d.len() + data.len() <= port::MAX_BYTES {
            d.extend(data);
            *what = format!("a write of {} bytes at {a:04X}H", d.len());
            return;
        }
    }
    frames.push((Request::Write { addr, data }, format!("a write of {}", o.canonical())));
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

    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        match key {
            "timeout" => self.timeout = parse_timeout(value)?,
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

/// Opens a serial port with the given character format.
fn open_serial(path: &str, baud: u32, bits: u8, parity: char, stop: u8) -> Result<Box<dyn Transport>> {
    let port = serialport::new(path, baud)
        .data_bits(if bits == 8 { serialport::DataBits::Eight } else { serialport::DataBits::Seven })
        .parity(match parity {
            'o' => serialport::Parity::Odd,
            'n' => serialport::Parity::None,
            _ => serialport::Parity::Even,
        })
        .stop_bits(if stop == 2 { serialport::StopBits::Two } else { serialport::StopBits::One })
        .flow_control(serialport::FlowControl::None)
        .timeout(Duration::from_millis(100))
        .open_native()
        .map_err(|e| {
            Error::link(format!("cannot open serial port {path}"))
                .cause(e)
                .hint("check the path (ls /dev/ttyUSB* /dev/ttyS*), that your user may open it (group dialout) and that no other program holds it")
        })?;
    Ok(Box::new(lines::Serial(port)))
}

/// Opens `fx:PORT?baud=9600&model=FX2N&timeout=500ms&retries=3`: the programming port, 7E1.
pub fn open_port(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(&["baud", "model", "timeout", "retries"])?;
    if u.target.is_empty() {
        return Err(Error::usage(format!("{} names no serial port", u.text)).hint("e.g. fx:/dev/ttyUSB0"));
    }
    let model = model_of(u, None)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(9600);
    let settings = format!("{baud} 7E1");
    let line = lines::shared(&u.target, &settings, || open_serial(&u.target, baud, 7, 'e', 1))?;
    let info = DeviceInfo {
        family: "fx",
        model: format!("{} (programming port)", model.name),
        link: format!("{} ({settings})", u.target),
        simulated: false,
    };
    finish(Driver::port(line, model, info), u)
}

/// Opens `fxlink:PORT?station=0&pc=FF&wait=0&baud=9600&bits=7&parity=e&stop=1&sum=1&format=1`.
pub fn open_link(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(&[
        "station", "pc", "wait", "baud", "bits", "parity", "stop", "sum", "format", "xy", "model", "timeout", "retries",
    ])?;
    if u.target.is_empty() {
        return Err(Error::usage(format!("{} names no serial port", u.text)).hint("e.g. fxlink:/dev/ttyUSB0?station=0"));
    }
    let model = model_of(u, None)?;
    let header = Header {
        station: hex_param(u, "station", 0, 31)?,
        pc: hex_param(u, "pc", 0xFF, 0xFF)?,
        wait: hex_param(u, "wait", 0, 15)?,
    };
    let settings = link_settings(u)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(9600);
    let bits = u.param_num::<u8>("bits")?.unwrap_or(7);
    let parity = u.param("parity").unwrap_or("e").to_ascii_lowercase().chars().next().unwrap_or('e');
    let stop = u.param_num::<u8>("stop")?.unwrap_or(1);
    if !matches!(bits, 7 | 8) || !matches!(parity, 'e' | 'o' | 'n') || !matches!(stop, 1 | 2) {
        return Err(Error::usage(format!("{}: bits=7|8, parity=e|o|n, stop=1|2", u.text)));
    }
    let line_settings = format!("{baud} {bits}{}{stop}", parity.to_ascii_uppercase());
    let line = lines::shared(&u.target, &line_settings, || open_serial(&u.target, baud, bits, parity, stop))?;
    let info = DeviceInfo {
        family: "fx",
        model: format!("{} (computer link, station {})", model.name, header.station),
        link: format!(
            "{} ({line_settings}, format {}, sum {})",
            u.target,
            if settings.format4 { 4 } else { 1 },
            if settings.sum { "on" } else { "off" }
        ),
        simulated: false,
    };
    finish(Driver::link(line, model, header, settings, info), u)
}

fn shared_plcs() -> &'static Mutex<HashMap<String, Weak<Mutex<Memory>>>> {
    static R: OnceLock<Mutex<HashMap<String, Weak<Mutex<Memory>>>>> = OnceLock::new();
    R.get_or_init(|| Mutex::new(HashMap::new()))
}

/// A simulated PLC's memory, shared under `share` when given.
pub fn sim_plc(model: &'static Model, share: Option<&str>) -> Result<Plc> {
    let Some(name) = share else { return Ok(Arc::new(Mutex::new(Memory::new(model)))) };
    let mut reg = shared_plcs().lock().unwrap_or_else(|p| p.into_inner());
    reg.retain(|_, w| w.strong_count() > 0);
    if let Some(p) = reg.get(name).and_then(Weak::upgrade) {
        let m = p.lock().unwrap_or_else(|e| e.into_inner()).model.name;
        if m != model.name {
            return Err(Error::usage(format!("simulated PLC `{name}` is an {m}, not an {}", model.name)));
        }
        return Ok(p);
    }
    let p = Arc::new(Mutex::new(Memory::new(model)));
    reg.insert(name.to_string(), Arc::downgrade(&p));
    Ok(p)
}

/// Opens `sim-fx:MODEL?protocol=port|link&station=0&sum=1&format=1&share=NAME`.
pub fn open_sim(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(&[
        "model", "protocol", "station", "pc", "wait", "sum", "format", "xy", "share", "timeout", "retries",
    ])?;
    let model = model_of(u, Some(if u.target.is_empty() { "FX2N" } else { &u.target }))?;
    let plc = sim_plc(model, u.param("share"))?;
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
    finish(d, u)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io;

    fn sim(url: &str) -> Box<dyn Device> {
        open_sim(&DeviceUrl::parse(url).unwrap()).unwrap_or_else(|e| panic!("{url}: {e}"))
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
        for url in ["sim-fx:FX2N", "sim-fx:FX2N?protocol=link"] {
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
            set(d, "K4M0", 0xA5F0);
            assert_eq!(get(d, "M4"), 1);
            assert_eq!(get(d, "M0"), 0);
            assert_eq!(get(d, "K4M0"), 0xA5F0);
            assert_eq!(get(d, "K1M4"), 0xF, "K1 is 4 bits");
            assert_eq!(get(d, "K3M0"), 0x5F0, "M12–M15 are on, but a K3 group's high bits are zero");
            assert_eq!(get(d, "K4M0/INT"), 0xA5F0 - 0x10000, "a full K4 group may be negative");
            assert_eq!(get(d, "K8M0"), 0xA5F0, "K8 in 32 bits: M16–M31 are off");
            set(d, "K2M3", 0xFF);
            assert_eq!(get(d, "K4M0"), 0xA5F0 | 0x7F8, "an unaligned group writes exactly its bits");
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
        assert!(open_sim(&DeviceUrl::parse("sim-fx:FX2N?protocol=link&xy=hex").unwrap()).is_err());
    }

    #[test]
    fn both_ports_share_one_plc() {
        let mut a = sim("sim-fx:FX1N?share=unit-test-a");
        let mut b = sim("sim-fx:FX1N?protocol=link&share=unit-test-a");
        set(a.as_mut(), "D5", 77);
        assert_eq!(get(b.as_mut(), "D5"), 77);
        set(b.as_mut(), "D1000", 9); // only the link reaches it
        assert!(a.operands().parse("D1000").is_err());
        assert!(open_sim(&DeviceUrl::parse("sim-fx:FX2N?share=unit-test-a").unwrap()).is_err(), "model differs");
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
        let plc = sim_plc(model, None).unwrap();
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
        let plc = sim_plc(Model::find("FX1S").unwrap(), None).unwrap();
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
        let plc = sim_plc(model, None).unwrap();
        let s = Settings::default();
        let line = lines::private("one-station", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
        let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
        let mut d = Driver::link(line, model, Header { station: 3, pc: 0xFF, wait: 0 }, s, info.clone());
        let e = d.read(&ops(&d, &["D0"])).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(e.message.contains("no reply to WR"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("station 3"), "{e:?}");
        assert_eq!(d.requests(), 1, "silence is not retried");
        // A programming port that never answers ENQ.
        struct Dead;
        impl Transport for Dead {
            fn send(&mut self, _: &[u8]) -> io::Result<()> {
                Ok(())
            }
            fn recv(&mut self, _: &mut [u8], _: Duration) -> io::Result<usize> {
                Ok(0)
            }
        }
        let mut p = Driver::port(lines::private("dead", Box::new(Dead)), model, info);
        let e = p.read(&ops(&p, &["D0"])).unwrap_err();
        assert!(e.message.contains("no ACK to ENQ"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("7E1"), "{e:?}");
        assert_eq!(p.requests(), 0, "no frame goes out before the handshake");
    }
}
