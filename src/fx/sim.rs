//! The simulated FX PLC's two ports, answering the same codecs the drivers use
//! ([`super::port`], [`super::link`]) from one shared [`Memory`]:
//!
//! - [`PortServer`]: ENQ → ACK; a read/write/force frame → data, ACK or NAK, with or without
//!   an ENQ before it (public drivers send none). NAK for a bad sum check, a malformed frame,
//!   any byte address or force address where the model has no device (seed 004:
//!   "如传送的命令有错误PLC返回NAK信号"), the E-commands on a model without them, and program
//!   memory (E01/E11, not simulated).
//! - [`LinkServer`]: requests for its station get data, ACK or NAK with an error code;
//!   requests for other stations get no reply (a multi-drop line); a PC number other than
//!   FF is error 0A.
//!
//! A pseudo-terminal carries no parity, so the simulator exchanges the 7-bit characters and
//! treats any byte with bit 7 set as a line error (what a parity or framing error is on a
//! real 7E1 line): the partial frame is dropped and NAK is answered. Both servers are byte
//! parsers that run in time linear in their input; a partial frame left sitting for
//! [`GAP`] is dropped (`serve` calls [`Server::gap`]).
//!
//! They are used in-process through [`SimLink`] (`sim-fx:FX2N` runs the real driver code) and
//! served on a pty or a TCP port by [`serve`] (`plcsh sim serve --fx-pty LINK --fx-link-pty
//! LINK2`, or `--fx-tcp ADDR --fx-link-tcp ADDR`).

use super::link::{self, code, Cmd, Dev, Header, Parsed, Reply, Settings};
use super::memory::Memory;
use super::operand::{Area, CN32_FIRST};
use super::port::{self, Request, Table, ACK, ENQ, ETX, NAK, STX};
use crate::core::link::line::Transport;
use crate::core::link::served::{ServeOn, Served};
use crate::core::Result;
use crate::msg;
use std::collections::VecDeque;
use std::io;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// The memory both ports share.
pub type Plc = Arc<Mutex<Memory>>;

/// Silence after which a partial frame is dropped (a frame of 140 characters takes 146 ms at
/// 9600 baud, but characters of one frame follow each other closely).
pub const GAP: Duration = Duration::from_millis(100);

/// Longest programming-port frame: STX 1 4 2 128 ETX 2.
const PORT_MAX: usize = 139;
/// Longest link request the parser waits for (WW of 64 words with sum and CR LF).
const LINK_MAX: usize = 8 + 7 + 64 * 8 + 4;

/// A reply and how long the PLC waits before sending it (the link's wait digit).
#[derive(Clone, Debug, PartialEq)]
pub struct Out {
    pub bytes: Vec<u8>,
    pub wait: Duration,
}

/// A simulated port: bytes in, replies out.
pub trait Server: Send {
    fn feed(&mut self, input: &[u8], plc: &Mutex<Memory>) -> Vec<Out>;
    /// The line went quiet: drop a partial frame.
    fn gap(&mut self);
}

fn now(bytes: Vec<u8>) -> Out {
    Out { bytes, wait: Duration::ZERO }
}

/// Locks the PLC and brings it to the present: every request is answered from the image as
/// it is at the moment it arrives ([`Memory::advance`]).
fn lock(plc: &Mutex<Memory>) -> std::sync::MutexGuard<'_, Memory> {
    let mut m = plc.lock().unwrap_or_else(|p| p.into_inner());
    m.advance();
    m
}

/// The programming port.
#[derive(Default)]
pub struct PortServer {
    buf: Vec<u8>,
    /// Frames answered NAK (for tests).
    pub naks: u64,
}

impl PortServer {
    fn answer(&mut self, frame: &[u8], plc: &Mutex<Memory>) -> u8 {
        let Ok(req) = port::decode_request(frame) else { return NAK };
        let mut m = lock(plc);
        match req {
            Request::Read { .. } | Request::Program { .. } => NAK, // reads: the caller; program memory: not simulated
            Request::Write { table, .. } | Request::Force { table, .. } if !answers(&m, table) => NAK,
            Request::Write { table, addr, data } => {
                if data.is_empty() || data.len() > port::MAX_BYTES || !m.port_range_ok_in(table, addr, data.len()) {
                    return NAK;
                }
                for (i, b) in data.iter().enumerate() {
                    m.set_port_byte_in(table, addr + i as u16, *b);
                }
                ACK
            }
            Request::Force { table, on, addr } => match port::force_target(table, addr) {
                Some((area, index)) if m.set_bit(area, index, on).is_some() => ACK,
                _ => NAK,
            },
        }
    }

