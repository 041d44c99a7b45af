//! TCP reassembly for captures: the bytes of one direction of one connection put back in
//! sequence order, then cut into frames by [`super::framing`]. A capture from the wire
//! holds segments as the operating system sent them — a Modbus TCP frame may be split
//! across two segments, several frames may share one — and repeats (retransmissions) and
//! segments out of order. Sequence numbers decide: bytes already taken are dropped, a
//! segment ahead of the next expected byte waits (up to [`MAX_WAITING`] segments) until the
//! gap fills; a gap that never fills is bytes the capture missed, reported, and reading
//! goes on after it. Linear in the bytes captured.

use super::framing;
use crate::core::trace::Proto;

/// Segments held back waiting for a gap to fill.
pub const MAX_WAITING: usize = 64;

/// One direction of one TCP connection.
#[derive(Debug, Default)]
pub struct Stream {
    /// The sequence number of the next byte expected.
    next: Option<u32>,
    buf: Vec<u8>,
    /// Segments ahead of `next`.
    waiting: Vec<(u32, Vec<u8>)>,
    /// Bytes the capture missed (gaps given up on).
    pub lost: u64,
}

/// `a - b` in sequence space (RFC 793 §3.3 modular comparison).
fn diff(a: u32, b: u32) -> i64 {
    i64::from(a.wrapping_sub(b) as i32)
}

impl Stream {
    /// A SYN: the data starts at `seq + 1`.
    pub fn syn(&mut self, seq: u32) {
        *self = Stream { lost: self.lost, ..Default::default() };
        self.next = Some(seq.wrapping_add(1));
    }

    /// Takes a segment in; the whole frames it completes go to `out`.
    pub fn push(&mut self, seq: u32, payload: &[u8], proto: Proto, request: bool, out: &mut Vec<Vec<u8>>) {
        if payload.is_empty() {
            return;
        }
        let next = *self.next.get_or_insert(seq);
        if diff(seq, next) > 0 {
            if self.waiting.len() >= MAX_WAITING {
                self.give_up_gap(proto, request, out);
                return self.push(seq, payload, proto, request, out);
            }
            self.waiting.push((seq, payload.to_vec()));
            return;
        }
        self.take(seq, payload);
        // Segments that waited for this one.
        while let Some(i) = self.waiting.iter().position(|(s, _)| diff(*s, self.next.unwrap_or(*s)) <= 0) {
            let (s, p) = self.waiting.swap_remove(i);
            self.take(s, &p);
        }
        self.frames(proto, request, out);
    }

    /// Appends the part of a segment at or before `next` not taken yet.
    fn take(&mut self, seq: u32, payload: &[u8]) {
        let next = self.next.unwrap_or(seq);
        let skip = (-diff(seq, next)).max(0) as usize;
        if skip < payload.len() {
            self.buf.extend_from_slice(&payload[skip..]);
            self.next = Some(next.wrapping_add((payload.len() - skip) as u32));
        }
    }

    /// The bytes before the earliest waiting segment never came: what is buffered goes out
    /// as it is and reading resumes at that segment.
    fn give_up_gap(&mut self, proto: Proto, request: bool, out: &mut Vec<Vec<u8>>) {
        let Some(next) = self.next else { return };
        let Some(&(first, _)) = self.waiting.iter().min_by_key(|(s, _)| diff(*s, next)) else { return };
        self.lost += diff(first, next).max(0) as u64;
        self.flush(out);
        self.next = Some(first);
        let waiting = std::mem::take(&mut self.waiting);
        let mut sorted = waiting;
        sorted.sort_by_key(|(s, _)| diff(*s, first));
        for (s, p) in sorted {
            if diff(s, self.next.unwrap_or(s)) > 0 {
                self.waiting.push((s, p));
            } else {
                self.take(s, &p);
            }
        }
        self.frames(proto, request, out);
    }

    fn frames(&mut self, proto: Proto, request: bool, out: &mut Vec<Vec<u8>>) {
        let mut start = 0;
        while start < self.buf.len() {
            match framing::frame_end(proto, request, &self.buf[start..]) {
                Some(end) if end > 0 => {
                    out.push(self.buf[start..start + end].to_vec());
                    start += end;
                }
                _ => break,
            }
        }
        self.buf.drain(..start);
    }

    /// Whatever is buffered, as one frame (the connection ended, or the other side spoke).
    pub fn flush(&mut self, out: &mut Vec<Vec<u8>>) {
        if !self.buf.is_empty() {
            out.push(std::mem::take(&mut self.buf));
        }
    }

    /// The end of the capture: gaps given up on, the rest flushed.
    pub fn finish(&mut self, proto: Proto, request: bool, out: &mut Vec<Vec<u8>>) {
        while !self.waiting.is_empty() {
            self.give_up_gap(proto, request, out);
        }
        self.flush(out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const A: [u8; 12] = [0, 1, 0, 0, 0, 6, 1, 3, 0, 100, 0, 2];
    const B: [u8; 12] = [0, 2, 0, 0, 0, 6, 1, 3, 0, 200, 0, 1];

    #[test]
    fn split_merged_retransmitted_and_reordered_segments_give_whole_frames() {
        let both: Vec<u8> = [A, B].concat();
        let mut s = Stream::default();
        s.syn(99);
        let mut out = Vec::new();
        // B's second half first (out of order), A in two pieces with a retransmission.
        s.push(100 + 18, &both[18..], Proto::ModbusTcp, true, &mut out);
        s.push(100, &both[..5], Proto::ModbusTcp, true, &mut out);
        s.push(100, &both[..5], Proto::ModbusTcp, true, &mut out);
        assert!(out.is_empty());
        s.push(100 + 3, &both[3..18], Proto::ModbusTcp, true, &mut out);
        assert_eq!(out, vec![A.to_vec(), B.to_vec()]);
        s.finish(Proto::ModbusTcp, true, &mut out);
        assert_eq!((out.len(), s.lost), (2, 0));
    }

    #[test]
    fn a_gap_the_capture_missed_is_counted_and_reading_goes_on() {
        let mut s = Stream::default();
        let mut out = Vec::new();
        s.push(1000, &A[..4], Proto::ModbusTcp, true, &mut out);
        s.push(1000 + 12, &B, Proto::ModbusTcp, true, &mut out);
        s.finish(Proto::ModbusTcp, true, &mut out);
        assert_eq!(out, vec![A[..4].to_vec(), B.to_vec()]);
        assert_eq!(s.lost, 8);
    }

    #[test]
    fn sequence_numbers_wrap() {
        let mut s = Stream::default();
        let mut out = Vec::new();
        s.push(u32::MAX - 2, &A[..6], Proto::ModbusTcp, true, &mut out);
        s.push(3, &A[6..], Proto::ModbusTcp, true, &mut out);
        assert_eq!(out, vec![A.to_vec()]);
    }

    #[test]
    fn many_segments_ahead_do_not_wait_forever() {
        let mut s = Stream::default();
        let mut out = Vec::new();
        s.push(0, &[0], Proto::Unknown, true, &mut out);
        for k in 0..(MAX_WAITING as u32 + 5) {
            s.push(10 + 2 * k, &[1], Proto::Unknown, true, &mut out);
        }
        s.finish(Proto::Unknown, true, &mut out);
        assert!(s.lost > 0 && out.len() > MAX_WAITING, "{}", out.len());
    }
}
