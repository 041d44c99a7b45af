//! Intel HEX records as the UMPK's programming commands use them (manual §4.2, Table 8,
//! Appendix "Формат Intel HEX-record"), pure.
//!
//! A record is `:` RECLEN OFFSET(2) RECTYPE DATA CHKSUM, every byte two ASCII hex digits;
//! the checksum is the two's complement of the byte sum from RECLEN through the data.
//! The UMPK's record types: 00 data (one 64-byte flash page recommended, §4.2.1), 01 end,
//! 02 start (erases the program, §4.2.3), 03 program info (1–22 bytes, §4.2.4).
//!
//! [`parse_file`] validates a whole file before anything is sent (checksums, types,
//! addresses inside the model's program memory, no overlap) and [`pages`] re-blocks its
//! data into page-aligned 64-byte records, so a file written with 16- or 32-byte lines
//! programs the same flash pages. Bytes a page does not define are sent as 0xFF (erased
//! flash).

use super::codec::{complement, hex_pair, push_hex, sum, INFO_LEN};
use super::model::PAGE;
use crate::msg;
use std::collections::BTreeMap;

/// Record types (Table 8).
pub mod kind {
    pub const DATA: u8 = 0x00;
    pub const END: u8 = 0x01;
    pub const START: u8 = 0x02;
    pub const INFO: u8 = 0x03;
}

/// One record.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Record {
    pub kind: u8,
    pub offset: u16,
    pub data: Vec<u8>,
}

impl Record {
    /// `:00000002FE`
    pub fn start() -> Record {
        Record { kind: kind::START, offset: 0, data: Vec::new() }
    }
    /// `:00000001FF`
    pub fn end() -> Record {
        Record { kind: kind::END, offset: 0, data: Vec::new() }
    }
    /// `:NN000003DD…CC`
    pub fn info(text: &[u8]) -> Record {
        Record { kind: kind::INFO, offset: 0, data: text.to_vec() }
    }
    /// `:NNAAAA00DD…CC`
    pub fn data(offset: u16, data: &[u8]) -> Record {
        Record { kind: kind::DATA, offset, data: data.to_vec() }
    }

    /// The record as sent: `:` and hex pairs, no line end.
    pub fn encode(&self) -> Vec<u8> {
        let head = [self.data.len() as u8, (self.offset >> 8) as u8, self.offset as u8, self.kind];
        let mut out = Vec::with_capacity(11 + 2 * self.data.len());
        out.push(b':');
        for &b in head.iter().chain(&self.data) {
            push_hex(&mut out, b);
        }
        push_hex(&mut out, complement(&head).wrapping_sub(sum(&self.data)));
        out
    }

    /// The record's length in characters, from its first three (`:NN`); `None` if RECLEN
    /// is not hex.
    pub fn text_len(head: &[u8]) -> Option<usize> {
        Some(11 + 2 * hex_pair(head.get(1..3)?)? as usize)
    }

    /// Parses one record (no line end). Errors carry the PLC's reply letter (`C` illegal
    /// character, `E` checksum) and a message.
    pub fn parse(text: &[u8]) -> Result<Record, (u8, String)> {
        if text.first() != Some(&b':') {
            return Err((b'C', msg!("umpk-hex-no-colon").text));
        }
        if let Some(p) = text[1..].iter().position(|c| !c.is_ascii_hexdigit()) {
            return Err((b'C', msg!("umpk-hex-not-hex-digit", position = p + 2).text));
        }
        if text.len() < 11 || text.len().is_multiple_of(2) {
            return Err((b'C', msg!("umpk-hex-odd-digits", count = text.len() - 1).text));
        }
        let bytes: Vec<u8> = text[1..].chunks(2).filter_map(hex_pair).collect();
        let n = bytes[0] as usize;
        if bytes.len() != n + 5 {
            return Err((b'C', msg!("umpk-hex-reclen", reclen = n, count = bytes.len() as i64 - 5).text));
        }
        if sum(&bytes) != 0 {
            let want = complement(&bytes[..bytes.len() - 1]);
            return Err((
                b'E',
                msg!(
                    "umpk-hex-checksum",
                    got = format!("{:02X}", bytes[bytes.len() - 1]),
                    want = format!("{want:02X}")
                )
                .text,
            ));
        }
        Ok(Record { kind: bytes[3], offset: u16::from_be_bytes([bytes[1], bytes[2]]), data: bytes[4..4 + n].to_vec() })
    }
}