    fn frame(&mut self, plc: &Mutex<Memory>) -> Vec<u8> {
        let frame = std::mem::take(&mut self.buf);
        let reply = match port::decode_request(&frame) {
            Ok(Request::Read { table, addr, count }) => {
                let m = lock(plc);
                let n = count as usize;
                if !answers(&m, table) || n == 0 || n > port::MAX_BYTES || !m.port_range_ok_in(table, addr, n) {
                    vec![NAK]
                } else {
                    let data: Vec<u8> = (0..n).filter_map(|i| m.port_byte_in(table, addr + i as u16)).collect();
                    port::encode_read_reply(&data)
                }
            }
            _ => vec![self.answer(&frame, plc)],
        };
        if reply == [NAK] {
            self.naks += 1;
        }
        reply
    }
}

/// Whether the simulated model answers frames of `table`: the classic commands every model,
/// the E-commands a model that has them (an FX2N answers them NAK).
fn answers(m: &Memory, table: Table) -> bool {
    table == Table::Classic || m.model.extended
}

impl Server for PortServer {
    fn feed(&mut self, input: &[u8], plc: &Mutex<Memory>) -> Vec<Out> {
        let mut out = Vec::new();
        for &b in input {
            if b & 0x80 != 0 {
                self.buf.clear();
                self.naks += 1;
                out.push(now(vec![NAK]));
                continue;
            }
            if self.buf.is_empty() {
                match b {
                    ENQ => out.push(now(vec![ACK])),
                    STX => self.buf.push(b),
                    _ => {} // noise between frames
                }
                continue;
            }
            self.buf.push(b);
            let n = self.buf.len();
            if n >= 3 && self.buf[n - 3] == ETX {
                out.push(now(self.frame(plc)));
            } else if n > PORT_MAX {
                self.buf.clear();
                self.naks += 1;
                out.push(now(vec![NAK]));
            }
        }
        out
    }
    fn gap(&mut self) {
        self.buf.clear();
    }
}

/// The computer-link port of station `station`.
pub struct LinkServer {
    pub station: u8,
    pub settings: Settings,
    buf: Vec<u8>,
    pub naks: u64,
}

impl LinkServer {
    pub fn new(station: u8, settings: Settings) -> LinkServer {
        LinkServer { station, settings, buf: Vec::new(), naks: 0 }
    }

    fn nak(&mut self, h: Header, c: u8) -> Vec<u8> {
        self.naks += 1;
        link::encode_reply(h, &Reply::Nak(c), self.settings)
    }

