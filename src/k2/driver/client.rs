//! The driver's Modbus client framing: one request in flight on a [`Port`], Modbus TCP
//! (MBAP header, Modbus messaging on TCP/IP V1.0b §3.1.3) or RTU (unit id, PDU, CRC-16;
//! Modbus over serial line V1.02 §2.5.1), with the frame and reply buffers kept from one
//! request to the next.
//!
//! Why not tokio-modbus's client (used before): a read of 100 registers there decodes the
//! reply into a fresh `Vec<u16>` a word at a time through a cursor, inside a codec that
//! splits and copies `BytesMut` buffers, and the driver then copied the words again per
//! operand. Here the reply stays in the receive buffer and the driver decodes each operand
//! straight from its bytes ([`crate::k2::modbus_map::decode_reply`]): registers travel as
//! the big-endian memory image, so reading them is a slice of what arrived.
//!
//! What a reply must be to be taken, as tokio-modbus checked it: for TCP the transaction
//! id, protocol 0, the unit id and a length of 2…254; for RTU the unit id and the CRC — a
//! bad CRC drops the first byte and the frame is looked for again (a line glitch before the
//! reply), at most [`MAX_FRAME`] times, so the work is bounded by the bytes received. Then
//! the function code must be the request's, or the request's with 0x80 set (an exception).
//! Anything else fails the request as a link error (the driver reconnects and retries).
//! Bytes left from an earlier exchange are dropped before each request.
//!
//! Bytes that arrived but never made a valid frame are not silence: when the deadline
//! passes, the request fails with [`Garbled`] (what arrived, and the first RTU frame whose
//! CRC was wrong with the CRC it carried and the one its bytes need), as mbpoll reports
//! "Invalid CRC", so the driver can say the reply was damaged rather than missing.

use crate::core::link::port::Port;
use crate::k2::sim::rtu_frame::crc16;
use crate::msg;
use std::io;
use std::time::Instant;
use tokio_modbus::{ExceptionCode, Request, Response};

/// Longest RTU frame, and the most bytes dropped while looking for one.
const MAX_FRAME: usize = 256;

/// A Modbus client on one connection.
pub struct ModbusClient {
    port: Box<dyn Port>,
    rtu: bool,
    unit: u8,
    tid: u16,
    /// The request being sent (header, PDU, CRC).
    frame: Vec<u8>,
    /// Bytes received; the last reply's PDU is `rx[pdu.0..pdu.1]`.
    rx: Vec<u8>,
    pdu: (usize, usize),
}

/// What arrived for a request that got no valid reply frame before its deadline: the
/// payload of the `InvalidData` error [`ModbusClient`] returns then.
#[derive(Debug, Clone, PartialEq)]
pub struct Garbled {
    /// The first bytes that arrived (at most [`MAX_FRAME`]).
    pub arrived: Vec<u8>,
    /// How many bytes arrived in all.
    pub total: usize,
    /// The first RTU frame whose CRC was wrong: its bytes, the CRC it carried and the CRC
    /// its bytes need (printed low byte first, as on the wire).
    pub bad_crc: Option<(Vec<u8>, u16, u16)>,
}

impl std::fmt::Display for Garbled {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let hex = crate::core::trace::hex_bytes;
        let more = if self.total > self.arrived.len() { " …" } else { "" };
        let received = format!("{}{more}", hex(&self.arrived));
        let m = match &self.bad_crc {
            Some((frame, got, want)) => {
                let (frame_hex, got, want) = (hex(frame), hex(&got.to_le_bytes()), hex(&want.to_le_bytes()));
                if *frame == self.arrived && self.total == frame.len() {
                    msg!("k2-reply-bad-crc", frame = frame_hex, got = got, want = want)
                } else {
                    msg!("k2-reply-bad-crc-received", frame = frame_hex, got = got, want = want, received = received)
                }
            }
            None => msg!("k2-reply-no-frame", n = self.total, received = received),
        };
        f.write_str(&m)
    }
}

impl std::error::Error for Garbled {}

/// The [`Garbled`] inside an error from [`ModbusClient`], if that is what it is.
pub fn garbled(e: &io::Error) -> Option<&Garbled> {
    e.get_ref().and_then(|inner| inner.downcast_ref::<Garbled>())
}

fn invalid(msg: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, msg)
}

