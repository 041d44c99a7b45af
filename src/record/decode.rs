//! Decoding recorded frames for people: Modbus requests and replies with K2 operand names
//! (`FC3 read holding registers 150…151 = VW100…VW102`), Kinco servo frames with object
//! names (`read statusword (6041.00)`). Every decoder takes hostile bytes: lengths are
//! checked, nothing panics, a frame that does not parse says why.

use super::file::{Frame, LinkInfo};
use crate::core::trace::{Dir, Proto};
use crate::k2::modbus_map::{self, Table};
use crate::k2::space::K2Space;
use crate::servo::frame as sframe;
use crate::servo::objects;
use serde::Serialize;

/// What a frame says, structured for `--json` and replay.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Decoded {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unit: Option<u8>,
    /// Modbus function code or servo function byte.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub function: Option<u8>,
    /// First Modbus address (register or bit), or servo object `index.sub`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub address: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<u16>,
    /// K2 operand names of the addressed range, or the servo object's name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub operands: Option<String>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub values: Vec<i64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exception: Option<u8>,
    /// Why the frame is malformed, when it is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// One line for people.
    pub text: String,
}

/// A Modbus request's table, address and count (what names a reply's values).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Asked {
    pub fc: u8,
    pub addr: u16,
    pub count: u16,
}

/// Unit id and PDU of a Modbus frame (MBAP for TCP; unit … CRC for RTU).
pub fn modbus_pdu(proto: Proto, b: &[u8]) -> Result<(u8, &[u8]), String> {
    match proto {
        Proto::ModbusTcp => {
            if b.len() < 8 {
                return Err(format!("{} bytes: shorter than an MBAP header and a function code", b.len()));
            }
            let len = usize::from(u16::from_be_bytes([b[4], b[5]]));
            if b[2..4] != [0, 0] {
                return Err("protocol id is not 0 (not Modbus)".into());
            }
            if len != b.len() - 6 {
                return Err(format!("MBAP length {len} but {} bytes follow", b.len() - 6));
            }
            Ok((b[6], &b[7..]))
        }
        _ => {
            if b.len() < 4 {
                return Err(format!("{} bytes: too short for an RTU frame", b.len()));
            }
            let n = b.len();
            let crc = crate::k2::sim::rtu_frame::crc16(&b[..n - 2]);
            if crc != u16::from_le_bytes([b[n - 2], b[n - 1]]) {
                return Err(format!(
                    "bad CRC: frame ends {:02X} {:02X}, the bytes before need {:04X}",
                    b[n - 2],
                    b[n - 1],
                    crc.swap_bytes()
                ));
            }
            Ok((b[0], &b[1..n - 2]))
        }
    }
}

fn be16(b: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_be_bytes([*b.get(at)?, *b.get(at + 1)?]))
}

fn table_of(fc: u8) -> Option<Table> {
    Table::of_fc(fc).map(|(t, _)| t)
}

fn fc_name(fc: u8) -> &'static str {
    match fc {
        0x01 => "read coils",
        0x02 => "read discrete inputs",
        0x03 => "read holding registers",
        0x04 => "read input registers",
        0x05 => "write single coil",
        0x06 => "write single register",
        0x0F => "write multiple coils",
        0x10 => "write multiple registers",
        _ => "function",
    }
}

/// `VW100…VW102` for `count` addresses from `addr` in `table`.
pub fn k2_names(space: &K2Space, table: Table, addr: u16, count: u16) -> Option<String> {
    let first = modbus_map::operand_at(space, table, addr)?;
    if count <= 1 {
        return Some(first);
    }
    let last = modbus_map::operand_at(space, table, addr.checked_add(count - 1)?)?;
    Some(format!("{first}…{last}"))
}

fn range(addr: u16, count: u16) -> String {
    if count <= 1 {
        addr.to_string()
    } else {
        format!("{addr}…{}", u32::from(addr) + u32::from(count) - 1)
    }
}

