//! Capture files block by block: pcapng (every section, either byte order; RFC draft
//! draft-ietf-opsawg-pcapng §3–§4) and classic libpcap files (draft-ietf-opsawg-pcap §4–§5,
//! microsecond and nanosecond magic, either byte order). Pure and linear in the file's size:
//! a capture from any tool is outside input.
//!
//! Damage does not end the reading. A block (or pcap record) whose header does not hold
//! together — an unknown length, a trailing length that differs from the leading one, a body
//! too short for its fields — is reported with its byte offset, and the reader scans forward,
//! byte by byte, to the next plausible block: a known block type whose leading and trailing
//! lengths agree (for pcap: a record header whose lengths and time fraction are possible,
//! followed by another such header or the end of the file). Only when nothing plausible
//! follows is the file taken as cut short, which is what a killed writer leaves.

use std::time::Duration;

/// One capture interface (pcapng IDB, or the pcap file header).
#[derive(Clone, Debug, PartialEq)]
pub struct Interface {
    pub linktype: u32,
    pub name: String,
    pub description: String,
    /// Byte offset of the block that described it.
    pub offset: usize,
}

/// One captured packet.
#[derive(Clone, Debug, PartialEq)]
pub struct Packet<'a> {
    /// Index into [`Capture::interfaces`].
    pub iface: usize,
    /// Since the Unix epoch.
    pub ts: Duration,
    pub data: &'a [u8],
    /// pcapng `epb_flags`.
    pub flags: Option<u32>,
    pub comments: Vec<String>,
    /// Byte offset of its block (record).
    pub offset: usize,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct Capture<'a> {
    /// `pcapng` or `pcap`.
    pub format: &'static str,
    pub interfaces: Vec<Interface>,
    pub packets: Vec<Packet<'a>>,
    /// Damaged regions skipped, each naming its offsets.
    pub damaged: Vec<String>,
    /// Why the file ends early (its last block cut short).
    pub truncated: Option<String>,
}

const SHB: u32 = 0x0A0D_0D0A;
const BOM: u32 = 0x1A2B_3C4D;
/// Block types this reader knows (the ones a resynchronisation may land on): SHB, IDB,
/// obsolete PB, SPB, NRB, ISB, EPB, DSB, custom.
const KNOWN: [u32; 10] = [SHB, 1, 2, 3, 4, 5, 6, 0x0A, 0x0BAD, 0x4000_0BAD];
/// Largest pcap record accepted (libpcap's own limit for most link types).
const MAX_RECORD: u32 = 262_144;
const LE: Endian = Endian { big: false };

#[derive(Clone, Copy)]
struct Endian {
    big: bool,
}

impl Endian {
    fn u16(self, b: &[u8], at: usize) -> Option<u16> {
        let a = [*b.get(at)?, *b.get(at + 1)?];
        Some(if self.big { u16::from_be_bytes(a) } else { u16::from_le_bytes(a) })
    }
    fn u32(self, b: &[u8], at: usize) -> Option<u32> {
        let a: [u8; 4] = b.get(at..at + 4)?.try_into().ok()?;
        Some(if self.big { u32::from_be_bytes(a) } else { u32::from_le_bytes(a) })
    }
    fn u64(self, b: &[u8], at: usize) -> Option<u64> {
        let a: [u8; 8] = b.get(at..at + 8)?.try_into().ok()?;
        Some(if self.big { u64::from_be_bytes(a) } else { u64::from_le_bytes(a) })
    }
}

/// Reads a capture file (pcapng or pcap).
pub fn parse(bytes: &[u8]) -> Result<Capture<'_>, String> {
    let magic = bytes.get(..4).map(|m| u32::from_le_bytes([m[0], m[1], m[2], m[3]]));
    match magic {
        Some(SHB) => pcapng(bytes),
        Some(0xA1B2_C3D4 | 0xD4C3_B2A1 | 0xA1B2_3C4D | 0x4D3C_B2A1) => pcap(bytes),
        _ if bytes.is_empty() => Err(crate::msg!("capture-empty").text),
        _ => {
            Err(crate::msg!("capture-bad-start", bytes = crate::core::trace::hex_bytes(&bytes[..bytes.len().min(4)]))
                .text)
        }
    }
}

