//! The Kinco RS232 frame codec (`../shared/spec/kinco-servo.md` §2), pure: bytes in, typed
//! frames out, no I/O. Both the driver (master side) and the simulator (drive side) use it,
//! so the two cannot drift apart.
//!
//! Every frame, both directions, is exactly 10 bytes: drive id, function code, object
//! index (low byte first), sub-index, 4 data bytes (low byte first), checksum
//! `CHKS = -(byte0 + … + byte8) & 0xFF`. Write requests pick their function code from the
//! OBJECT's size (0x2F one byte, 0x2B two, 0x23 four) — never from the value's magnitude:
//! writing 5 to a 32-bit object is still a 0x23 frame. Reads are 0x40 with zero data.
//! Replies: 0x60 write acknowledged (data echoes the request), 0x4F/0x4B/0x43 read value
//! of 1/2/4 bytes, 0x80 error with a CiA-301 abort code in the data
//! (`../shared/spec/kinco-public-notes.md`, "Servo RS232 protocol details").

use crate::msg;
use std::fmt;

/// Function codes (§2).
pub mod func {
    pub const WRITE_4: u8 = 0x23;
    pub const WRITE_2: u8 = 0x2B;
    pub const WRITE_1: u8 = 0x2F;
    pub const READ: u8 = 0x40;
    pub const WRITE_OK: u8 = 0x60;
    pub const READ_4: u8 = 0x43;
    pub const READ_2: u8 = 0x4B;
    pub const READ_1: u8 = 0x4F;
    pub const ERROR: u8 = 0x80;
}

/// Frame length in bytes, both directions.
pub const FRAME_LEN: usize = 10;

/// An object's data size on the wire.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Size {
    B1,
    B2,
    B4,
}

impl Size {
    pub fn bytes(self) -> u32 {
        match self {
            Size::B1 => 1,
            Size::B2 => 2,
            Size::B4 => 4,
        }
    }
    pub fn bits(self) -> u32 {
        self.bytes() * 8
    }
    pub fn from_bits(bits: u32) -> Option<Size> {
        match bits {
            8 => Some(Size::B1),
            16 => Some(Size::B2),
            32 => Some(Size::B4),
            _ => None,
        }
    }
    /// All-ones mask of this size.
    pub fn mask(self) -> u32 {
        match self {
            Size::B1 => 0xFF,
            Size::B2 => 0xFFFF,
            Size::B4 => 0xFFFF_FFFF,
        }
    }
    /// The write request function code for an object of this size.
    pub fn write_func(self) -> u8 {
        match self {
            Size::B1 => func::WRITE_1,
            Size::B2 => func::WRITE_2,
            Size::B4 => func::WRITE_4,
        }
    }
    /// The read reply function code for an object of this size.
    pub fn read_reply_func(self) -> u8 {
        match self {
            Size::B1 => func::READ_1,
            Size::B2 => func::READ_2,
            Size::B4 => func::READ_4,
        }
    }
}

/// One 10-byte frame, decoded into its fields.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    pub id: u8,
    pub func: u8,
    pub index: u16,
    pub sub: u8,
    /// Data bytes 5–8, little-endian.
    pub data: u32,
}

/// `CHKS = (-(byte0 + … + byte8)) & 0xFF` (§2).
pub fn checksum(bytes: &[u8]) -> u8 {
    bytes.iter().fold(0u8, |s, b| s.wrapping_add(*b)).wrapping_neg()
}

impl Frame {
    /// A write request; the function code comes from the object's `size`, and only the
    /// object's bytes of `raw` are sent (unused data bytes are 0).
    pub fn write(id: u8, index: u16, sub: u8, size: Size, raw: u32) -> Frame {
        Frame { id, func: size.write_func(), index, sub, data: raw & size.mask() }
    }

    /// A read request (data bytes zero).
    pub fn read(id: u8, index: u16, sub: u8) -> Frame {
        Frame { id, func: func::READ, index, sub, data: 0 }
    }

    pub fn to_bytes(&self) -> [u8; FRAME_LEN] {
        let i = self.index.to_le_bytes();
        let d = self.data.to_le_bytes();
        let mut b = [self.id, self.func, i[0], i[1], self.sub, d[0], d[1], d[2], d[3], 0];
        b[9] = checksum(&b[..9]);
        b
    }

    /// Decodes 10 bytes, checking the checksum.
    pub fn from_bytes(b: &[u8; FRAME_LEN]) -> Result<Frame, BadChecksum> {
        let want = checksum(&b[..9]);
        if b[9] != want {
            return Err(BadChecksum { got: b[9], want });
        }
        Ok(Frame {
            id: b[0],
            func: b[1],
            index: u16::from_le_bytes([b[2], b[3]]),
            sub: b[4],
            data: u32::from_le_bytes([b[5], b[6], b[7], b[8]]),
        })
    }