fn bits(data: &[u8], n: usize) -> Vec<i64> {
    (0..n.min(data.len() * 8)).map(|i| i64::from((data[i / 8] >> (i % 8)) & 1)).collect()
}

/// Decodes a Modbus PDU; `asked` is the request a reply answers.
pub fn modbus(space: &K2Space, unit: u8, pdu: &[u8], dir: Dir, asked: Option<Asked>) -> (Decoded, Option<Asked>) {
    let mut d = Decoded { unit: Some(unit), ..Default::default() };
    let Some(&fc) = pdu.first() else {
        d.error = Some("empty PDU".into());
        d.text = "empty PDU".into();
        return (d, None);
    };
    d.function = Some(fc);
    let names = |fc: u8, a: u16, n: u16| table_of(fc).and_then(|t| k2_names(space, t, a, n));
    if fc & 0x80 != 0 {
        let code = pdu.get(1).copied().unwrap_or(0);
        d.exception = Some(code);
        d.text = format!("FC{} exception {code:02X} {}", fc & 0x7F, modbus_map::exception_name(code));
        return (d, None);
    }
    let mut new_ask = None;
    let body = &pdu[1..];
    let text = match (dir, fc) {
        (Dir::Sent, 0x01..=0x04) => match (be16(body, 0), be16(body, 2)) {
            (Some(a), Some(n)) => {
                new_ask = Some(Asked { fc, addr: a, count: n });
                d.address = Some(a.to_string());
                d.count = Some(n);
                d.operands = names(fc, a, n);
                format!("FC{fc} {} {} ×{n}", fc_name(fc), range(a, n))
            }
            _ => return malformed(d, "request shorter than address and count"),
        },
        (Dir::Sent, 0x05 | 0x06) | (Dir::Received, 0x05 | 0x06) => match (be16(body, 0), be16(body, 2)) {
            (Some(a), Some(v)) => {
                d.address = Some(a.to_string());
                d.count = Some(1);
                d.operands = names(fc, a, 1);
                let v = if fc == 5 { i64::from(v == 0xFF00) } else { i64::from(v) };
                d.values = vec![v];
                let what = if dir == Dir::Sent { fc_name(fc) } else { "written" };
                format!("FC{fc} {what} {a}")
            }
            _ => return malformed(d, "shorter than address and value"),
        },
        (Dir::Sent, 0x0F | 0x10) => match (be16(body, 0), be16(body, 2), body.get(4)) {
            (Some(a), Some(n), Some(&bc)) if body.len() == 5 + usize::from(bc) => {
                new_ask = Some(Asked { fc, addr: a, count: n });
                d.address = Some(a.to_string());
                d.count = Some(n);
                d.operands = names(fc, a, n);
                let data = &body[5..];
                d.values = if fc == 0x0F {
                    bits(data, usize::from(n))
                } else {
                    data.chunks_exact(2).map(|c| i64::from(u16::from_be_bytes([c[0], c[1]]))).collect()
                };
                format!("FC{fc} {} {} ×{n}", fc_name(fc), range(a, n))
            }
            _ => return malformed(d, "byte count does not match the data"),
        },
        (Dir::Received, 0x01..=0x04) => match body.first() {
            Some(&bc) if body.len() == 1 + usize::from(bc) => {
                let data = &body[1..];
                let a = asked.filter(|q| q.fc == fc);
                if let Some(q) = a {
                    d.address = Some(q.addr.to_string());
                    d.count = Some(q.count);
                    d.operands = names(fc, q.addr, q.count);
                }
                d.values = if fc <= 2 {
                    bits(data, a.map_or(data.len() * 8, |q| usize::from(q.count)))
                } else {
                    data.chunks_exact(2).map(|c| i64::from(u16::from_be_bytes([c[0], c[1]]))).collect()
                };
                format!("FC{fc} reply, {bc} bytes")
            }
            _ => return malformed(d, "byte count does not match the data"),
        },
        (Dir::Received, 0x0F | 0x10) => match (be16(body, 0), be16(body, 2)) {
            (Some(a), Some(n)) => {
                d.address = Some(a.to_string());
                d.count = Some(n);
                d.operands = names(fc, a, n);
                format!("FC{fc} written {} ×{n}", range(a, n))
            }
            _ => return malformed(d, "reply shorter than address and count"),
        },
        _ => format!("FC{fc} {} bytes of data", body.len()),
    };
    d.text = text;
    if let Some(ops) = &d.operands {
        d.text.push_str(&format!(" ({ops})"));
    }
    if !d.values.is_empty() {
        let vals: Vec<String> = d.values.iter().take(16).map(|v| v.to_string()).collect();
        let more = if d.values.len() > 16 { " …" } else { "" };
        d.text.push_str(&format!(": {}{more}", vals.join(" ")));
    }
    (d, new_ask)
}

