//! Cutting a byte stream back into frames, for recording. Stream transports hand over
//! whatever the operating system delivered (a reply may arrive in two pieces, two replies in
//! one); a recording holds whole frames. Pure and linear in its input.
//!
//! - Modbus TCP: the MBAP length field says where a frame ends (Modbus Messaging on TCP/IP
//!   Implementation Guide V1.0b §3.1.3); a header that cannot be a Modbus one (protocol id
//!   not 0, length 0 or past 254) ends the framing: the rest is kept as one frame.
//! - Modbus RTU replies: the length follows from the function code (Modbus over serial line
//!   V1.02 §2.5.1): an exception is 5 bytes, a read reply 5 + byte count, a write echo 8.
//!   Anything else is kept until the next request, then recorded as one frame.

use crate::core::trace::Proto;

/// Where the first frame in `buf` ends, if it is complete; `Some(buf.len())` when the bytes
/// cannot be framed (they go out as one frame).
pub fn frame_end(proto: Proto, request: bool, buf: &[u8]) -> Option<usize> {
    match proto {
        Proto::ModbusTcp => {
            if buf.len() < 7 {
                return None;
            }
            let len = usize::from(u16::from_be_bytes([buf[4], buf[5]]));
            if buf[2..4] != [0, 0] || len == 0 || len > 254 {
                return Some(buf.len());
            }
            (buf.len() >= 6 + len).then_some(6 + len)
        }
        Proto::ModbusRtu | Proto::RtuOverTcp if !request => {
            if buf.len() < 3 {
                return None;
            }
            let n = match buf[1] {
                f if f & 0x80 != 0 => 5,
                0x01..=0x04 => 5 + usize::from(buf[2]),
                0x05 | 0x06 | 0x0F | 0x10 => 8,
                _ => return None,
            };
            (buf.len() >= n).then_some(n)
        }
        // UMPK replies come in pieces of unknown shape (echo, CR LF, monitor packets): kept
        // until the next command.
        Proto::Umpk if !request => None,
        // Requests are written whole; servo, FX and undeclared frames arrive whole.
        _ => Some(buf.len()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modbus_tcp_frames_end_where_the_mbap_length_says() {
        let two = [0, 1, 0, 0, 0, 5, 1, 3, 2, 0, 7, 0, 2, 0, 0, 0, 3, 1];
        assert_eq!(frame_end(Proto::ModbusTcp, false, &two), Some(11));
        assert_eq!(frame_end(Proto::ModbusTcp, false, &two[..9]), None, "half a frame waits");
        assert_eq!(frame_end(Proto::ModbusTcp, false, &[9, 9, 9, 9, 9, 9, 9, 9]), Some(8), "not Modbus: all");
    }

    #[test]
    fn rtu_replies_end_by_function_code() {
        // 01 03 02 00 07 CRC: a read reply with 2 data bytes.
        assert_eq!(frame_end(Proto::ModbusRtu, false, &[1, 3, 2, 0, 7, 0xF9, 0x86, 1]), Some(7));
        assert_eq!(frame_end(Proto::ModbusRtu, false, &[1, 0x83, 2, 0xC0, 0xF1]), Some(5));
        assert_eq!(frame_end(Proto::ModbusRtu, false, &[1, 6, 0, 100, 0, 7]), None);
        assert_eq!(frame_end(Proto::ModbusRtu, false, &[1, 0x2B, 0]), None, "unknown: wait");
        assert_eq!(frame_end(Proto::ModbusRtu, true, &[1, 3, 0, 100, 0, 1, 0, 0]), Some(8));
    }
}