    /// For write requests: the size the function code implies.
    pub fn write_size(&self) -> Option<Size> {
        match self.func {
            func::WRITE_1 => Some(Size::B1),
            func::WRITE_2 => Some(Size::B2),
            func::WRITE_4 => Some(Size::B4),
            _ => None,
        }
    }

    /// `6040.00`.
    pub fn object(&self) -> String {
        format!("{:04X}.{:02X}", self.index, self.sub)
    }
}

/// A frame whose checksum byte is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BadChecksum {
    pub got: u8,
    pub want: u8,
}

impl fmt::Display for BadChecksum {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (got, want) = (format!("{:02X}", self.got), format!("{:02X}", self.want));
        f.write_str(&msg!("servo-frame-checksum", got = got, want = want))
    }
}

/// What a reply means, once checked against its request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reply {
    /// 0x60: the write was accepted.
    Written,
    /// 0x43/0x4B/0x4F: the object's raw value, masked to the object's size.
    Value(u32),
    /// 0x80: the drive refused; CiA-301 abort code.
    Abort(u32),
}

/// Why a reply does not answer the request: a link error (the bytes are not ours).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Mismatch {
    BadChecksum(BadChecksum),
    Id {
        got: u8,
        want: u8,
    },
    Object {
        got: String,
        want: String,
    },
    Func {
        got: u8,
        request: u8,
    },
    /// A write acknowledgement whose data differs from the request.
    Echo {
        got: u32,
        want: u32,
    },
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Mismatch::BadChecksum(b) => f.write_str(&msg!(
                "servo-frame-reply-checksum",
                got = format!("{:02X}", b.got),
                want = format!("{:02X}", b.want)
            )),
            Mismatch::Id { got, want } => f.write_str(&msg!("servo-frame-id", got = *got, want = *want)),
            Mismatch::Object { got, want } => f.write_str(&msg!("servo-frame-object", got = got, want = want)),
            Mismatch::Func { got, request } => {
                f.write_str(&msg!("servo-frame-func", got = format!("{got:02X}"), request = format!("{request:02X}")))
            }
            Mismatch::Echo { got, want } => {
                f.write_str(&msg!("servo-frame-echo", got = format!("{got:08X}"), want = format!("{want:08X}")))
            }
        }
    }
}

/// Checks a reply against its request and decodes it. `size` is the object's size: read
/// values are masked to it, because drives may sign-extend 16-bit replies
/// (`01 4B 41 60 00 37 C4 FF FF 1A`, public notes).
pub fn decode_reply(request: &Frame, reply: &[u8; FRAME_LEN], size: Size) -> Result<Reply, Mismatch> {
    let r = Frame::from_bytes(reply).map_err(Mismatch::BadChecksum)?;
    if r.id != request.id {
        return Err(Mismatch::Id { got: r.id, want: request.id });
    }
    if (r.index, r.sub) != (request.index, request.sub) {
        return Err(Mismatch::Object { got: r.object(), want: request.object() });
    }
    let is_read = request.func == func::READ;
    match r.func {
        func::ERROR => Ok(Reply::Abort(r.data)),
        func::WRITE_OK if !is_read => {
            if r.data & size.mask() != request.data & size.mask() {
                return Err(Mismatch::Echo { got: r.data, want: request.data });
            }
            Ok(Reply::Written)
        }
        func::READ_1 | func::READ_2 | func::READ_4 if is_read => {
            let len = match r.func {
                func::READ_1 => Size::B1,
                func::READ_2 => Size::B2,
                _ => Size::B4,
            };
            Ok(Reply::Value(r.data & len.mask() & size.mask()))
        }
        got => Err(Mismatch::Func { got, request: request.func }),
    }
}

/// The meaning of an abort code, in words (FD5P manual table 10-14 via the public notes;
/// 0x06090030 is CiA 301's "value range exceeded").
pub fn abort_text(code: u32) -> String {
    abort_text_in(crate::core::msg::language(), code)
}

/// [`abort_text`] in a given language.
pub fn abort_text_in(lang: crate::core::msg::Lang, code: u32) -> String {
    let key = match code {
        0x0504_0001 | 0x0601_0001 | 0x0601_0002 | 0x0602_0000 | 0x0604_0041 | 0x0607_0010 | 0x0607_0012
        | 0x0609_0030 => format!("x{code:08X}"),
        _ => "other".to_string(),
    };
    msg!(lang: lang, "servo-abort", code = key).text
}