    fn run(m: &mut Memory, cmd: &Cmd) -> std::result::Result<Reply, u8> {
        let bit_area = |a: Area| matches!(a, Area::X | Area::Y | Area::M | Area::S | Area::TS | Area::CS);
        let word_bits = |a: Area| matches!(a, Area::X | Area::Y | Area::M | Area::S);
        match cmd {
            Cmd::Br { dev, count } => {
                if !bit_area(dev.area) || *count > link::MAX_BITS {
                    return Err(code::AREA);
                }
                let mut d = Vec::with_capacity(*count);
                for i in 0..*count as u16 {
                    let b = m.bit(dev.area, dev.index.checked_add(i).ok_or(code::AREA)?).ok_or(code::AREA)?;
                    d.push(if b { b'1' } else { b'0' });
                }
                Ok(Reply::Data(d))
            }
            Cmd::Wr { dev, count } => {
                let mut d = Vec::new();
                if word_bits(dev.area) {
                    if *count > link::MAX_WORDS / 2 {
                        return Err(code::AREA);
                    }
                    for w in 0..*count as u16 {
                        let mut v = 0u16;
                        for i in 0..16 {
                            let idx = dev.index.checked_add(16 * w + i).ok_or(code::AREA)?;
                            v |= (m.bit(dev.area, idx).ok_or(code::AREA)? as u16) << i;
                        }
                        d.extend(format!("{v:04X}").bytes());
                    }
                    return Ok(Reply::Data(d));
                }
                let max = if dev.unit() == 8 { link::MAX_WORDS / 2 } else { link::MAX_WORDS };
                if !matches!(dev.area, Area::D | Area::TN | Area::CN) || *count > max {
                    return Err(code::AREA);
                }
                for i in 0..*count as u16 {
                    let idx = dev.index.checked_add(i).ok_or(code::AREA)?;
                    if (idx >= CN32_FIRST) != (dev.index >= CN32_FIRST) && dev.area == Area::CN {
                        return Err(code::AREA);
                    }
                    let v = m.word(dev.area, idx).ok_or(code::AREA)?;
                    d.extend(if dev.unit() == 8 { format!("{v:08X}") } else { format!("{v:04X}") }.bytes());
                }
                Ok(Reply::Data(d))
            }
            Cmd::Bw { dev, bits } => {
                if !bit_area(dev.area) || bits.len() > 160 {
                    return Err(code::AREA);
                }
                for i in 0..bits.len() as u16 {
                    m.bit(dev.area, dev.index.checked_add(i).ok_or(code::AREA)?).ok_or(code::AREA)?;
                }
                for (i, b) in bits.iter().enumerate() {
                    m.set_bit(dev.area, dev.index + i as u16, *b);
                }
                Ok(Reply::Ack)
            }
            Cmd::Ww { dev, values } => {
                Self::check_words(m, *dev, values.len())?;
                for (i, v) in values.iter().enumerate() {
                    Self::put_word(m, Dev { area: dev.area, index: dev.index + (i as u16) * Self::step(*dev) }, *v);
                }
                Ok(Reply::Ack)
            }
            Cmd::Wt { items } => {
                if items.is_empty() || items.len() > link::MAX_WT {
                    return Err(code::AREA);
                }
                for (d, _) in items {
                    Self::check_words(m, *d, 1)?;
                }
                for (d, v) in items {
                    Self::put_word(m, *d, *v);
                }
                Ok(Reply::Ack)
            }
        }
    }

    /// Device numbers one word covers: 16 for bit devices, 1 for word devices.
    fn step(d: Dev) -> u16 {
        if d.area.is_bit() {
            16
        } else {
            1
        }
    }

    fn check_words(m: &Memory, dev: Dev, n: usize) -> std::result::Result<(), u8> {
        let bits = matches!(dev.area, Area::X | Area::Y | Area::M | Area::S);
        if !(bits || matches!(dev.area, Area::D | Area::TN | Area::CN)) || n == 0 || n > link::MAX_WORDS {
            return Err(code::AREA);
        }
        let last = (dev.index as usize + n * Self::step(dev) as usize).checked_sub(1).ok_or(code::AREA)?;
        if last > u16::MAX as usize {
            return Err(code::AREA);
        }
        for i in dev.index..=last as u16 {
            let ok = if bits { m.bit(dev.area, i).is_some() } else { m.word(dev.area, i).is_some() };
            if !ok || (dev.area == Area::CN && (i >= CN32_FIRST) != (dev.index >= CN32_FIRST)) {
                return Err(code::AREA);
            }
        }
        Ok(())
    }

    fn put_word(m: &mut Memory, d: Dev, v: u32) {
        if d.area.is_bit() {
            for i in 0..16 {
                m.set_bit(d.area, d.index + i, v >> i & 1 != 0);
            }
        } else {
            m.set_word(d.area, d.index, v);
        }
    }
}

