//! The FX programming port as a driver (`fx:/dev/ttyUSB0`, 9600 7E1; seed 004, FX2 article):
//! the ENQ/ACK handshake, the reply frames, and reads and writes through the model's address
//! table. The transaction these frames ride on (quiet line, timeout, resends, messages) is
//! the driver's, in [`super`].
//!
//! - The first request probes ENQ; a PLC that answers ACK gets the ENQ/ACK handshake before
//!   the conversation (and again after a failure), one that leaves ENQ unanswered gets its
//!   frames without it (what public drivers send); NAK to ENQ is a real answer.
//! - Each operand goes through the model's address table ([`Table::of`]): the classic
//!   commands 0/1/7/8 on an FX1S/FX1N/FX2N, the E-commands E00/E10/E7/E8 on an FX3U. Reads
//!   coalesce into the fewest frames of at most 64 bytes within one region of the address
//!   table; words are written with command 1 (adjacent words in one frame), bits are forced
//!   ON/OFF (commands 7/8), a `Kn` group that covers whole bytes is written as bytes and any
//!   other group bit by bit — never a read-modify-write of the PLC's bytes.

use super::{finish, late_text, model_of, read_only, show, Driver, Expect, Got, Mode, FRAME_CAP, PORT_PARAMS};
use crate::core::link::line as lines;
use crate::core::link::serial::{Carrier, LineSettings, Parity};
use crate::core::url::DeviceUrl;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Result, Value};
use crate::fx::operand::{FxOperand, Width};
use crate::fx::port::{self, Request, Table, ACK, ENQ, NAK};
use crate::msg;

/// How long the programming-port reply at the start of `f` is (`f` starts with STX, ACK or
/// NAK): ACK and NAK are one character, a data frame ends two characters after ETX.
pub(super) fn port_len(f: &[u8]) -> Option<usize> {
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
pub(super) fn classify_port(f: &[u8], expect: Expect) -> Got {
    match (f[0], expect) {
        (NAK, _) => Got::Nak(None),
        (ACK, Expect::Ack { .. }) => Got::Ack,
        (ACK, Expect::Data { .. }) => Got::Other(msg!("fx-reply-ack-not-data").text),
        (_, Expect::Ack { .. }) => Got::Other(msg!("fx-reply-data-not-ack", bytes = show(f)).text),
        (_, Expect::Data { data, .. }) => match port::decode_read_reply(f, data) {
            Ok(d) => Got::Data(d),
            Err(port::FrameError::BadSum { got, want }) => {
                Got::BadSum(msg!("fx-reply-sum", got = format!("{got:02X}"), want = format!("{want:02X}")).text)
            }
            Err(port::FrameError::Malformed(m)) => {
                Got::Other(msg!("fx-reply-garbled", bytes = show(f), reason = crate::fx::link::malformed_text(m)).text)
            }
        },
    }
}

/// Whether the programming port wants ENQ before a frame. The seed's host program opens with
/// ENQ and waits for ACK; public drivers (node-fxplc, KrystianD/fxplc, HslCommunication) send
/// their frames without it, and clones answer frames either way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Handshake {
    /// Not known yet: the next ENQ is a probe, and silence to it is an answer too.
    Probe,
    /// The PLC answers ENQ: ENQ opens the conversation, and opens it again after a failure.
    Enq,
    /// The PLC left the probe unanswered: frames go without ENQ. Silence to a frame makes the
    /// next request probe again.
    Skip,
}

impl Driver {
    /// The ENQ/ACK handshake (programming port; seed 004: "通过ENQ、ACK和NAK上位机协调与PLC的通信
    /// 应答"). Only ACK opens the conversation; a NAK is a NAK character in reply, noise is
    /// reported as noise. The first ENQ is a probe: a PLC that leaves it unanswered (and
    /// nothing comes late either) is talked to without ENQ from then on. `after_failure`: the
    /// line just carried a failed exchange, so the first ENQ waits as a resend does.
    pub(super) fn enq(&mut self, after_failure: bool) -> Result<()> {
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
            return Err(Error::link(msg!("fx-enq-nak", count = seen.len(), line = &self.line.name))
                .hint(msg!("fx-hint-enq-nak")));
        }
        Err(self.failure("ENQ", &seen, (1, 1)))
    }

    /// The programming port opens the conversation again with ENQ after a failed exchange.
    pub(super) fn desync(&mut self) {
        if let Mode::Port { handshake, .. } = self.mode {
            self.mode = Mode::Port { synced: false, handshake };
        }
    }

    pub(super) fn port_read(&mut self, ops: &[FxOperand]) -> Result<Vec<Value>> {
        let table = Table::of(self.space.model);
        let regions = port::regions(table);
        let places: Vec<port::Place> = ops
            .iter()
            .map(|o| {
                port::place(table, o)
                    .ok_or_else(|| Error::new(ErrorKind::Range, msg!("fx-past-table")).operand(o.canonical()))
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
            let kind = if table == Table::Extended { "e00" } else { "read" };
            let what = msg!("fx-req-port", kind = kind, count = count, address = format!("{s:04X}")).text;
            let bytes = self.transact(&req.encode(), expect, &what)?;
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

    pub(super) fn port_write(&mut self, items: &[(FxOperand, Value)]) -> Result<()> {
        // Frames in order; adjacent byte writes merge.
        let table = Table::of(self.space.model);
        let mut frames: Vec<(Request, String)> = Vec::new();
        for (o, v) in items {
            let raw = o.view.encode(v) as u64;
            let p = port::place(table, o)
                .ok_or_else(|| Error::new(ErrorKind::Range, msg!("fx-past-table")).operand(o.canonical()))?;
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
}

fn on_off(raw: u64) -> &'static str {
    if raw != 0 {
        "ON"
    } else {
        "OFF"
    }
}

fn push_write(frames: &mut Vec<(Request, String)>, table: Table, addr: u16, data: Vec<u8>, o: &FxOperand) {
    if let Some((Request::Write { addr: a, data: d, .. }, what)) = frames.last_mut() {
        if *a as usize + d.len() == addr as usize && d.len() + data.len() <= port::MAX_BYTES {
            d.extend(data);
            *what = msg!("fx-req-port", kind = write_kind(table), count = d.len(), address = format!("{a:04X}")).text;
            return;
        }
    }
    frames.push((
        Request::Write { table, addr, data },
        msg!("fx-req-port-operand", kind = write_kind(table), operand = o.canonical()).text,
    ));
}

fn write_kind(table: Table) -> &'static str {
    match table {
        Table::Classic => "write",
        Table::Extended => "e10",
    }
}

/// Opens `fx:PORT?baud=9600&model=FX2N&timeout=500ms&retries=3`: the programming port, 7E1.
pub fn open_port(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(PORT_PARAMS)?;
    let carrier = Carrier::from_url(u, "fx:COM6 or fx:/dev/ttyUSB0")?;
    let model = model_of(u, None)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(9600);
    if baud == 0 {
        return Err(Error::usage(msg!("fx-baud-zero", url = &u.text)));
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