/// Abort codes the simulator sends.
pub mod abort {
    pub const READ_ONLY: u32 = 0x0601_0002;
    pub const WRITE_ONLY: u32 = 0x0601_0001;
    pub const LENGTH_MISMATCH: u32 = 0x0607_0010;
    pub const INVALID_COMMAND: u32 = 0x0504_0001;
    pub const VALUE_RANGE: u32 = 0x0609_0030;
}

/// What the streaming decoder found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decoded {
    /// Fewer than 10 bytes are buffered.
    NeedMore,
    /// A whole frame with a good checksum.
    Frame(Frame),
    /// 10 bytes whose checksum is wrong (they are consumed).
    Bad([u8; FRAME_LEN], BadChecksum),
}

/// A streaming decoder over a byte buffer: feed bytes as they arrive, take frames out.
/// Frames have no delimiter, so alignment comes from the line: a reader that sees a gap
/// (the simulator) or a timeout (the driver) calls [`FrameBuffer::clear`] to resynchronise.
#[derive(Clone, Debug, Default)]
pub struct FrameBuffer {
    buf: Vec<u8>,
}

impl FrameBuffer {
    pub fn new() -> FrameBuffer {
        FrameBuffer::default()
    }
    pub fn push(&mut self, bytes: &[u8]) {
        self.buf.extend_from_slice(bytes);
    }
    pub fn len(&self) -> usize {
        self.buf.len()
    }
    pub fn is_empty(&self) -> bool {
        self.buf.is_empty()
    }
    /// The bytes buffered but not yet decoded.
    pub fn pending(&self) -> &[u8] {
        &self.buf
    }
    pub fn clear(&mut self) {
        self.buf.clear();
    }
    /// Takes the next 10 raw bytes, if there are 10.
    pub fn next_raw(&mut self) -> Option<[u8; FRAME_LEN]> {
        if self.buf.len() < FRAME_LEN {
            return None;
        }
        let mut b = [0u8; FRAME_LEN];
        b.copy_from_slice(&self.buf[..FRAME_LEN]);
        self.buf.drain(..FRAME_LEN);
        Some(b)
    }
    /// Decodes the next frame.
    pub fn next_frame(&mut self) -> Decoded {
        match self.next_raw() {
            None => Decoded::NeedMore,
            Some(b) => match Frame::from_bytes(&b) {
                Ok(f) => Decoded::Frame(f),
                Err(e) => Decoded::Bad(b, e),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hex(s: &str) -> [u8; 10] {
        let v: Vec<u8> = s.split_whitespace().map(|b| u8::from_str_radix(b, 16).unwrap()).collect();
        v.try_into().unwrap()
    }

    // The manual's four worked examples (kinco-servo.md §2), byte for byte.
    #[test]
    fn golden_write_controlword_enable() {
        // 01 id, 2B write 2 bytes, 40 60 index 6040 low byte first, 00 sub, 0F 00 00 00 data, 25 checksum
        let f = Frame::write(1, 0x6040, 0x00, Size::B2, 0x000F);
        assert_eq!(f.to_bytes(), hex("01 2B 40 60 00 0F 00 00 00 25"));
    }

    #[test]
    fn golden_write_acknowledgement() {
        let req = Frame::write(1, 0x6040, 0x00, Size::B2, 0x000F);
        let ack = hex("01 60 40 60 00 0F 00 00 00 F0");
        assert_eq!(Frame { func: func::WRITE_OK, ..req }.to_bytes(), ack, "the drive side encodes it");
        assert_eq!(decode_reply(&req, &ack, Size::B2), Ok(Reply::Written));
    }

    #[test]
    fn golden_read_statusword() {
        assert_eq!(Frame::read(1, 0x6041, 0x00).to_bytes(), hex("01 40 41 60 00 00 00 00 00 1E"));
    }

    #[test]
    fn golden_statusword_reply() {
        let req = Frame::read(1, 0x6041, 0);
        let reply = hex("01 4B 41 60 00 31 42 00 00 A0");
        assert_eq!(decode_reply(&req, &reply, Size::B2), Ok(Reply::Value(0x4231)));
        let f = Frame::from_bytes(&reply).unwrap();
        assert_eq!((f.func, f.index, f.sub, f.data), (func::READ_2, 0x6041, 0, 0x4231));
    }

    #[test]
    fn write_code_comes_from_the_object_size_not_the_value() {
        // 5 into a 32-bit object is still a 4-byte write; 0 into a byte object a 1-byte write.
        assert_eq!(Frame::write(1, 0x607A, 0, Size::B4, 5).to_bytes()[1], 0x23);
        assert_eq!(Frame::write(1, 0x6060, 0, Size::B1, 0).to_bytes()[1], 0x2F);
        // -3 into an 8-bit object: only its byte is sent, unused bytes are 0.
        let b = Frame::write(1, 0x6060, 0, Size::B1, (-3i32) as u32).to_bytes();
        assert_eq!(&b[5..9], &[0xFD, 0, 0, 0]);
        // -1 into a 32-bit object: all four bytes.
        let b = Frame::write(2, 0x60FF, 0, Size::B4, (-1i32) as u32).to_bytes();
        assert_eq!(&b[..9], &[0x02, 0x23, 0xFF, 0x60, 0x00, 0xFF, 0xFF, 0xFF, 0xFF]);
    }

    #[test]
    fn sign_extended_16_bit_reply_is_masked() {
        // Public notes: `01 4B 41 60 00 37 C4 FF FF 1A` is statusword 0xC437.
        let req = Frame::read(1, 0x6041, 0);
        assert_eq!(decode_reply(&req, &hex("01 4B 41 60 00 37 C4 FF FF 1A"), Size::B2), Ok(Reply::Value(0xC437)));
    }

    #[test]
    fn abort_reply_carries_the_code() {
        let req = Frame::write(1, 0x6041, 0, Size::B2, 1);
        let mut r = Frame { func: func::ERROR, data: abort::READ_ONLY, ..req };
        let reply = r.to_bytes();
        assert_eq!(decode_reply(&req, &reply, Size::B2), Ok(Reply::Abort(0x0601_0002)));
        assert_eq!(abort_text(0x0601_0002), "attempt to write a read-only object");
        r.data = 0x0602_0000;
        assert_eq!(decode_reply(&req, &r.to_bytes(), Size::B2), Ok(Reply::Abort(0x0602_0000)));
    }

    #[test]
    fn mismatches_are_link_errors() {
        let req = Frame::read(1, 0x6041, 0);
        let mut bad = hex("01 4B 41 60 00 31 42 00 00 A0");
        bad[9] = 0xA1;
        assert!(matches!(decode_reply(&req, &bad, Size::B2), Err(Mismatch::BadChecksum(_))));
        let other_id = Frame { id: 2, func: func::READ_2, ..req }.to_bytes();
        assert_eq!(decode_reply(&req, &other_id, Size::B2), Err(Mismatch::Id { got: 2, want: 1 }));
        let other_obj = Frame { func: func::READ_2, index: 0x6040, ..req }.to_bytes();
        assert!(matches!(decode_reply(&req, &other_obj, Size::B2), Err(Mismatch::Object { .. })));
        let ack_to_read = Frame { func: func::WRITE_OK, ..req }.to_bytes();
        assert!(matches!(decode_reply(&req, &ack_to_read, Size::B2), Err(Mismatch::Func { .. })));
        let w = Frame::write(1, 0x6040, 0, Size::B2, 0x0F);
        let wrong_echo = Frame { func: func::WRITE_OK, data: 0x06, ..w }.to_bytes();
        assert!(matches!(decode_reply(&w, &wrong_echo, Size::B2), Err(Mismatch::Echo { .. })));
    }

    #[test]
    fn streaming_decoder_needs_more_on_partial_input() {
        let mut fb = FrameBuffer::new();
        let reply = hex("01 4B 41 60 00 31 42 00 00 A0");
        fb.push(&reply[..4]);
        assert_eq!(fb.next_frame(), Decoded::NeedMore);
        fb.push(&reply[4..]);
        fb.push(&hex("01 60 40 60 00 0F 00 00 00 F0")[..3]);
        assert!(matches!(fb.next_frame(), Decoded::Frame(f) if f.data == 0x4231));
        assert_eq!(fb.next_frame(), Decoded::NeedMore);
        assert_eq!(fb.len(), 3);
        fb.clear();
        let mut bad = reply;
        bad[9] ^= 0xFF;
        fb.push(&bad);
        assert!(matches!(fb.next_frame(), Decoded::Bad(_, BadChecksum { want: 0xA0, .. })));
        assert!(fb.is_empty());
    }

    #[test]
    fn checksum_makes_the_byte_sum_zero() {
        for f in [Frame::read(7, 0x1234, 0x56), Frame::write(255, 0xFFFF, 0xFF, Size::B4, 0xDEAD_BEEF)] {
            let b = f.to_bytes();
            assert_eq!(b.iter().fold(0u8, |s, x| s.wrapping_add(*x)), 0);
            assert_eq!(Frame::from_bytes(&b), Ok(f));
        }
    }
}