impl Server for LinkServer {
    fn feed(&mut self, input: &[u8], plc: &Mutex<Memory>) -> Vec<Out> {
        let mut out = Vec::new();
        let own = Header { station: self.station, pc: 0xFF, wait: 0 };
        for &b in input {
            if b & 0x80 != 0 {
                self.buf.clear();
                let r = self.nak(own, code::PROTOCOL);
                out.push(now(r));
                continue;
            }
            if self.buf.is_empty() && b != ENQ {
                continue;
            }
            self.buf.push(b);
            loop {
                match link::parse_request(&self.buf, self.settings) {
                    Parsed::Need => {
                        if self.buf.len() > LINK_MAX {
                            self.buf.clear();
                        }
                        break;
                    }
                    Parsed::Refused { len, header, code } => {
                        self.buf.drain(..len.min(self.buf.len()));
                        let h = header.unwrap_or(own);
                        if h.station == self.station {
                            let r = self.nak(h, code);
                            out.push(Out { bytes: r, wait: wait_of(h) });
                        }
                    }
                    Parsed::Request { len, header, cmd } => {
                        self.buf.drain(..len);
                        if header.station != self.station {
                            // Another station's request: stay silent.
                        } else if header.pc != 0xFF {
                            let r = self.nak(header, code::PC_NUMBER);
                            out.push(Out { bytes: r, wait: wait_of(header) });
                        } else {
                            let r = Self::run(&mut lock(plc), &cmd);
                            let bytes = match r {
                                Ok(reply) => link::encode_reply(header, &reply, self.settings),
                                Err(c) => self.nak(header, c),
                            };
                            out.push(Out { bytes, wait: wait_of(header) });
                        }
                    }
                }
                // Anything left that is not the start of a request is noise.
                match self.buf.iter().position(|b| *b == ENQ) {
                    Some(0) => {}
                    Some(p) => {
                        self.buf.drain(..p);
                    }
                    None => self.buf.clear(),
                }
                if self.buf.is_empty() {
                    break;
                }
            }
        }
        out
    }
    fn gap(&mut self) {
        self.buf.clear();
    }
}

fn wait_of(h: Header) -> Duration {
    Duration::from_millis(10 * h.wait as u64)
}

/// The in-process transport: bytes go straight to a simulated port (no waiting: the wait
/// digit is carried but not slept in-process).
pub struct SimLink {
    pub plc: Plc,
    server: Box<dyn Server>,
    rx: VecDeque<u8>,
}

impl SimLink {
    pub fn new(plc: Plc, server: Box<dyn Server>) -> SimLink {
        SimLink { plc, server, rx: VecDeque::new() }
    }
}

impl Transport for SimLink {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        for o in self.server.feed(bytes, &self.plc) {
            self.rx.extend(o.bytes);
        }
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], _timeout: Duration) -> io::Result<usize> {
        let n = buf.len().min(self.rx.len());
        for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.rx.clear();
        Ok(())
    }
}

/// Answers on `t` until `stop` is raised (checked at least every [`GAP`]).
pub fn serve_line(t: &mut dyn Transport, server: &mut dyn Server, plc: &Plc, stop: &AtomicBool) -> Result<()> {
    let mut buf = [0u8; 512];
    while !stop.load(Ordering::Relaxed) {
        let n = t.recv(&mut buf, GAP)?;
        if n == 0 {
            server.gap();
            // Keep the PLC near the present while the line is quiet, so a request after a
            // long silence does not wait for its scans (the outcome is the same either way).
            drop(lock(plc));
            continue;
        }
        // A silent line (control channel fault): what arrives is not answered.
        let muted = {
            let mut p = lock(plc);
            p.advance();
            let now = p.cpu.clock.now();
            p.faults.mute(now)
        };
        if muted {
            server.gap();
            continue;
        }
        for o in server.feed(&buf[..n], plc) {
            if !o.wait.is_zero() {
                std::thread::sleep(o.wait);
            }
            t.send(&o.bytes)?;
        }
    }
    Ok(())
}

/// Opens the endpoint, calls `ready` with its fields for the readiness line, then serves
/// `server` on it until `stop`.
pub fn serve(
    on: &ServeOn,
    mut server: Box<dyn Server>,
    plc: Plc,
    stop: &AtomicBool,
    ready: impl FnOnce(serde_json::Value),
) -> Result<()> {
    let mut served = Served::open(on)?;
    ready(match served.tcp {
        Some(a) => serde_json::json!(a.to_string()),
        None => serde_json::json!(served.pty_ready()),
    });
    serve_line(served.line.as_mut(), server.as_mut(), &plc, stop)
}

/// The simulated FX PLC `sim serve` runs: model, computer-link station, a program, the clock.
pub struct PlcOptions<'a> {
    pub model: &'a str,
    pub station: u8,
    pub program: Option<&'a std::path::Path>,
    pub clock: &'a crate::core::Clock,
    /// The control channel's path ([`super::control`]); by default `LINK.ctl` beside the
    /// programming port's pty link (else the computer link's).
    pub control: Option<std::path::PathBuf>,
}