/// Where the reply frame at the front of the received bytes stands.
enum Found {
    /// A whole frame: the PDU's range.
    Pdu(usize, usize),
    More,
    /// Not a frame (RTU): drop the first byte and look again.
    Skip,
}

impl ModbusClient {
    pub fn new(port: Box<dyn Port>, rtu: bool, unit: u8) -> ModbusClient {
        ModbusClient {
            port,
            rtu,
            unit,
            tid: 0,
            frame: Vec::with_capacity(270),
            rx: Vec::with_capacity(270),
            pdu: (0, 0),
        }
    }

    /// Starts a request frame; the PDU follows with [`Self::put`].
    fn begin(&mut self, fc: u8) {
        self.frame.clear();
        if self.rtu {
            self.frame.push(self.unit);
        } else {
            self.tid = self.tid.wrapping_add(1);
            self.frame.extend_from_slice(&self.tid.to_be_bytes());
            self.frame.extend_from_slice(&[0, 0, 0, 0, self.unit]); // length set in `finish`
        }
        self.frame.push(fc);
    }

    fn put(&mut self, v: u16) {
        self.frame.extend_from_slice(&v.to_be_bytes());
    }

    fn finish(&mut self) {
        if self.rtu {
            let crc = crc16(&self.frame);
            self.frame.extend_from_slice(&crc.to_le_bytes());
        } else {
            let len = (self.frame.len() - 6) as u16;
            self.frame[4..6].copy_from_slice(&len.to_be_bytes());
        }
    }

    fn fc(&self) -> u8 {
        self.frame[if self.rtu { 1 } else { 7 }]
    }

    /// Reads `count` units from `start` with function `fc` (1–4). On success the reply's
    /// data (after the byte count) is [`Self::data`]; its length is checked by the caller.
    pub fn read(&mut self, fc: u8, start: u16, count: u16, deadline: Instant) -> io::Result<Result<(), ExceptionCode>> {
        self.begin(fc);
        self.put(start);
        self.put(count);
        self.finish();
        self.exchange(deadline)
    }

    /// The last reply's PDU after its function code.
    pub fn data(&self) -> &[u8] {
        &self.rx[self.pdu.0 + 1..self.pdu.1]
    }

    /// Sends any request the K2 implements (function codes 1–6, 15, 16) and decodes the reply.
    pub fn call(&mut self, req: &Request<'_>, deadline: Instant) -> io::Result<Result<Response, ExceptionCode>> {
        let fc = req.function_code().value();
        self.begin(fc);
        match req {
            Request::ReadCoils(a, n)
            | Request::ReadDiscreteInputs(a, n)
            | Request::ReadHoldingRegisters(a, n)
            | Request::ReadInputRegisters(a, n) => {
                self.put(*a);
                self.put(*n);
            }
            Request::WriteSingleCoil(a, on) => {
                self.put(*a);
                self.put(if *on { 0xFF00 } else { 0 });
            }
            Request::WriteSingleRegister(a, v) => {
                self.put(*a);
                self.put(*v);
            }
            Request::WriteMultipleCoils(a, bits) => {
                self.put(*a);
                self.put(bits.len() as u16);
                let mut packed = vec![0u8; bits.len().div_ceil(8)];
                for (i, on) in bits.iter().enumerate() {
                    packed[i / 8] |= (*on as u8) << (i % 8);
                }
                self.frame.push(packed.len() as u8);
                self.frame.extend_from_slice(&packed);
            }
            Request::WriteMultipleRegisters(a, words) => {
                self.put(*a);
                self.put(words.len() as u16);
                self.frame.push((2 * words.len()) as u8);
                words.iter().for_each(|w| self.put(*w));
            }
            other => {
                return Err(io::Error::new(
                    io::ErrorKind::Unsupported,
                    msg!("k2-not-k2-request", request = format!("{other:?}")).text,
                ))
            }
        }
        self.finish();
        if let Err(code) = self.exchange(deadline)? {
            return Ok(Err(code));
        }
        response(req, self.data()).map(Ok)
    }