fn malformed(mut d: Decoded, why: &str) -> (Decoded, Option<Asked>) {
    d.error = Some(why.to_string());
    d.text = format!("malformed: {why}");
    (d, None)
}

/// Decodes a Kinco servo frame (seed §2): requests by function, replies by object name.
pub fn servo(bytes: &[u8]) -> Decoded {
    let mut d = Decoded::default();
    let Ok(arr) = <[u8; sframe::FRAME_LEN]>::try_from(bytes) else {
        d.error = Some(format!("{} bytes, a servo frame has {}", bytes.len(), sframe::FRAME_LEN));
        d.text = format!("malformed: {}", d.error.as_deref().unwrap_or(""));
        return d;
    };
    let f = match sframe::Frame::from_bytes(&arr) {
        Ok(f) => f,
        Err(b) => {
            d.error = Some(format!("bad checksum {:02X}, want {:02X}", b.got, b.want));
            d.text = format!("malformed: {}", d.error.as_deref().unwrap_or(""));
            return d;
        }
    };
    use sframe::func;
    d.unit = Some(f.id);
    d.function = Some(f.func);
    d.address = Some(f.object());
    let name = objects::lookup(f.index, f.sub).map(|o| o.name.to_string());
    d.operands = name.clone();
    let obj = match &name {
        Some(n) => format!("{n} ({})", f.object()),
        None => f.object(),
    };
    let size_of = |fc: u8| match fc {
        func::WRITE_1 | func::READ_1 => Some(sframe::Size::B1),
        func::WRITE_2 | func::READ_2 => Some(sframe::Size::B2),
        func::WRITE_4 | func::READ_4 => Some(sframe::Size::B4),
        _ => None,
    };
    d.text = match f.func {
        func::READ => format!("id {} read {obj}", f.id),
        func::WRITE_1 | func::WRITE_2 | func::WRITE_4 | func::READ_1 | func::READ_2 | func::READ_4 => {
            let size = size_of(f.func).expect("sized function");
            let raw = f.data & size.mask();
            let signed = match objects::lookup(f.index, f.sub).map(|o| o.dtype.is_signed()) {
                Some(true) => match size {
                    sframe::Size::B1 => i64::from(raw as u8 as i8),
                    sframe::Size::B2 => i64::from(raw as u16 as i16),
                    sframe::Size::B4 => i64::from(raw as i32),
                },
                _ => i64::from(raw),
            };
            d.values = vec![signed];
            if matches!(f.func, func::WRITE_1 | func::WRITE_2 | func::WRITE_4) {
                format!("id {} write {obj} = {signed}", f.id)
            } else {
                format!("id {} {obj} = {signed}", f.id)
            }
        }
        func::WRITE_OK => format!("id {} write {obj} ok", f.id),
        func::ERROR => {
            d.exception = Some(0x80);
            format!("id {} abort {:08X} {} on {obj}", f.id, f.data, sframe::abort_text(f.data))
        }
        other => format!("id {} function {other:02X} on {obj}", f.id),
    };
    d
}