/// A validated program file: its bytes by address, and its program info if it had one.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Program {
    pub bytes: BTreeMap<usize, u8>,
    pub info: Option<Vec<u8>>,
}

impl Program {
    /// Highest address + 1 (0 when empty).
    pub fn end(&self) -> usize {
        self.bytes.keys().next_back().map_or(0, |a| a + 1)
    }
}

/// Reads and checks a whole HEX file for a program memory of `memory` bytes. Errors name
/// the line and what is wrong.
pub fn parse_file(text: &str, memory: usize) -> Result<Program, String> {
    let mut p = Program::default();
    let mut ended = false;
    for (i, line) in text.lines().enumerate() {
        let ln = i + 1;
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        if ended {
            return Err(msg!("umpk-hex-after-end", line = ln).text);
        }
        let r = Record::parse(line.as_bytes()).map_err(|(_, m)| msg!("umpk-hex-line", line = ln, message = m).text)?;
        match r.kind {
            kind::DATA => {
                let start = r.offset as usize;
                let end = start + r.data.len();
                if end > memory {
                    return Err(msg!(
                        "umpk-hex-outside-memory",
                        line = ln,
                        first = format!("{start:04X}"),
                        last = format!("{:04X}", end - 1),
                        top = format!("{:04X}", memory - 1),
                        memory = memory
                    )
                    .text);
                }
                for (k, b) in r.data.iter().enumerate() {
                    if p.bytes.insert(start + k, *b).is_some() {
                        return Err(msg!("umpk-hex-twice", line = ln, address = format!("{:04X}", start + k)).text);
                    }
                }
            }
            kind::END => ended = true,
            kind::START if r.data.is_empty() => {}
            kind::START => {
                // Standard Intel HEX calls type 02 an extended segment address (2 data bytes);
                // to the UMPK 02 is the start record, which carries no data.
                return Err(msg!("umpk-hex-type-02", line = ln, count = r.data.len()).text);
            }
            kind::INFO => {
                if r.data.is_empty() || r.data.len() > INFO_LEN {
                    return Err(msg!("umpk-hex-info-size", line = ln, count = r.data.len()).text);
                }
                p.info = Some(r.data);
            }
            k => return Err(msg!("umpk-hex-record-type", line = ln, rtype = format!("{k:02X}")).text),
        }
    }
    if !ended {
        return Err(msg!("umpk-hex-no-end").text);
    }
    if p.bytes.is_empty() {
        return Err(msg!("umpk-hex-no-data").text);
    }
    Ok(p)
}