/// What `plcsh sim serve --fx-pty LINK --fx-link-pty LINK2` (or `--fx-tcp ADDR
/// --fx-link-tcp ADDR`) serves: one simulated PLC of `model` on the session's clock (running
/// `--fx-program FILE.il` if given), its programming port and/or its computer link (station
/// `station`, format 1, sum check on), each on its own endpoint served from a thread. Returns
/// once both are open, with their fields for the readiness line (`fx_model`, `fx_pty` or
/// `fx_tcp`, `fx_link_pty` or `fx_link_tcp`, `fx_station`, `fx_program`).
pub async fn serve_ports(
    port_on: Option<ServeOn>,
    link_on: Option<ServeOn>,
    opts: PlcOptions<'_>,
    stop: &Arc<AtomicBool>,
) -> Result<(serde_json::Map<String, serde_json::Value>, Option<crate::core::link::control::Channel>)> {
    use crate::core::link::control as channel;
    use serde_json::json;
    let (model, station) = (opts.model, opts.station);
    let mut ready = serde_json::Map::new();
    if port_on.is_none() && link_on.is_none() {
        return Ok((ready, None));
    }
    let pty_link = |on: &Option<ServeOn>| match on {
        Some(ServeOn::Pty(Some(l))) => Some(channel::default_path(l)),
        _ => None,
    };
    let control = opts.control.clone().or_else(|| pty_link(&port_on)).or_else(|| pty_link(&link_on));
    let m = super::model::Model::find(model).ok_or_else(|| {
        crate::core::Error::usage(format!("unknown FX model `{model}`"))
            .hint(format!("models: {}", super::model::Model::names()))
    })?;
    if station > 31 {
        return Err(crate::core::Error::usage("--fx-station is 0–31"));
    }
    let mut mem = Memory::with_clock(m, opts.clock.clone());
    if let Some(p) = opts.program {
        let text = crate::core::encoding::read_source(p).map_err(|e| {
            crate::core::Error::io(msg!("fx-serve-cannot-read", file = p.display().to_string(), reason = e.to_string()))
        })?;
        mem.load_program(super::program::Loaded::load(&text, &p.display().to_string(), m)?);
        ready.insert("fx_program".into(), json!(p.display().to_string()));
    }
    let plc: Plc = Arc::new(Mutex::new(mem));
    ready.insert("fx_model".into(), json!(m.name));
    let control = match control {
        Some(path) => {
            let p = plc.clone();
            let answer: channel::Answer =
                Arc::new(move |text: &str| channel::reply(super::control::answer(&mut lock(&p), text)));
            let ch = channel::Channel::open(&path, &msg!("link-channel-name", device = "fx"), answer, stop.clone())?;
            ready.insert("fx_control".into(), json!(ch.path()));
            Some(ch)
        }
        None => None,
    };
    let servers: [(Option<ServeOn>, &str, Box<dyn Server>); 2] = [
        (port_on, "fx", Box::new(PortServer::default())),
        (link_on, "fx_link", Box::new(LinkServer::new(station, Settings::default()))),
    ];
    for (on, key, server) in servers {
        let Some(on) = on else { continue };
        let key = format!("{key}_{}", if matches!(on, ServeOn::Tcp(_)) { "tcp" } else { "pty" });
        let (tx, rx) = tokio::sync::oneshot::channel::<Result<serde_json::Value>>();
        let (plc, stop) = (plc.clone(), stop.clone());
        std::thread::spawn(move || {
            let mut tx = Some(tx);
            let r = serve(&on, server, plc, &stop, |r| {
                if let Some(tx) = tx.take() {
                    let _ = tx.send(Ok(r));
                }
            });
            if let (Err(e), Some(tx)) = (r, tx.take()) {
                let _ = tx.send(Err(e));
            }
        });
        match rx.await {
            Ok(Ok(r)) => {
                ready.insert(key.clone(), r);
            }
            Ok(Err(e)) => return Err(e),
            Err(_) => return Err(crate::core::Error::io(msg!("fx-serve-stopped"))),
        }
        if key.starts_with("fx_link") {
            ready.insert("fx_station".into(), json!(station));
        }
    }
    Ok((ready, control))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fx::model::Model;

    fn plc(model: &str) -> Plc {
        Arc::new(Mutex::new(Memory::new(Model::find(model).unwrap())))
    }

    fn hex(s: &str) -> Vec<u8> {
        s.split_whitespace().map(|b| u8::from_str_radix(b, 16).unwrap()).collect()
    }

    fn talk(s: &mut dyn Server, p: &Plc, bytes: &[u8]) -> Vec<u8> {
        s.feed(bytes, p).into_iter().flat_map(|o| o.bytes).collect()
    }

    #[test]
    fn port_answers_the_seeds_frames() {
        let p = plc("FX2N");
        let mut s = PortServer::default();
        assert_eq!(talk(&mut s, &p, &[ENQ]), vec![ACK]);
        // Write 1234, ABCD to D123/D124, then read 4 bytes back (seed 004's two examples).
        assert_eq!(talk(&mut s, &p, &hex("02 31 31 30 46 36 30 34 33 34 31 32 43 44 41 42 03 34 39")), vec![ACK]);
        let r = talk(&mut s, &p, &hex("02 30 31 30 46 36 30 34 03 37 34"));
        // STX "3412CDAB" ETX sum: 0x33+0x34+0x31+0x32+0x43+0x44+0x41+0x42+0x03 = 0x1D7 → "D7".
        assert_eq!(r, hex("02 33 34 31 32 43 44 41 42 03 44 37"));
        // Force M500 on, Y10 off.
        assert_eq!(talk(&mut s, &p, &hex("02 37 46 34 30 39 03 31 44")), vec![ACK]);
        assert_eq!(lock(&p).bit(Area::M, 500), Some(true));
        assert_eq!(talk(&mut s, &p, &hex("02 38 30 38 30 35 03 30 38")), vec![ACK]);
        // The frame arriving in pieces is the same frame.
        let f = hex("02 30 30 30 41 32 30 32 03 36 38");
        assert!(talk(&mut s, &p, &f[..4]).is_empty());
        assert_eq!(talk(&mut s, &p, &f[4..]), hex("02 30 30 30 30 03 43 33"));
    }

    #[test]
    fn port_naks_bad_sums_addresses_and_line_errors() {
        let p = plc("FX1S");
        let mut s = PortServer::default();
        let mut bad = hex("02 30 31 30 46 36 30 34 03 37 34");
        bad[10] = b'5';
        assert_eq!(talk(&mut s, &p, &bad), vec![NAK], "bad sum");
        // D300 is past an FX1S (D0–D255): 0x1000 + 600 = 0x1258.
        let d300 = Request::Read { table: Table::Classic, addr: 0x1258, count: 2 }.encode();
        assert_eq!(talk(&mut s, &p, &d300), vec![NAK]);
        assert_eq!(
            talk(&mut s, &p, &Request::Read { table: Table::Classic, addr: 0x0700, count: 1 }.encode()),
            vec![NAK],
            "no device"
        );
        assert_eq!(
            talk(&mut s, &p, &Request::Read { table: Table::Classic, addr: 0x1000, count: 65 }.encode()),
            vec![NAK],
            "> 64 bytes"
        );
        assert_eq!(
            talk(&mut s, &p, &Request::Force { table: Table::Classic, on: true, addr: 0x0700 }.encode()),
            vec![NAK]
        );
        // A byte with bit 7 set (a parity error on a real line) drops the frame: NAK.
        assert_eq!(talk(&mut s, &p, &[STX, b'0', 0xB1]), vec![NAK]);
        assert_eq!(
            talk(&mut s, &p, &Request::Read { table: Table::Classic, addr: 0x1000, count: 2 }.encode()).len(),
            8,
            "then recovers"
        );
        assert_eq!(s.naks, 6);
    }

    #[test]
    fn link_answers_and_shares_memory_with_the_port() {
        let p = plc("FX2N");
        let mut port = PortServer::default();
        let mut l = LinkServer::new(0, Settings::default());
        let h = Header { station: 0, pc: 0xFF, wait: 0 };
        let s = Settings::default();
        let ww = link::encode_request(h, &Cmd::Ww { dev: Dev { area: Area::D, index: 123 }, values: vec![0x1234] }, s);
        assert_eq!(talk(&mut l, &p, &ww), b"\x0600FF".to_vec());
        // The programming port sees the link's write.
        let r = talk(&mut port, &p, &Request::Read { table: Table::Classic, addr: 0x10F6, count: 2 }.encode());
        assert_eq!(port::decode_read_reply(&r, 2).unwrap(), vec![0x34, 0x12]);
        let bw = link::encode_request(
            h,
            &Cmd::Bw { dev: Dev { area: Area::Y, index: 0 }, bits: vec![true, false, true] },
            s,
        );
        assert_eq!(talk(&mut l, &p, &bw), b"\x0600FF".to_vec());
        let br = link::encode_request(h, &Cmd::Br { dev: Dev { area: Area::Y, index: 0 }, count: 4 }, s);
        assert_eq!(link::decode_reply(&talk(&mut l, &p, &br), h, s), Ok(Reply::Data(b"1010".to_vec())));
        let wr = link::encode_request(h, &Cmd::Wr { dev: Dev { area: Area::Y, index: 0 }, count: 1 }, s);
        assert_eq!(link::decode_reply(&talk(&mut l, &p, &wr), h, s), Ok(Reply::Data(b"0005".to_vec())));
        // Out of range: D8255 exists, D8256 does not.
        let bad = link::encode_request(h, &Cmd::Wr { dev: Dev { area: Area::D, index: 8255 }, count: 2 }, s);
        assert_eq!(link::decode_reply(&talk(&mut l, &p, &bad), h, s), Ok(Reply::Nak(code::AREA)));
        // Bad sum → NAK 02.
        let mut bs = br.clone();
        let n = bs.len();
        bs[n - 1] = if bs[n - 1] == b'0' { b'1' } else { b'0' };
        assert_eq!(link::decode_reply(&talk(&mut l, &p, &bs), h, s), Ok(Reply::Nak(code::SUM)));
        // Another station: silence. PC number not FF: error 0A.
        let other = link::encode_request(
            Header { station: 3, ..h },
            &Cmd::Br { dev: Dev { area: Area::Y, index: 0 }, count: 1 },
            s,
        );
        assert!(talk(&mut l, &p, &other).is_empty());
        let pc = link::encode_request(
            Header { pc: 0x01, ..h },
            &Cmd::Br { dev: Dev { area: Area::Y, index: 0 }, count: 1 },
            s,
        );
        assert_eq!(talk(&mut l, &p, &pc), b"\x1500010A".to_vec());
        // Wait digit: the reply is held back 10 ms per step.
        let slow = link::encode_request(
            Header { wait: 0xA, ..h },
            &Cmd::Br { dev: Dev { area: Area::Y, index: 0 }, count: 1 },
            s,
        );
        assert_eq!(l.feed(&slow, &p)[0].wait, Duration::from_millis(100));
    }

    #[test]
    fn hostile_bytes_never_panic_and_the_servers_recover() {
        // Random bytes, biased towards the protocols' own characters so parsing goes deep.
        let alphabet = b"\x02\x03\x05\x06\x150123456789ABCDEFXYMSDTNCWRBF\xB0";
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let p = plc("FX2N");
        let mut port = PortServer::default();
        let mut l = LinkServer::new(0, Settings::default());
        for _ in 0..2000 {
            let n = (next() % 64) as usize;
            let chunk: Vec<u8> = (0..n).map(|_| alphabet[(next() % alphabet.len() as u64) as usize]).collect();
            port.feed(&chunk, &p);
            l.feed(&chunk, &p);
            let raw: Vec<u8> = (0..n).map(|_| next() as u8).collect();
            port.feed(&raw, &p);
            l.feed(&raw, &p);
            if next() % 8 == 0 {
                port.gap();
                l.gap();
            }
        }
        port.gap();
        l.gap();
        assert_eq!(talk(&mut port, &p, &[ENQ]), vec![ACK]);
        let h = Header { station: 0, pc: 0xFF, wait: 0 };
        let br =
            link::encode_request(h, &Cmd::Br { dev: Dev { area: Area::X, index: 0 }, count: 1 }, Settings::default());
        assert!(matches!(link::decode_reply(&talk(&mut l, &p, &br), h, Settings::default()), Ok(Reply::Data(_))));
    }
}
