//! Modbus RTU framing for the simulator's serial server (Modbus over serial line V1.02 §2.5):
//! unit id, PDU, CRC-16 (polynomial 0xA001, low byte first). Pure: bytes in, frames out.
//!
//! Why not tokio-modbus's RTU server: it only runs on a `tokio_serial::SerialStream`, which
//! costs a spurious wakeup and a `tcdrain` per frame on a pty (see
//! `core::link::fd_stream`), and its framing drops requests whose function code it does not
//! know, where a K2 answers *illegal function*. Here the frame length follows from the
//! function code for the codes the K2 implements (1–6, 15, 16); any other request ends
//! where a valid CRC ends it, and is answered with exception 01.
//!
//! Resynchronisation is silence-based, as the serial line specification frames RTU
//! (§2.5.1.1: a frame ends with 3.5 character times of silence): the server hands the
//! buffer to [`end_of_frame`] when the line falls silent, which drops whatever could not be
//! taken as a frame, so a bad CRC or a truncated request costs that request only. What
//! arrived between two silences with a valid CRC over its whole length is one frame even
//! when its byte count says otherwise (quantity 0 and byte count 0 followed by data): it is
//! decoded and refused with 03, as Modbus TCP refuses the same PDU. Finding
//! where an unknown function's frame ends runs one CRC pass over the buffer (linear), so
//! noise cannot stall the server.
//!
//! The PDU decoder ([`decode_pdu`]) and encoder ([`encode_pdu`]) are shared with the TCP
//! transports (`super::modbus_net`), so every transport answers the same malformed request
//! with the same exception.

use tokio_modbus::{ExceptionCode, Request, Response};

/// Longest RTU frame (§2.5.1).
pub const MAX_FRAME: usize = 256;

/// CRC-16/MODBUS of each byte value (one table step per byte instead of eight shifts).
const CRC_TABLE: [u16; 256] = {
    let mut t = [0u16; 256];
    let mut i = 0;
    while i < 256 {
        let mut crc = i as u16;
        let mut k = 0;
        while k < 8 {
            crc = if crc & 1 != 0 { (crc >> 1) ^ 0xA001 } else { crc >> 1 };
            k += 1;
        }
        t[i] = crc;
        i += 1;
    }
    t
};

/// CRC-16/MODBUS.
pub fn crc16(data: &[u8]) -> u16 {
    data.iter().fold(0xFFFF, |crc, b| crc_step(crc, *b))
}

/// Extends a running CRC-16/MODBUS by one byte.
fn crc_step(crc: u16, b: u8) -> u16 {
    (crc >> 8) ^ CRC_TABLE[((crc ^ b as u16) & 0xFF) as usize]
}

fn crc_ok(frame: &[u8]) -> bool {
    let n = frame.len();
    n >= 4 && crc16(&frame[..n - 2]) == u16::from_le_bytes([frame[n - 2], frame[n - 1]])
}