/// Units of a timestamp: `if_tsresol` (pcapng §4.2): 10^-n, or 2^-n with the top bit set.
fn ts_of(units: u64, resol: u8) -> Duration {
    let n = u32::from(resol & 0x7F);
    if resol & 0x80 != 0 {
        if n >= 64 {
            return Duration::ZERO;
        }
        let secs = units >> n;
        let frac = units & ((1u64 << n) - 1);
        let nanos = ((u128::from(frac) * 1_000_000_000) >> n) as u32;
        return Duration::new(secs, nanos);
    }
    if n > 19 {
        return Duration::ZERO;
    }
    let per = 10u64.pow(n);
    let secs = units / per;
    let frac = units % per;
    let nanos = if n <= 9 { frac * 10u64.pow(9 - n) } else { frac / 10u64.pow(n - 9) };
    Duration::new(secs, nanos as u32)
}

/// Options of a block body from `at`: (code, value) pairs up to opt_endofopt.
fn options(e: Endian, b: &[u8], mut at: usize) -> Vec<(u16, &[u8])> {
    let mut out = Vec::new();
    while let (Some(code), Some(len)) = (e.u16(b, at), e.u16(b, at + 2)) {
        if code == 0 {
            break;
        }
        let len = usize::from(len);
        let Some(v) = b.get(at + 4..at + 4 + len) else { break };
        out.push((code, v));
        at += 4 + len.div_ceil(4) * 4;
    }
    out
}

fn text(v: &[u8]) -> String {
    String::from_utf8_lossy(v).trim_end_matches('\0').to_string()
}

/// The block at `pos` if its header holds together: (type, total length, byte order).
fn plausible(bytes: &[u8], pos: usize, e: Endian) -> Option<(u32, usize, Endian)> {
    let raw_type = LE.u32(bytes, pos)?;
    let e = if raw_type == SHB {
        match LE.u32(bytes, pos + 8)? {
            BOM => LE,
            0x4D3C_2B1A => Endian { big: true },
            _ => return None,
        }
    } else {
        e
    };
    let t = e.u32(bytes, pos)?;
    let total = e.u32(bytes, pos + 4)? as usize;
    if !KNOWN.contains(&t) || total < 12 || !total.is_multiple_of(4) || bytes.len() - pos < total {
        return None;
    }
    (e.u32(bytes, pos + total - 4)? as usize == total).then_some((t, total, e))
}

fn pcapng(bytes: &[u8]) -> Result<Capture<'_>, String> {
    let mut cap = Capture { format: "pcapng", ..Default::default() };
    let mut e = Endian { big: false };
    // Section-local interface ids → (index in cap.interfaces, if_tsresol, if_tsoffset).
    let mut section: Vec<(usize, u8, i64)> = Vec::new();
    let mut pos = 0;
    // Whole blocks taken in: a file without one is no capture (§3.1: every block ends with
    // its total length), not an empty one.
    let mut whole = 0usize;
    while pos < bytes.len() {
        let (why, cut) = match plausible(bytes, pos, e) {
            Some((t, total, be)) => {
                let body = &bytes[pos + 8..pos + total - 4];
                match block(&mut cap, &mut section, be, t, body, pos) {
                    Ok(()) => {
                        if t == SHB {
                            e = be;
                        }
                        whole += 1;
                        pos += total;
                        continue;
                    }
                    Err(why) => (why, false),
                }
            }
            None => header_fault(bytes, pos, e),
        };
        // Scan forward for the next block that holds together.
        let next = (pos + 1..bytes.len().saturating_sub(11)).find(|&q| plausible(bytes, q, e).is_some());
        let state = if cut { "cut" } else { "damaged" };
        match next {
            Some(q) => {
                cap.damaged.push(
                    crate::msg!(
                        "capture-damaged-block",
                        from = pos,
                        to = q - 1,
                        count = q - pos,
                        why = why.as_str(),
                        next = q
                    )
                    .text,
                );
                pos = q;
            }
            None if whole == 0 => {
                let what = if pos == 0 { "header" } else { "block" };
                return Err(crate::msg!(
                    "capture-no-block",
                    size = bytes.len(),
                    what = what,
                    at = pos,
                    state = state,
                    why = why.as_str()
                )
                .text);
            }
            None => {
                cap.truncated =
                    Some(crate::msg!("capture-block-truncated", at = pos, state = state, why = why.as_str()).text);
                break;
            }
        }
    }
    Ok(cap)
}