/// The program's data as page-aligned 64-byte data records, in address order; pages with
/// no data are left out, gaps inside a page are 0xFF.
pub fn pages(p: &Program) -> Vec<Record> {
    let mut out: Vec<Record> = Vec::new();
    for (&addr, &b) in &p.bytes {
        let page = addr / PAGE * PAGE;
        if out.last().map(|r| r.offset as usize) != Some(page) {
            out.push(Record::data(page as u16, &[0xFF; PAGE]));
        }
        out.last_mut().expect("pushed").data[addr - page] = b;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_manuals_records_byte_for_byte() {
        // Table 8: start :00000002FE, end :00000001FF.
        assert_eq!(Record::start().encode(), b":00000002FE");
        assert_eq!(Record::end().encode(), b":00000001FF");
        assert_eq!(Record::parse(b":00000002FE").unwrap(), Record::start());
        assert_eq!(Record::parse(b":00000001FF").unwrap(), Record::end());
        // Program info "LAB1": 04 00 00 03 4C 41 42 31 → sum 0x107, checksum 0xF9.
        assert_eq!(Record::info(b"LAB1").encode(), b":040000034C414231F9");
        // A data record at 0x0040: 02 00 40 00 12 34 → 0x88, checksum 0x78.
        assert_eq!(Record::data(0x40, &[0x12, 0x34]).encode(), b":02004000123478");
        // The appendix's rule: all pairs from RECLEN through CHKSUM sum to 0.
        let r = Record::data(0x0BC0, &[0xA5; 64]).encode();
        let bytes: Vec<u8> = r[1..].chunks(2).map(|p| hex_pair(p).unwrap()).collect();
        assert_eq!(sum(&bytes), 0);
        assert_eq!(Record::text_len(&r[..3]), Some(r.len()));
    }

    #[test]
    fn bad_records_get_the_plcs_letters() {
        assert_eq!(Record::parse(b":00000001FE").unwrap_err().0, b'E');
        assert_eq!(Record::parse(b":0000000G01FF").unwrap_err().0, b'C');
        assert_eq!(Record::parse(b"00000001FF").unwrap_err().0, b'C');
        assert_eq!(Record::parse(b":01000000FF").unwrap_err().0, b'C', "RECLEN larger than the data");
        assert_eq!(Record::parse(b":").unwrap_err().0, b'C');
    }

    #[test]
    fn files_are_validated_whole_and_reblocked_into_pages() {
        let mut f = String::new();
        f.push_str(&String::from_utf8(Record::info(b"LAB1").encode()).unwrap());
        for (a, n) in [(0x00u16, 16usize), (0x10, 16), (0x48, 8)] {
            f.push('\n');
            f.push_str(&String::from_utf8(Record::data(a, &vec![a as u8; n]).encode()).unwrap());
        }
        f.push_str("\r\n:00000001FF\r\n");
        let p = parse_file(&f, 2048).unwrap();
        assert_eq!(p.info.as_deref(), Some(&b"LAB1"[..]));
        assert_eq!(p.end(), 0x50);
        let pg = pages(&p);
        assert_eq!(pg.len(), 2);
        assert_eq!((pg[0].offset, pg[0].data.len(), pg[0].data[0x10], pg[0].data[0x20]), (0, 64, 0x10, 0xFF));
        assert_eq!((pg[1].offset, pg[1].data[8], pg[1].data[7]), (0x40, 0x48, 0xFF));
        // Errors name the line.
        let e = parse_file(":0108000000F7\n:00000001FF\n", 2048).unwrap_err();
        assert!(e.contains("line 1") && e.contains("outside the program memory"), "{e}");
        assert!(parse_file(":0108000000F7\n:00000001FF\n", 3072).is_ok(), "inside 3 KB");
        assert!(parse_file(":0100000000FF\n", 2048).unwrap_err().contains("no end record"));
        let twice = ":0100000000FF\n:0100000000FF\n:00000001FF\n";
        assert!(parse_file(twice, 2048).unwrap_err().contains("line 2"));
        assert!(parse_file(":020000040000FA\n:00000001FF\n", 2048).unwrap_err().contains("type 04"));
        // Type 02 with data (an Intel HEX extended segment address) is not the UMPK's start.
        let e = parse_file(":020000021000EC\n:0100000012ED\n:00000001FF\n", 2048).unwrap_err();
        assert!(e.starts_with("line 1: a type-02 record with 2 data byte(s)") && e.contains("remove the line"), "{e}");
        assert!(!e.contains("not one the UMPK takes"), "{e}");
        assert!(parse_file(":0100000000FE\n:00000001FF\n", 2048).unwrap_err().contains("checksum"));
    }
}