/// Decodes every frame of a recording in order, pairing Modbus replies with their requests
/// per link; K2 names come from the model each link's URL names ([`model_of`]).
pub fn all(links: &[LinkInfo], frames: &[Frame]) -> Vec<Decoded> {
    let spaces: Vec<K2Space> = links.iter().map(|l| K2Space::new(model_of(l))).collect();
    let mut asked: Vec<Option<Asked>> = vec![None; links.len()];
    // Modbus TCP clients may send several requests before the replies: a reply answers the
    // request with its transaction id (the MBAP's first word), among the last few.
    let mut by_tid: Vec<Vec<(u16, Asked)>> = vec![Vec::new(); links.len()];
    frames
        .iter()
        .map(|f| {
            let l = &links[f.link];
            let tid = (l.proto == Proto::ModbusTcp && f.bytes.len() >= 2)
                .then(|| u16::from_be_bytes([f.bytes[0], f.bytes[1]]));
            match l.proto {
                Proto::ModbusTcp | Proto::ModbusRtu | Proto::RtuOverTcp => match modbus_pdu(l.proto, &f.bytes) {
                    Ok((unit, pdu)) => {
                        let pending = &mut by_tid[f.link];
                        let before = match (f.dir, tid) {
                            (Dir::Received, Some(t)) => pending.iter().rev().find(|(k, _)| *k == t).map(|(_, q)| *q),
                            _ => None,
                        };
                        let (d, q) = modbus(&spaces[f.link], unit, pdu, f.dir, before.or(asked[f.link]));
                        if f.dir == Dir::Sent {
                            asked[f.link] = q;
                            if let (Some(t), Some(q)) = (tid, q) {
                                if pending.len() >= 16 {
                                    pending.remove(0);
                                }
                                pending.push((t, q));
                            }
                        }
                        d
                    }
                    Err(e) => Decoded { text: format!("malformed: {e}"), error: Some(e), ..Default::default() },
                },
                Proto::KincoServo => servo(&f.bytes),
                Proto::Umpk | Proto::FxPort | Proto::FxLink => {
                    Decoded { text: format!("{} bytes: {}", f.bytes.len(), ascii(&f.bytes)), ..Default::default() }
                }
                Proto::Unknown => Decoded { text: format!("{} bytes", f.bytes.len()), ..Default::default() },
            }
        })
        .collect()
}

/// The text of an ASCII protocol's frame, control characters named (`<STX>0 00A0 02<ETX>…`).
pub fn ascii(b: &[u8]) -> String {
    const NAMES: [(u8, &str); 8] = [
        (0x02, "STX"),
        (0x03, "ETX"),
        (0x05, "ENQ"),
        (0x06, "ACK"),
        (0x15, "NAK"),
        (0x0D, "CR"),
        (0x0A, "LF"),
        (0xAA, "AA"),
    ];
    let mut out = String::with_capacity(b.len());
    for &c in b.iter().take(256) {
        match NAMES.iter().find(|(k, _)| *k == c) {
            Some((_, n)) => out.push_str(&format!("<{n}>")),
            None if (0x20..0x7F).contains(&c) => out.push(char::from(c)),
            None => out.push_str(&format!("<{c:02X}>")),
        }
    }
    if b.len() > 256 {
        out.push('…');
    }
    out
}

/// The K2 model a link's URL names (`model=`), else the default for its scheme.
pub fn model_of(l: &LinkInfo) -> &'static crate::k2::catalog::Model {
    use crate::k2::catalog;
    let param = l
        .link
        .split_once('?')
        .and_then(|(_, q)| q.split('&').find_map(|kv| kv.strip_prefix("model=")).and_then(|m| catalog::lookup(m).ok()));
    param.unwrap_or_else(|| {
        let default = if l.proto == Proto::ModbusTcp { "K204ET-16DT" } else { catalog::DEFAULT_MODEL };
        catalog::lookup(default).expect("the default models are in the catalogue")
    })
}