    /// Sends the frame and waits for the reply frame; `Err(code)` inside is an exception.
    fn exchange(&mut self, deadline: Instant) -> io::Result<Result<(), ExceptionCode>> {
        self.rx.clear();
        self.port.send(&self.frame, deadline)?;
        let mut dropped = 0;
        // What arrived, for the diagnosis when no valid frame does.
        let mut seen = Garbled { arrived: Vec::new(), total: 0, bad_crc: None };
        let (lo, hi) = loop {
            match self.found()? {
                Found::Pdu(lo, hi) => break (lo, hi),
                Found::Skip if dropped < MAX_FRAME => {
                    if seen.bad_crc.is_none() {
                        seen.bad_crc = self.bad_crc();
                    }
                    self.rx.remove(0);
                    dropped += 1;
                    continue;
                }
                Found::Skip => return Err(io::Error::new(io::ErrorKind::InvalidData, seen)),
                Found::More => {}
            }
            let before = self.rx.len();
            match self.port.recv(&mut self.rx, deadline) {
                Ok(()) => {
                    let new = &self.rx[before..];
                    seen.total += new.len();
                    let room = MAX_FRAME.saturating_sub(seen.arrived.len()).min(new.len());
                    seen.arrived.extend_from_slice(&new[..room]);
                }
                Err(e) if e.kind() == io::ErrorKind::TimedOut && seen.total > 0 => {
                    return Err(io::Error::new(io::ErrorKind::InvalidData, seen));
                }
                Err(e) => return Err(e),
            }
        };
        self.pdu = (lo, hi);
        let fc = self.fc();
        match self.rx[lo] {
            f if f == fc => Ok(Ok(())),
            f if f == fc | 0x80 && hi - lo == 2 => Ok(Err(ExceptionCode::new(self.rx[lo + 1]))),
            f => Err(invalid(
                msg!("k2-reply-function-code", got = format!("{f:#04x}"), want = format!("{fc:#04x}")).into(),
            )),
        }
    }

    /// The RTU frame at the front of the received bytes when its CRC is what is wrong with
    /// it: its bytes, the CRC carried and the CRC needed.
    fn bad_crc(&self) -> Option<(Vec<u8>, u16, u16)> {
        let b = &self.rx;
        let len = rtu_len(b)?;
        let frame = b.get(..len)?;
        let (got, want) = (u16::from_le_bytes([frame[len - 2], frame[len - 1]]), crc16(&frame[..len - 2]));
        (got != want).then(|| (frame.to_vec(), got, want))
    }

    /// Frames the bytes received so far.
    fn found(&self) -> io::Result<Found> {
        let b = &self.rx;
        if self.rtu {
            if b.len() < 3 {
                return Ok(Found::More);
            }
            let Some(len) = rtu_len(b) else { return Ok(Found::Skip) };
            if b.len() < len {
                return Ok(Found::More);
            }
            if crc16(&b[..len - 2]) != u16::from_le_bytes([b[len - 2], b[len - 1]]) {
                return Ok(Found::Skip);
            }
            if b[0] != self.unit {
                return Err(invalid(msg!("k2-reply-unit", got = b[0], want = self.unit).into()));
            }
            Ok(Found::Pdu(1, len - 2))
        } else {
            if b.len() < 7 {
                return Ok(Found::More);
            }
            let len = u16::from_be_bytes([b[4], b[5]]) as usize;
            if b[2..4] != [0, 0] || !(2..=254).contains(&len) {
                return Err(invalid(msg!("k2-reply-not-tcp", header = format!("{:02x?}", &b[..7])).into()));
            }
            if b.len() < 6 + len {
                return Ok(Found::More);
            }
            let tid = u16::from_be_bytes([b[0], b[1]]);
            if tid != self.tid || b[6] != self.unit {
                return Err(invalid(
                    msg!("k2-reply-transaction", tid = tid, unit = b[6], want_tid = self.tid, want_unit = self.unit)
                        .into(),
                ));
            }
            Ok(Found::Pdu(7, 6 + len))
        }
    }
}

/// The length of the RTU reply frame starting `b` (at least 3 bytes), from its function
/// code and byte count; `None` when the function code is none a K2 answers with.
fn rtu_len(b: &[u8]) -> Option<usize> {
    let (&fc, &count) = (b.get(1)?, b.get(2)?);
    Some(match fc {
        0x01..=0x04 => 5 + count as usize,
        0x05 | 0x06 | 0x0F | 0x10 => 8,
        f if f & 0x80 != 0 => 5,
        _ => return None,
    })
}

/// A port replaying fixed bytes as the replies, in chunks of a given size
/// ([`fuzz_replies`]).
struct Replay {
    data: Vec<u8>,
    at: usize,
    chunk: usize,
}