/// Why the block header at `pos` does not hold together, and whether the file ends inside
/// it (cut short rather than damaged).
fn header_fault(bytes: &[u8], pos: usize, e: Endian) -> (String, bool) {
    let left = bytes.len() - pos;
    let shb = LE.u32(bytes, pos) == Some(SHB);
    // A section header says its own byte order (§4.1: the byte-order magic after the length).
    let e = match (shb, LE.u32(bytes, pos + 8)) {
        (true, Some(BOM)) => LE,
        (true, Some(0x4D3C_2B1A)) => Endian { big: true },
        (true, Some(_)) => {
            let magic = crate::core::trace::hex_bytes(&bytes[pos + 8..pos + 12]);
            return (crate::msg!("capture-bad-magic", magic = magic).text, false);
        }
        (true, None) => return (crate::msg!("capture-short-section", left = left).text, true),
        (false, _) => e,
    };
    let (Some(t), Some(total)) = (e.u32(bytes, pos), e.u32(bytes, pos + 4)) else {
        return (crate::msg!("capture-short-block", left = left).text, true);
    };
    let total = total as usize;
    if !KNOWN.contains(&t) && !shb {
        (crate::msg!("capture-unknown-block", kind = format!("{t:#010X}")).text, false)
    } else if total < 12 || !total.is_multiple_of(4) {
        (crate::msg!("capture-bad-block-length", total = total).text, false)
    } else if total > left {
        (crate::msg!("capture-block-past-end", total = total, left = left).text, true)
    } else {
        (crate::msg!("capture-lengths-differ").text, false)
    }
}

