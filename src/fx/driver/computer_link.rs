//! The FX computer link as a driver (`fxlink:/dev/ttyUSB0?station=0&pc=FF&wait=0`; seed
//! 004, "FX系列PLC专用协议通信指令格式详解"): judging the link's replies, and reads and writes as
//! its commands. The transaction these frames ride on (quiet line, timeout, resends,
//! messages) is the driver's, in [`super`].
//!
//! - Bits are read with BR (≤ 256 points a frame), words with WR (≤ 64); writes with BW and
//!   WW, and WT when single words at scattered devices are written together.
//! - A link reply carries no device address: the station, the PC number, the kind and the
//!   length are all there is to tell this request's reply from another's.

use super::{finish, model_of, show, Driver, Expect, Got, Mode, LINK_PARAMS};
use crate::core::link::line as lines;
use crate::core::link::serial::{Carrier, LineSettings, Parity};
use crate::core::url::DeviceUrl;
use crate::core::{Device, DeviceInfo, Error, Result, Value};
use crate::fx::link::{self as fxlink, Cmd, Dev, Header, Reply, Settings};
use crate::fx::operand::{Area, FxOperand, Width, CN32_FIRST};
use crate::msg;

/// Judges a complete computer-link reply (seed 004, "FX系列PLC专用协议通信指令格式详解": the
/// reply repeats the station and PC number; data comes as `STX … ETX sum`, a write is
/// acknowledged with ACK, an error is NAK with its code — "若发送码有误，则有以下回应"). A link
/// reply carries no device address, so the station, the kind and the length are all there is
/// to tell this request's reply from another's.
pub(super) fn classify_link(f: &[u8], h: Header, s: Settings, expect: Expect) -> Got {
    match (fxlink::decode_reply(f, h, s), expect) {
        (Ok(Reply::Data(d)), Expect::Data { data, .. }) if d.len() == data => Got::Data(d),
        (Ok(Reply::Data(d)), Expect::Data { data, .. }) => {
            Got::Other(msg!("fx-reply-other-length", got = d.len(), want = data).text)
        }
        (Ok(Reply::Data(_)), Expect::Ack { .. }) => {
            Got::Other(msg!("fx-reply-data-not-ack-link", bytes = show(f)).text)
        }
        (Ok(Reply::Ack), Expect::Ack { .. }) => Got::Ack,
        (Ok(Reply::Ack), Expect::Data { .. }) => Got::Other(msg!("fx-reply-ack-not-data").text),
        (Ok(Reply::Nak(c)), _) => Got::Nak(Some(c)),
        (Err(fxlink::ReplyError::BadSum { got, want }), _) => {
            Got::BadSum(msg!("fx-reply-sum", got = format!("{got:02X}"), want = format!("{want:02X}")).text)
        }
        (Err(fxlink::ReplyError::Station { station, pc }), _) => Got::Other(
            msg!(
                "fx-reply-station",
                station = station,
                pc = format!("{pc:02X}"),
                want = h.station,
                wantpc = format!("{:02X}", h.pc)
            )
            .text,
        ),
        (Err(fxlink::ReplyError::Malformed(m)), _) => {
            Got::Other(msg!("fx-reply-garbled", bytes = show(f), reason = fxlink::malformed_text(m)).text)
        }
    }
}

impl Driver {
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

