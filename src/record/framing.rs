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
        // UMPK replies (manual §4.1): with echo on they end in CR LF; a monitor packet is 30
        // bytes from its 0xAA header; anything else (echo off: `R`, `#…CC`) is kept until the
        // next command, or until 1 KiB has piled up.
        Proto::Umpk if !request => {
            if buf.first() == Some(&crate::umpk::codec::MONITOR_HEADER) {
                return (buf.len() >= crate::umpk::codec::MONITOR_LEN).then_some(crate::umpk::codec::MONITOR_LEN);
            }
            match buf.windows(2).position(|w| w == b"\r\n") {
                Some(at) => Some(at + 2),
                None => (buf.len() >= 1024).then_some(buf.len()),
            }
        }
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
    fn umpk_replies_end_at_cr_lf_or_a_whole_monitor_packet() {
        assert_eq!(frame_end(Proto::Umpk, false, b"?03FD#06102910080001A8\r\n?0"), Some(24));
        assert_eq!(frame_end(Proto::Umpk, false, b"?03FD#0610"), None, "wait for the rest");
        let mut monitor = vec![0xAA; 31];
        monitor[5] = b'\r';
        monitor[6] = b'\n';
        assert_eq!(frame_end(Proto::Umpk, false, &monitor), Some(30));
        assert_eq!(frame_end(Proto::Umpk, false, &monitor[..29]), None);
        assert_eq!(frame_end(Proto::Umpk, false, &[b'R'; 1024]), Some(1024));
        assert_eq!(frame_end(Proto::Umpk, true, b"?05FB"), Some(5));
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