/// A request taken off the line.
#[derive(Debug, PartialEq)]
pub enum Frame {
    /// A request the K2 implements, decoded.
    Request { unit: u8, request: Request<'static> },
    /// A well-formed frame with a function code the K2 does not implement (or a malformed
    /// body): answered with the exception.
    Refuse { unit: u8, function: u8, exception: ExceptionCode },
}

fn be16(b: &[u8], at: usize) -> u16 {
    u16::from_be_bytes([b[at], b[at + 1]])
}

/// Takes the next request frame off the front of `buf`. Returns `None` when more bytes are
/// needed; drops leading bytes that cannot start a valid frame (noise, a bad CRC: a slave
/// stays silent then).
pub fn next_frame(buf: &mut Vec<u8>) -> Option<Frame> {
    loop {
        if buf.len() < 4 {
            return None;
        }
        let fc = buf[1];
        let len = match fc {
            0x01..=0x06 => Some(8),
            0x0F | 0x10 if buf.len() >= 7 => Some(9 + buf[6] as usize),
            0x0F | 0x10 => return None,
            _ => None,
        };
        match len {
            Some(n) if n > MAX_FRAME => {}
            Some(n) if buf.len() < n => return None,
            Some(n) => {
                if crc_ok(&buf[..n]) {
                    let frame = decode(&buf[..n]);
                    buf.drain(..n);
                    return Some(frame);
                }
            }
            None => {
                // Unknown length: the frame ends where a CRC matches (one running CRC pass).
                if let Some(n) = first_crc_end(&buf[..buf.len().min(MAX_FRAME)]) {
                    let frame: Vec<u8> = buf.drain(..n).collect();
                    return Some(Frame::Refuse {
                        unit: frame[0],
                        function: fc,
                        exception: ExceptionCode::IllegalFunction,
                    });
                }
                if buf.len() < MAX_FRAME {
                    return None;
                }
            }
        }
        buf.remove(0); // resynchronise
    }
}

/// The shortest prefix length ≥ 4 whose last two bytes are the CRC of the rest, found in
/// one pass (the CRC of each prefix extends the previous one).
fn first_crc_end(b: &[u8]) -> Option<usize> {
    let mut crc = 0xFFFFu16;
    for n in 0..b.len() {
        // `crc` covers b[..n]; a frame of length n + 2 ends with that CRC.
        if n >= 2 && n + 2 <= b.len() && crc == u16::from_le_bytes([b[n], b[n + 1]]) {
            return Some(n + 2);
        }
        crc = crc_step(crc, b[n]);
    }
    None
}

/// What the bytes at the front of a buffer are, for a receiver framing by silence.
#[derive(Debug, PartialEq)]
pub enum Take {
    /// A whole frame (taken off the buffer).
    Frame(Frame),
    /// The start of a frame: more bytes are needed.
    More,
    /// Not a frame (a bad CRC, no CRC within the longest frame): discard until silence.
    Garbage,
}

/// Takes the frame at the very front of `buf`, without sliding through it: with
/// silence-based framing a frame starts where the line fell quiet, so the work per byte
/// received is bounded and noise costs no more than its length.
pub fn take_frame(buf: &mut Vec<u8>) -> Take {
    if buf.len() < 4 {
        return Take::More;
    }
    let fc = buf[1];
    let len = match fc {
        0x01..=0x06 => Some(8),
        0x0F | 0x10 if buf.len() >= 7 => Some(9 + buf[6] as usize),
        0x0F | 0x10 => return Take::More,
        _ => None,
    };
    match len {
        Some(n) if n > MAX_FRAME => Take::Garbage,
        Some(n) if buf.len() < n => Take::More,
        Some(n) if crc_ok(&buf[..n]) => {
            let frame = decode(&buf[..n]);
            buf.drain(..n);
            Take::Frame(frame)
        }
        Some(_) => Take::Garbage,
        None => match first_crc_end(&buf[..buf.len().min(MAX_FRAME)]) {
            Some(n) => {
                let frame: Vec<u8> = buf.drain(..n).collect();
                Take::Frame(Frame::Refuse { unit: frame[0], function: fc, exception: ExceptionCode::IllegalFunction })
            }
            None if buf.len() >= MAX_FRAME => Take::Garbage,
            None => Take::More,
        },
    }
}

/// A receiver framing by silence (module doc): bytes go in as they arrive, frames come out.
/// Bytes whose length fields do not make a frame (a bad CRC where the byte count says the
/// frame ends, a byte count that promises more than comes) are held until the line falls
/// silent: if what arrived up to the silence is one frame with a valid CRC over its whole
/// length, it is a request whose length fields disagree with its length and gets the
/// exception Modbus TCP gives it (03, through [`decode_pdu`]); anything else is dropped.
#[derive(Default)]
pub struct Receiver {
    buf: Vec<u8>,
    discarding: bool,
}

impl Receiver {
    /// True while bytes wait for the rest of their frame (or are being discarded), i.e.
    /// while silence on the line means something.
    pub fn pending(&self) -> bool {
        !self.buf.is_empty() || self.discarding
    }

    /// Bytes arrived; returns the frames they complete.
    pub fn bytes(&mut self, data: &[u8]) -> Vec<Frame> {
        let mut out = Vec::new();
        if self.discarding {
            // Held up to one byte past the longest frame, for the check at silence.
            let room = (MAX_FRAME + 1).saturating_sub(self.buf.len()).min(data.len());
            self.buf.extend_from_slice(&data[..room]);
            return out;
        }
        self.buf.extend_from_slice(data);
        loop {
            match take_frame(&mut self.buf) {
                Take::Frame(f) => out.push(f),
                Take::More => break,
                Take::Garbage => {
                    self.buf.truncate(MAX_FRAME + 1);
                    self.discarding = true;
                    break;
                }
            }
        }
        out
    }