    pub(super) fn link_read(&mut self, ops: &[FxOperand]) -> Result<Vec<Value>> {
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
            let what = msg!(
                "fx-req-link-read",
                cmd = if bits { "BR" } else { "WR" },
                count = count,
                device = dev.text(self.settings())
            )
            .text;
            let frame = self.link_frame(&cmd);
            let chars = if bits { count } else { count * dev.unit() };
            let expect = Expect::Data { chars: fxlink::data_reply_chars(chars, self.settings()), data: chars };
            let d = self.transact(&frame, expect, &what)?;
            let values = if bits {
                if d.len() != count || !d.iter().all(|c| *c == b'0' || *c == b'1') {
                    return Err(Error::link(msg!("fx-bad-bits-reply", what = &what, count = count)));
                }
                d.iter().map(|c| (*c == b'1') as u32).collect()
            } else {
                let v = fxlink::parse_values(&d, dev.unit()).filter(|v| v.len() == count);
                v.ok_or_else(|| Error::link(msg!("fx-bad-words-reply", what = &what, count = count)))?
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

    pub(super) fn link_write(&mut self, items: &[(FxOperand, Value)]) -> Result<()> {
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
                Cmd::Bw { dev, bits } => msg!("fx-req-link-bw", count = bits.len(), device = dev.text(st)).text,
                Cmd::Ww { dev, values } => msg!("fx-req-link-ww", count = values.len(), device = dev.text(st)).text,
                Cmd::Wt { items } => msg!("fx-req-link-wt", count = items.len()).text,
                _ => String::new(),
            };
            let frame = self.link_frame(&c);
            self.transact(&frame, Expect::Ack { chars: fxlink::ack_chars(st) }, &what)?;
        }
        Ok(())
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

fn hex_param(u: &DeviceUrl, key: &str, default: u8, max: u8) -> Result<u8> {
    match u.param(key) {
        None => Ok(default),
        Some(v) => {
            let n = if key == "pc" { u8::from_str_radix(v, 16).ok() } else { v.parse::<u8>().ok() };
            n.filter(|n| *n <= max).ok_or_else(|| {
                Error::usage(msg!("fx-param-out-of-range", key = key, value = v, url = &u.text))
                    .hint(msg!("fx-hint-param", key = key))
            })
        }
    }
}

/// The link's station, PC number and message wait from the URL (`station`, `pc`, `wait`).
pub(super) fn link_header(u: &DeviceUrl) -> Result<Header> {
    Ok(Header {
        station: hex_param(u, "station", 0, 31)?,
        pc: hex_param(u, "pc", 0xFF, 0xFF)?,
        wait: hex_param(u, "wait", 0, 15)?,
    })
}

pub(super) fn link_settings(u: &DeviceUrl) -> Result<Settings> {
    let sum = match u.param("sum") {
        None | Some("1") | Some("on") | Some("true") => true,
        Some("0") | Some("off") | Some("false") => false,
        Some(v) => return Err(Error::usage(msg!("fx-sum-param", value = v, url = &u.text))),
    };
    let format4 = match u.param("format") {
        None | Some("1") => false,
        Some("4") => true,
        Some(v) => return Err(Error::usage(msg!("fx-format-param", value = v, url = &u.text))),
    };
    let decimal_xy = match u.param("xy") {
        None | Some("octal") => false,
        Some("decimal") => true,
        Some(v) => return Err(Error::usage(msg!("fx-xy-param", value = v, url = &u.text))),
    };
    Ok(Settings { sum, format4, decimal_xy })
}

/// Opens `fxlink:PORT?station=0&pc=FF&wait=0&baud=9600&bits=7&parity=e&stop=1&sum=1&format=1`.
pub fn open_link(u: &DeviceUrl) -> Result<Box<dyn Device>> {
    u.expect_params(LINK_PARAMS)?;
    let carrier = Carrier::from_url(u, "fxlink:COM7?station=0 or fxlink:/dev/ttyUSB0?station=0")?;
    let model = model_of(u, None)?;
    let header = link_header(u)?;
    let settings = link_settings(u)?;
    let baud = u.param_num::<u32>("baud")?.unwrap_or(9600);
    let bits = u.param_num::<u8>("bits")?.unwrap_or(7);
    let parity = Parity::parse(u.param("parity").unwrap_or("e"));
    let stop = u.param_num::<u8>("stop")?.unwrap_or(1);
    let (Some(parity), true, true, true) = (parity, matches!(bits, 7 | 8), matches!(stop, 1 | 2), baud > 0) else {
        return Err(Error::usage(msg!("fx-line-params", url = &u.text)));
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