/// Takes one whole block's body in.
fn block<'a>(
    cap: &mut Capture<'a>,
    section: &mut Vec<(usize, u8, i64)>,
    e: Endian,
    t: u32,
    body: &'a [u8],
    pos: usize,
) -> Result<(), String> {
    match t {
        SHB => {
            if body.len() < 16 {
                return Err(short("section", 16));
            }
            section.clear();
        }
        1 => {
            let linktype = u32::from(e.u16(body, 0).ok_or_else(|| short("interface", 8))?);
            if body.len() < 8 {
                return Err(short("interface", 8));
            }
            let mut iface = Interface { linktype, name: String::new(), description: String::new(), offset: pos };
            let (mut resol, mut tsoffset) = (6u8, 0i64);
            for (code, v) in options(e, body, 8) {
                match code {
                    2 => iface.name = text(v),
                    3 => iface.description = text(v),
                    9 => resol = v.first().copied().unwrap_or(6),
                    14 => tsoffset = e.u64(v, 0).map_or(0, |x| x as i64),
                    _ => {}
                }
            }
            section.push((cap.interfaces.len(), resol, tsoffset));
            cap.interfaces.push(iface);
        }
        2 | 3 | 6 => {
            // EPB: id, ts hi, ts lo, cap len, orig len, data, options.
            // Obsolete PB: id (16 bits), drops, ts hi, ts lo, cap len, orig len, data, options.
            // SPB: orig len, data (interface 0, no timestamp).
            let (id, ts_units, caplen, data_at): (usize, u64, usize, usize) = match t {
                6 => {
                    let f = |at| e.u32(body, at).ok_or_else(|| short("enhanced", 20));
                    (f(0)? as usize, (u64::from(f(4)?) << 32) | u64::from(f(8)?), f(12)? as usize, 20)
                }
                2 => {
                    let f = |at| e.u32(body, at).ok_or_else(|| short("packet", 20));
                    let id = usize::from(e.u16(body, 0).ok_or_else(|| short("packet", 20))?);
                    (id, (u64::from(f(4)?) << 32) | u64::from(f(8)?), f(12)? as usize, 20)
                }
                _ => {
                    let orig = e.u32(body, 0).ok_or_else(|| short("simple", 4))? as usize;
                    (0, 0, orig.min(body.len() - 4), 4)
                }
            };
            let data = body
                .get(data_at..data_at.saturating_add(caplen))
                .ok_or_else(|| crate::msg!("capture-packet-past-block", length = caplen).text)?;
            let Some(&(iface, resol, tsoffset)) = section.get(id) else {
                return Err(crate::msg!("capture-no-interface", id = id).text);
            };
            let mut p = Packet {
                iface,
                ts: ts_of(ts_units, resol).saturating_add(Duration::from_secs(tsoffset.max(0) as u64)),
                data,
                flags: None,
                comments: Vec::new(),
                offset: pos,
            };
            if t != 3 {
                for (code, v) in options(e, body, data_at + caplen.div_ceil(4) * 4) {
                    match code {
                        1 => p.comments.push(text(v)),
                        2 => p.flags = e.u32(v, 0),
                        _ => {}
                    }
                }
            }
            cap.packets.push(p);
        }
        _ => {}
    }
    Ok(())
}

/// A pcap record header at `pos` that could be one: (captured length).
fn pcap_record(bytes: &[u8], pos: usize, e: Endian, frac_max: u32) -> Option<usize> {
    let frac = e.u32(bytes, pos + 4)?;
    let incl = e.u32(bytes, pos + 8)?;
    let orig = e.u32(bytes, pos + 12)?;
    (frac < frac_max
        && incl <= MAX_RECORD
        && incl <= orig
        && orig <= MAX_RECORD
        && bytes.len() - pos - 16 >= incl as usize)
        .then_some(incl as usize)
}

/// `section header shorter than 16 bytes` (a pcapng block too short for its fixed fields).
fn short(block: &str, bytes: usize) -> String {
    crate::msg!("capture-block-short", block = block, bytes = bytes).text
}