impl Port for Replay {
    fn send(&mut self, _frame: &[u8], _deadline: Instant) -> io::Result<()> {
        Ok(())
    }
    fn recv(&mut self, buf: &mut Vec<u8>, _deadline: Instant) -> io::Result<()> {
        if self.at >= self.data.len() {
            return Err(io::Error::new(io::ErrorKind::UnexpectedEof, msg!("k2-no-more-replies").text));
        }
        let end = (self.at + self.chunk).min(self.data.len());
        buf.extend_from_slice(&self.data[self.at..end]);
        self.at = end;
        Ok(())
    }
}

/// Arbitrary bytes as what a device answered, to every request the driver sends, over TCP
/// (with the transaction id the client expects, so the rest of the frame is reached) and
/// RTU framing, arriving in chunks of 1, 7 and 300 bytes: the fuzz target `modbus_client`
/// ([`crate::fuzzing::modbus_client`]). Nothing may panic; every outcome is a value or an
/// error.
pub fn fuzz_replies(data: &[u8]) {
    let bits = [true, false, true];
    let words = [1u16, 2, 3];
    let requests = [
        Request::ReadCoils(0, 9),
        Request::ReadDiscreteInputs(0, 9),
        Request::ReadHoldingRegisters(0, 3),
        Request::ReadInputRegisters(0, 3),
        Request::WriteSingleCoil(0, true),
        Request::WriteSingleRegister(0, 7),
        Request::WriteMultipleCoils(0, std::borrow::Cow::Borrowed(&bits[..])),
        Request::WriteMultipleRegisters(0, std::borrow::Cow::Borrowed(&words[..])),
    ];
    let deadline = Instant::now() + std::time::Duration::from_secs(1);
    for rtu in [false, true] {
        let mut bytes = data.to_vec();
        if !rtu && bytes.len() >= 2 {
            bytes[..2].copy_from_slice(&1u16.to_be_bytes());
        }
        for chunk in [1, 7, 300] {
            for req in &requests {
                let port = Replay { data: bytes.clone(), at: 0, chunk };
                let mut c = ModbusClient::new(Box::new(port), rtu, 1);
                let _ = c.call(req, deadline);
            }
        }
    }
}