    /// The line fell silent: the frames still buffered, and a clean start.
    pub fn silence(&mut self) -> Vec<Frame> {
        let discarding = std::mem::take(&mut self.discarding);
        if let Some(f) = whole_frame(&self.buf) {
            self.buf.clear();
            return vec![f];
        }
        if discarding {
            self.buf.clear();
            return Vec::new();
        }
        end_of_frame(&mut self.buf)
    }
}

/// What arrived between two silences as one frame, when its CRC is valid over its whole
/// length (at most [`MAX_FRAME`]): the request decoded, or the exception it gets.
fn whole_frame(buf: &[u8]) -> Option<Frame> {
    (buf.len() <= MAX_FRAME && crc_ok(buf)).then(|| decode(buf))
}

/// The line fell silent: takes the frames still in `buf`, then drops what is left (a
/// damaged or truncated request, noise), so the next request starts clean. It slides
/// through `buf` byte by byte, so it is meant for what [`Receiver`] holds at a silence (at
/// most one frame's worth, under 270 bytes), not for arbitrary streams.
pub fn end_of_frame(buf: &mut Vec<u8>) -> Vec<Frame> {
    let mut out = Vec::new();
    while !buf.is_empty() {
        match next_frame(buf) {
            Some(f) => out.push(f),
            // What waits for bytes that will not come is not a frame: skip its first byte
            // (a whole request may still follow a damaged one in the same burst).
            None => {
                buf.remove(0);
            }
        }
    }
    out
}

/// Decodes a complete, CRC-checked frame of a function code the K2 implements.
fn decode(f: &[u8]) -> Frame {
    decode_pdu(f[0], &f[1..f.len() - 2])
}

/// Decodes a request PDU (function code and data) for `unit`: a request the K2 implements,
/// or the exception a malformed one gets — 01 for a function it does not implement, 03 for
/// a length, byte count or value that does not match the function (Modbus application
/// protocol §6, §7).
pub fn decode_pdu(unit: u8, pdu: &[u8]) -> Frame {
    let fc = pdu.first().copied().unwrap_or(0);
    let bad = |e| Frame::Refuse { unit, function: fc, exception: e };
    if !matches!(fc, 0x01..=0x06 | 0x0F | 0x10) {
        return bad(ExceptionCode::IllegalFunction);
    }
    let fixed = matches!(fc, 0x01..=0x06);
    if pdu.len() < 5 || (fixed && pdu.len() != 5) || (!fixed && pdu.len() < 6) {
        return bad(ExceptionCode::IllegalDataValue);
    }
    let (a, q) = (be16(pdu, 1), be16(pdu, 3));
    let data = if fixed { &[][..] } else { &pdu[6..] };
    if !fixed && data.len() != pdu[5] as usize {
        return bad(ExceptionCode::IllegalDataValue);
    }
    // The quantities the application protocol allows (V1.1b3 §6.1–§6.4, §6.11, §6.12: read
    // coils/inputs 1…0x7D0, read registers 1…0x7D, write coils 1…0x7B0, write registers
    // 1…0x7B); anything else is exception 03 before the address is looked at.
    let most = match fc {
        0x01 | 0x02 => 0x7D0,
        0x03 | 0x04 => 0x7D,
        0x0F => 0x7B0,
        0x10 => 0x7B,
        _ => u16::MAX,
    };
    if (!fixed || fc <= 0x04) && !(1..=most).contains(&q) {
        return bad(ExceptionCode::IllegalDataValue);
    }
    let request = match fc {
        0x01 => Request::ReadCoils(a, q),
        0x02 => Request::ReadDiscreteInputs(a, q),
        0x03 => Request::ReadHoldingRegisters(a, q),
        0x04 => Request::ReadInputRegisters(a, q),
        0x05 => match q {
            0xFF00 => Request::WriteSingleCoil(a, true),
            0x0000 => Request::WriteSingleCoil(a, false),
            _ => return bad(ExceptionCode::IllegalDataValue),
        },
        0x06 => Request::WriteSingleRegister(a, q),
        0x0F => {
            if data.len() != (q as usize).div_ceil(8) {
                return bad(ExceptionCode::IllegalDataValue);
            }
            let bits = (0..q as usize).map(|i| data[i / 8] >> (i % 8) & 1 != 0).collect::<Vec<_>>();
            Request::WriteMultipleCoils(a, bits.into())
        }
        0x10 => {
            if data.len() != 2 * q as usize {
                return bad(ExceptionCode::IllegalDataValue);
            }
            Request::WriteMultipleRegisters(a, data.chunks_exact(2).map(|c| be16(c, 0)).collect::<Vec<_>>().into())
        }
        _ => return bad(ExceptionCode::IllegalFunction),
    };
    Frame::Request { unit, request }
}

/// Encodes a reply frame (with CRC) for `unit`.
pub fn encode(unit: u8, function: u8, reply: &Result<Response, ExceptionCode>) -> Vec<u8> {
    let mut f = vec![unit];
    f.extend(encode_pdu(function, reply));
    let crc = crc16(&f);
    f.extend(crc.to_le_bytes());
    f
}

/// Encodes a reply PDU: the function code and data, or the function code | 0x80 and the
/// exception code.
pub fn encode_pdu(function: u8, reply: &Result<Response, ExceptionCode>) -> Vec<u8> {
    let mut f = Vec::with_capacity(MAX_FRAME);
    let bits = |f: &mut Vec<u8>, b: &[bool]| {
        let mut packed = vec![0u8; b.len().div_ceil(8)];
        for (i, on) in b.iter().enumerate() {
            packed[i / 8] |= (*on as u8) << (i % 8);
        }
        f.push(packed.len() as u8);
        f.extend(packed);
    };
    let put = |f: &mut Vec<u8>, v: u16| f.extend(v.to_be_bytes());
    match reply {
        Err(e) => {
            f.push(function | 0x80);
            f.push(u8::from(*e));
        }
        Ok(r) => {
            f.push(function);
            match r {
                Response::ReadCoils(b) | Response::ReadDiscreteInputs(b) => bits(&mut f, b),
                Response::ReadHoldingRegisters(w) | Response::ReadInputRegisters(w) => {
                    f.push(2 * w.len() as u8);
                    w.iter().for_each(|v| put(&mut f, *v));
                }
                Response::WriteSingleCoil(a, v) => {
                    put(&mut f, *a);
                    put(&mut f, if *v { 0xFF00 } else { 0 });
                }
                Response::WriteMultipleCoils(a, n) | Response::WriteMultipleRegisters(a, n) => {
                    put(&mut f, *a);
                    put(&mut f, *n);
                }
                Response::WriteSingleRegister(a, v) => {
                    put(&mut f, *a);
                    put(&mut f, *v);
                }
                _ => {
                    f.clear();
                    f.push(function | 0x80);
                    f.push(u8::from(ExceptionCode::ServerDeviceFailure));
                }
            }
        }
    }
    f
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn golden_frames() {
        // Read one holding register at 100 (VW0) from unit 1: 01 03 00 64 00 01 C5 D5.
        let mut buf = vec![0x01, 0x03, 0x00, 0x64, 0x00, 0x01, 0xC5, 0xD5];
        assert_eq!(
            next_frame(&mut buf),
            Some(Frame::Request { unit: 1, request: Request::ReadHoldingRegisters(100, 1) })
        );
        assert!(buf.is_empty());
        // Its reply, value 0: 01 03 02 00 00 B8 44.
        assert_eq!(encode(1, 3, &Ok(Response::ReadHoldingRegisters(vec![0]))), vec![1, 3, 2, 0, 0, 0xB8, 0x44]);
        // Exception: 01 83 02 C0 F1 (illegal data address).
        assert_eq!(encode(1, 3, &Err(ExceptionCode::IllegalDataAddress)), vec![1, 0x83, 2, 0xC0, 0xF1]);
        // Coils pack LSB first: 3 coils on, off, on → byte count 1, 0b101.
        let f = encode(1, 1, &Ok(Response::ReadCoils(vec![true, false, true])));
        assert_eq!(&f[..4], &[1, 1, 1, 0b101]);
    }

    #[test]
    fn partial_noise_and_bad_crc() {
        let frame = [0x01u8, 0x06, 0x00, 0x64, 0x12, 0x34];
        let crc = crc16(&frame).to_le_bytes();
        let mut buf = vec![0xFF]; // noise before the frame
        buf.extend_from_slice(&frame[..4]);
        assert_eq!(next_frame(&mut buf), None, "needs more bytes");
        buf.extend_from_slice(&frame[4..]);
        buf.extend_from_slice(&crc);
        assert_eq!(
            next_frame(&mut buf),
            Some(Frame::Request { unit: 1, request: Request::WriteSingleRegister(100, 0x1234) })
        );
        let mut bad = vec![0x01, 0x03, 0x00, 0x64, 0x00, 0x01, 0xC5, 0xD6];
        assert_eq!(next_frame(&mut bad), None, "a bad CRC gets no reply");
        // Silence ends the damaged frame: the next request is taken whole.
        assert!(end_of_frame(&mut bad).is_empty() && bad.is_empty());
        let mut good = vec![0x01, 0x03, 0x00, 0x64, 0x00, 0x01, 0xC5, 0xD5];
        assert_eq!(end_of_frame(&mut good).len(), 1);
        // A truncated FC 16 (byte count promising more than comes) is dropped at silence too,
        // and a whole request in the same burst after it is still taken.
        let mut cut = vec![0x01, 0x10, 0x00, 0x64, 0x00, 0x7B, 0xF6, 0x11];
        assert!(end_of_frame(&mut cut).is_empty() && cut.is_empty());
        cut = vec![0x01, 0x10, 0x00, 0x64, 0x00, 0x7B, 0xF6, 0x11];
        cut.extend([0x01, 0x03, 0x00, 0x64, 0x00, 0x01, 0xC5, 0xD5]);
        assert_eq!(
            end_of_frame(&mut cut),
            vec![Frame::Request { unit: 1, request: Request::ReadHoldingRegisters(100, 1) }]
        );
    }

    /// The receiver's frames for `bytes` arriving in one burst and then silence.
    fn burst(bytes: &[u8]) -> Vec<Frame> {
        let mut rx = Receiver::default();
        let mut frames = rx.bytes(bytes);
        frames.extend(rx.silence());
        assert!(!rx.pending());
        frames
    }

    fn with_crc(mut f: Vec<u8>) -> Vec<u8> {
        let c = crc16(&f);
        f.extend(c.to_le_bytes());
        f
    }

    #[test]
    fn a_frame_whose_length_fields_disagree_with_its_length_is_framed_by_silence() {
        let refused =
            |unit, function| vec![Frame::Refuse { unit, function, exception: ExceptionCode::IllegalDataValue }];
        // Quantity 0, byte count 0 (pymodbus `write_registers(100, [])`, libmodbus
        // `modbus_write_bits(ctx, 1, 0, …)`): framed by the byte count, refused with 03.
        assert_eq!(burst(&with_crc(vec![1, 0x10, 0, 0x64, 0, 0, 0])), refused(1, 0x10));
        assert_eq!(burst(&with_crc(vec![1, 0x0F, 0, 0x01, 0, 0, 0])), refused(1, 0x0F));
        // Quantity 0 and byte count 0 with data after them, the CRC valid over the whole
        // frame: the byte count ends the frame too early, the silence ends it right.
        assert_eq!(burst(&with_crc(vec![1, 0x10, 0, 0x64, 0, 0, 0, 0x12, 0x34])), refused(1, 0x10));
        assert_eq!(burst(&with_crc(vec![1, 0x0F, 0, 0x01, 0, 0, 0, 0xFF])), refused(1, 0x0F));
        // A byte count promising more than comes; an FC 03 two bytes too long.
        assert_eq!(burst(&with_crc(vec![1, 0x10, 0, 0x64, 0, 1, 4, 0x12, 0x34])), refused(1, 0x10));
        assert_eq!(burst(&with_crc(vec![1, 0x03, 0, 0x64, 0, 1, 0, 0])), refused(1, 0x03));
        // Quantities past the specification's: 0x7B1 coils (247 bytes), 124 registers.
        let mut coils = vec![1, 0x0F, 0, 0, 0x07, 0xB1, 247];
        coils.extend([0u8; 247]);
        assert_eq!(burst(&with_crc(coils)), refused(1, 0x0F));
        assert_eq!(decode_pdu(1, &[0x03, 0, 0, 0, 0x7E]), refused(1, 0x03).remove(0));
        // A damaged frame is still dropped whole, and the next one served.
        let mut bad = with_crc(vec![1, 0x06, 0, 0x64, 0, 7]);
        bad[7] ^= 0x55;
        assert!(burst(&bad).is_empty());
        let mut rx = Receiver::default();
        assert!(rx.bytes(&bad).is_empty());
        assert!(rx.silence().is_empty());
        assert_eq!(rx.bytes(&with_crc(vec![1, 0x06, 0, 0x64, 0, 7])).len(), 1);
    }

    #[test]
    fn noise_is_scanned_in_linear_time() {
        // 16 KB of bytes that never end a frame, as the server's receiver gets them; then a
        // request after the silence is taken whole.
        let noise: Vec<u8> = (0..16_384u32).map(|i| (i * 7 + 3) as u8 | 0x80).collect();
        let mut rx = Receiver::default();
        let start = std::time::Instant::now();
        let mut frames = Vec::new();
        for chunk in noise.chunks(512) {
            frames.extend(rx.bytes(chunk));
        }
        frames.extend(rx.silence());
        assert!(start.elapsed() < std::time::Duration::from_secs(10), "{:?}", start.elapsed());
        assert!(frames.is_empty() && !rx.pending());
        let good = rx.bytes(&[0x01, 0x03, 0x00, 0x64, 0x00, 0x01, 0xC5, 0xD5]);
        assert_eq!(good, vec![Frame::Request { unit: 1, request: Request::ReadHoldingRegisters(100, 1) }]);
    }

    #[test]
    fn malformed_pdus_get_the_exception_the_specification_requires() {
        let refuse = |pdu: &[u8]| match decode_pdu(1, pdu) {
            Frame::Refuse { exception, .. } => Some(u8::from(exception)),
            Frame::Request { .. } => None,
        };
        assert_eq!(refuse(&[0x2B, 0x0E, 0x01, 0x00]), Some(1), "MEI: not a K2 function");
        assert_eq!(refuse(&[0x05, 0x00, 0x00, 0x12, 0x34]), Some(3), "FC 05 with an illegal coil value");
        // FC 15 whose quantity (16 coils) needs 2 bytes but carries 1: exception 03, no panic.
        assert_eq!(refuse(&[0x0F, 0x00, 0x00, 0x00, 0x10, 0x01, 0xFF]), Some(3));
        assert_eq!(refuse(&[0x0F, 0x00, 0x00, 0x00, 0x10, 0x02, 0xFF]), Some(3), "byte count beyond the data");
        assert_eq!(refuse(&[0x10, 0x00, 0x00, 0x00, 0x02, 0x02, 0, 0]), Some(3));
        assert_eq!(refuse(&[0x03, 0x00, 0x00]), Some(3), "too short");
        assert_eq!(refuse(&[]), Some(1));
        assert_eq!(refuse(&[0x03, 0x00, 0x64, 0x00, 0x01]), None);
    }

    #[test]
    fn multiple_writes_and_unknown_functions() {
        let mut f = vec![0x01, 0x10, 0x00, 0x64, 0x00, 0x02, 0x04, 0x11, 0x22, 0x33, 0x44];
        f.extend(crc16(&f).to_le_bytes());
        assert_eq!(
            next_frame(&mut f),
            Some(Frame::Request {
                unit: 1,
                request: Request::WriteMultipleRegisters(100, vec![0x1122, 0x3344].into())
            })
        );
        let mut f = vec![0x02, 0x0F, 0x01, 0x40, 0x00, 0x0A, 0x02, 0b1010_0101, 0b10];
        f.extend(crc16(&f).to_le_bytes());
        let Some(Frame::Request { request: Request::WriteMultipleCoils(320, bits), .. }) = next_frame(&mut f) else {
            panic!()
        };
        assert_eq!(bits.len(), 10);
        assert!(bits[0] && !bits[1] && bits[2] && bits[9]);
        // FC 08 (diagnostics) is not a K2 function: its frame ends at the CRC, exception 01.
        let mut f = vec![0x01, 0x08, 0x00, 0x00, 0xA5, 0x37];
        f.extend(crc16(&f).to_le_bytes());
        assert_eq!(
            next_frame(&mut f),
            Some(Frame::Refuse { unit: 1, function: 8, exception: ExceptionCode::IllegalFunction })
        );
        let mut f = vec![0x01, 0x05, 0x00, 0x00, 0x12, 0x34];
        f.extend(crc16(&f).to_le_bytes());
        assert_eq!(
            next_frame(&mut f),
            Some(Frame::Refuse { unit: 1, function: 5, exception: ExceptionCode::IllegalDataValue })
        );
    }
}