fn pcap(bytes: &[u8]) -> Result<Capture<'_>, String> {
    if bytes.len() < 24 {
        return Err(crate::msg!("capture-short-pcap", size = bytes.len()).text);
    }
    let le = u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]);
    let e = Endian { big: matches!(le, 0xD4C3_B2A1 | 0x4D3C_B2A1) };
    let nanos = matches!(le, 0xA1B2_3C4D | 0x4D3C_B2A1);
    let frac_max = if nanos { 1_000_000_000 } else { 1_000_000 };
    let linktype = e.u32(bytes, 20).unwrap_or(0) & 0x0FFF_FFFF;
    let mut cap = Capture { format: "pcap", ..Default::default() };
    cap.interfaces.push(Interface { linktype, name: String::new(), description: String::new(), offset: 0 });
    // A plausible record followed by another one, or by the end of the file.
    let chained = |q: usize| {
        pcap_record(bytes, q, e, frac_max).is_some_and(|n| {
            let next = q + 16 + n;
            next == bytes.len() || pcap_record(bytes, next, e, frac_max).is_some()
        })
    };
    let mut pos = 24;
    while pos < bytes.len() {
        if let Some(n) = pcap_record(bytes, pos, e, frac_max) {
            let secs = u64::from(e.u32(bytes, pos).unwrap_or(0));
            let frac = u64::from(e.u32(bytes, pos + 4).unwrap_or(0));
            let ts = Duration::from_secs(secs) + Duration::from_nanos(if nanos { frac } else { frac * 1000 });
            let data = &bytes[pos + 16..pos + 16 + n];
            cap.packets.push(Packet { iface: 0, ts, data, flags: None, comments: Vec::new(), offset: pos });
            pos += 16 + n;
            continue;
        }
        let left = bytes.len() - pos;
        let why = match (e.u32(bytes, pos + 8), e.u32(bytes, pos + 12)) {
            _ if left < 16 => crate::msg!("capture-short-record", left = left).text,
            (Some(incl), _) if incl as usize > left - 16 => {
                crate::msg!("capture-record-past-end", length = incl, left = left - 16).text
            }
            (Some(incl), Some(orig)) => crate::msg!("capture-record-impossible", length = incl, original = orig).text,
            _ => crate::msg!("capture-record-unreadable").text,
        };
        match (pos + 1..bytes.len().saturating_sub(15)).find(|&q| chained(q)) {
            Some(q) => {
                cap.damaged.push(
                    crate::msg!(
                        "capture-damaged-record",
                        from = pos,
                        to = q - 1,
                        count = q - pos,
                        why = why.as_str(),
                        next = q
                    )
                    .text,
                );
                pos = q;
            }
            None => {
                cap.truncated = Some(crate::msg!("capture-record-truncated", at = pos, why = why.as_str()).text);
                break;
            }
        }
    }
    Ok(cap)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pcapng block of type `t` around `body` (little-endian).
    fn block(t: u32, body: &[u8]) -> Vec<u8> {
        let total = (body.len() + 12) as u32;
        [&t.to_le_bytes()[..], &total.to_le_bytes(), body, &total.to_le_bytes()].concat()
    }

    fn epb(n: u8) -> Vec<u8> {
        let mut b = vec![0; 12];
        b.extend_from_slice(&4u32.to_le_bytes());
        b.extend_from_slice(&4u32.to_le_bytes());
        b.extend_from_slice(&[n, n, n, n]);
        block(6, &b)
    }

    fn file(packets: u8) -> Vec<u8> {
        let mut f = block(SHB, &[0x4D, 0x3C, 0x2B, 0x1A, 1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF]);
        f.extend_from_slice(&block(1, &[147, 0, 0, 0, 0, 0, 0, 0]));
        for n in 0..packets {
            f.extend_from_slice(&epb(n));
        }
        f
    }

    #[test]
    fn damage_mid_file_is_skipped_naming_its_offsets_and_the_blocks_after_it_are_kept() {
        let f = file(5);
        let second = 28 + 20 + 36; // SHB, IDB, first EPB
        let firsts = |c: &Capture<'_>| c.packets.iter().map(|p| p.data[0]).collect::<Vec<u8>>();
        // A length field overwritten.
        let mut bad = f.clone();
        bad[second + 4..second + 8].copy_from_slice(&0x7777u32.to_le_bytes());
        let c = parse(&bad).unwrap();
        assert_eq!(firsts(&c), vec![0, 2, 3, 4], "{:?}", c.damaged);
        assert_eq!(c.damaged.len(), 1);
        assert!(c.damaged[0].starts_with(&format!("bytes {second}…{} (36 bytes)", second + 35)), "{}", c.damaged[0]);
        assert!(
            c.damaged[0].contains("block length 30583") && c.damaged[0].contains(&format!("offset {}", second + 36))
        );
        assert_eq!(c.truncated, None);
        // Junk inserted between two blocks (not a multiple of 4), and a trailing length changed.
        let mut bad = f[..second].to_vec();
        bad.extend_from_slice(b"garbage");
        bad.extend_from_slice(&f[second..]);
        let end = bad.len();
        bad[end - 4] = 0x99;
        let c = parse(&bad).unwrap();
        assert_eq!(firsts(&c), vec![0, 1, 2, 3], "{:?}", c.damaged);
        assert!(c.damaged[0].contains("unknown block type"), "{:?}", c.damaged);
        assert!(
            c.truncated.as_deref().is_some_and(|t| t.contains(&format!("offset {}", end - 36))),
            "{:?}",
            c.truncated
        );
    }

    #[test]
    fn damaged_pcap_records_are_skipped_too() {
        let mut f = vec![0xD4, 0xC3, 0xB2, 0xA1, 2, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4, 0, 1, 0, 0, 0];
        for n in 0..4u8 {
            f.extend_from_slice(&[1, 0, 0, 0, 0, 0, 0, 0, 3, 0, 0, 0, 3, 0, 0, 0, n, n, n]);
        }
        let mut bad = f.clone();
        bad[24 + 19 + 8] = 0xEE; // the second record's captured length
        let c = parse(&bad).unwrap();
        let firsts: Vec<u8> = c.packets.iter().map(|p| p.data[0]).collect();
        assert_eq!(firsts, vec![0, 2, 3], "{:?}", c.damaged);
        assert!(c.damaged[0].starts_with("bytes 43…61 (19 bytes)"), "{:?}", c.damaged);
        let c = parse(&f[..f.len() - 1]).unwrap();
        assert_eq!((c.packets.len(), c.damaged.len()), (3, 0));
        assert!(c.truncated.is_some());
    }

    #[test]
    fn timestamp_resolutions_convert_to_nanoseconds() {
        assert_eq!(ts_of(1_500_000, 6), Duration::from_millis(1500));
        assert_eq!(ts_of(1_500_000_000, 9), Duration::from_millis(1500));
        assert_eq!(ts_of(3 << 9 | 256, 0x89), Duration::from_millis(3500));
        assert_eq!(ts_of(u64::MAX, 0xFF), Duration::ZERO);
        assert_eq!(ts_of(u64::MAX, 127), Duration::ZERO);
    }

    #[test]
    fn junk_is_refused_and_hostile_lengths_do_not_panic() {
        assert!(parse(b"hello world").unwrap_err().contains("68 65 6C 6C"));
        assert_eq!(parse(b"").unwrap_err(), "it is empty (0 bytes)");
        let mut b = vec![0x0A, 0x0D, 0x0D, 0x0A, 28, 0, 0, 0, 0x4D, 0x3C, 0x2B, 0x1A];
        b.extend_from_slice(&[1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 28, 0, 0, 0]);
        for n in 0..b.len() + 8 {
            let mut c = b.clone();
            c.resize(n, 0xFF);
            let _ = parse(&c);
        }
        assert!(parse(&b).unwrap().truncated.is_none());
    }

    #[test]
    fn a_file_without_one_whole_block_is_no_capture() {
        let f = file(2);
        // Every cut inside the section header (28 bytes) is refused, naming the header.
        for n in 4..28 {
            let e = parse(&f[..n]).unwrap_err();
            assert!(
                e.starts_with(&format!("it holds no complete block ({n} bytes): the section header at offset 0")),
                "{n}: {e}"
            );
            assert!(e.contains("cut short"), "{n}: {e}");
        }
        // A section header with a byte-order magic that is neither order: damaged, not cut.
        let mut bad = f.clone();
        bad[8..12].copy_from_slice(&[1, 2, 3, 4]);
        let e = parse(&bad[..28]).unwrap_err();
        assert!(e.contains("is damaged (its byte-order magic 01 02 03 04 is neither"), "{e}");
        // Past the header every cut keeps what came before and names the cut block.
        for n in 28..f.len() {
            let c = parse(&f[..n]).unwrap();
            let whole_packets = n.saturating_sub(48) / 36;
            assert_eq!(c.packets.len(), whole_packets, "{n}");
            let starts = [28, 48, 84, 120];
            let at = *starts.iter().rev().find(|&&s| s <= n).unwrap();
            if n == at {
                assert_eq!(c.truncated, None, "{n}");
            } else {
                let t = c.truncated.unwrap();
                assert!(t.starts_with(&format!("the block at offset {at} is cut short: ")), "{n}: {t}");
            }
        }
    }
}