/// Decodes the data of a reply to `req` (after the function code).
fn response(req: &Request<'_>, d: &[u8]) -> io::Result<Response> {
    let bad = || invalid(msg!("k2-reply-malformed", request = format!("{req:?}"), data = format!("{d:02x?}")).into());

    let be = |at: usize| u16::from_be_bytes([d[at], d[at + 1]]);
    Ok(match req {
        Request::ReadCoils(..) | Request::ReadDiscreteInputs(..) => {
            if d.is_empty() || d.len() != 1 + d[0] as usize {
                return Err(bad());
            }
            let bits = (0..8 * d[0] as usize).map(|i| d[1 + i / 8] >> (i % 8) & 1 != 0).collect();
            if matches!(req, Request::ReadCoils(..)) {
                Response::ReadCoils(bits)
            } else {
                Response::ReadDiscreteInputs(bits)
            }
        }
        Request::ReadHoldingRegisters(..) | Request::ReadInputRegisters(..) => {
            if d.is_empty() || d.len() != 1 + d[0] as usize || !d[0].is_multiple_of(2) {
                return Err(bad());
            }
            let words = d[1..].chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]])).collect();
            if matches!(req, Request::ReadHoldingRegisters(..)) {
                Response::ReadHoldingRegisters(words)
            } else {
                Response::ReadInputRegisters(words)
            }
        }
        _ if d.len() != 4 => return Err(bad()),
        Request::WriteSingleCoil(..) => Response::WriteSingleCoil(be(0), be(2) == 0xFF00),
        Request::WriteSingleRegister(..) => Response::WriteSingleRegister(be(0), be(2)),
        Request::WriteMultipleCoils(..) => Response::WriteMultipleCoils(be(0), be(2)),
        Request::WriteMultipleRegisters(..) => Response::WriteMultipleRegisters(be(0), be(2)),
        _ => return Err(bad()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::link::port::AsyncPort;
    use crate::core::trace::Proto;
    use std::time::Duration;
    use tokio::io::{AsyncReadExt, AsyncWriteExt};

    /// A client on one end of a pipe and, on a thread of its own, a peer that answers each
    /// request it reads (of `req_len` bytes) with the next reply; the peer returns what it read.
    fn pair(rtu: bool, req_len: usize, replies: Vec<Vec<u8>>) -> (ModbusClient, std::thread::JoinHandle<Vec<Vec<u8>>>) {
        let (a, mut b) = tokio::io::duplex(1024);
        let peer = std::thread::spawn(move || {
            let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
            rt.block_on(async move {
                let mut seen = Vec::new();
                for reply in replies {
                    let mut req = vec![0u8; req_len];
                    if b.read_exact(&mut req).await.is_err() {
                        break;
                    }
                    seen.push(req);
                    b.write_all(&reply).await.unwrap();
                }
                seen
            })
        });
        let port = AsyncPort::new(Box::new(a), "pipe", Proto::Unknown, "peer").unwrap();
        (ModbusClient::new(Box::new(port), rtu, 1), peer)
    }

    fn soon() -> Instant {
        Instant::now() + Duration::from_secs(5)
    }

    fn rtu(mut f: Vec<u8>) -> Vec<u8> {
        f.extend(crc16(&f).to_le_bytes());
        f
    }

    #[test]
    fn tcp_frames_checked_and_data_left_in_place() {
        let replies = vec![
            // Transaction 1: FC 03, two registers.
            vec![0, 1, 0, 0, 0, 7, 1, 3, 4, 0x12, 0x34, 0x56, 0x78],
            // Transaction 2: exception 02.
            vec![0, 2, 0, 0, 0, 3, 1, 0x83, 2],
            // Transaction 3: answered with the wrong transaction id.
            vec![0, 9, 0, 0, 0, 5, 1, 3, 2, 0, 0],
        ];
        let (mut c, peer) = pair(false, 12, replies);
        assert!(c.read(3, 100, 2, soon()).unwrap().is_ok());
        assert_eq!(c.data(), &[4, 0x12, 0x34, 0x56, 0x78]);
        assert_eq!(c.read(3, 5000, 1, soon()).unwrap(), Err(ExceptionCode::IllegalDataAddress));
        let e = c.read(3, 100, 1, soon()).unwrap_err();
        assert!(e.to_string().contains("transaction 9"), "{e}");
        let seen = peer.join().unwrap();
        assert_eq!(seen[0], vec![0, 1, 0, 0, 0, 6, 1, 3, 0, 100, 0, 2], "MBAP header, FC 03, address, count");
    }

    #[test]
    fn rtu_resynchronises_after_noise_and_decodes_writes() {
        let mut noisy = vec![0xFF, 0x00];
        noisy.extend(rtu(vec![1, 3, 2, 0xAB, 0xCD]));
        let replies = vec![noisy, rtu(vec![1, 6, 0, 100, 0x12, 0x34]), rtu(vec![2, 3, 2, 0, 0])];
        let (mut c, peer) = pair(true, 8, replies);
        assert!(c.read(3, 100, 1, soon()).unwrap().is_ok());
        assert_eq!(c.data(), &[2, 0xAB, 0xCD]);
        let r = c.call(&Request::WriteSingleRegister(100, 0x1234), soon()).unwrap();
        assert_eq!(r, Ok(Response::WriteSingleRegister(100, 0x1234)));
        let e = c.read(3, 100, 1, soon()).unwrap_err();
        assert!(e.to_string().contains("unit 2"), "{e}");
        let seen = peer.join().unwrap();
        assert_eq!(seen[0], rtu(vec![1, 3, 0, 100, 0, 1]));
    }

    #[test]
    fn a_closed_connection_a_wrong_function_and_silence_are_errors() {
        let (mut c, peer) = pair(false, 12, vec![vec![0, 1, 0, 0, 0, 3, 1, 4, 0]]);
        let e = c.read(3, 100, 1, soon()).unwrap_err();
        assert!(e.to_string().contains("function code 0x04"), "{e}");
        peer.join().unwrap();
        let e = c.read(3, 100, 1, soon()).unwrap_err();
        assert!(matches!(e.kind(), io::ErrorKind::UnexpectedEof | io::ErrorKind::BrokenPipe), "{e}");
        // A peer that reads and never answers: the deadline ends the wait.
        let (mut c, peer) = pair(false, 12, vec![]);
        let (a, _keep) = tokio::io::duplex(64);
        drop(peer.join());
        c.port = Box::new(AsyncPort::new(Box::new(a), "pipe", Proto::Unknown, "peer").unwrap());
        let e = c.read(3, 100, 1, Instant::now() + Duration::from_millis(20)).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::TimedOut, "{e}");
    }
}
