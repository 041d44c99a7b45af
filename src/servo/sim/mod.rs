//! The drive simulator: one or more simulated drives on one RS232 line, answering the same
//! 10-byte frames the driver sends (`../shared/spec/kinco-servo.md` §2), through the same
//! codec ([`crate::servo::frame`]) and object table ([`crate::servo::objects`]).
//!
//! A [`SimLine`] receives whole request frames and answers as the drives on the line
//! would: a frame with a bad checksum, or for an id no drive has, gets NO reply, and so
//! does an object the drive does not have (§2: "it does not answer at all"). In loop mode
//! (public notes, "RS232 loop") every request is echoed before the reply. Armed faults
//! ([`faults`]) and line timing ([`Pace`]) belong to the line too, so both ways of using it
//! show them alike; [`control`] is the one language that arms them.
//!
//! It is used two ways: in-process, where [`SimLink`] is a transport that hands frames to
//! the line synchronously (so `sim-servo:?id=1` runs the real driver code), and served on a
//! pseudo-terminal by [`serve`] (`plcsh sim serve --servo-pty`). Time is the virtual clock's.

pub mod control;
pub mod drive;
pub mod faults;
pub mod homing;
pub mod motion;
pub mod serve;
pub mod wired;

use super::frame::{func, Frame, FrameBuffer, FRAME_LEN};
use crate::core::link::line::Transport;
use crate::core::Clock;
use crate::msg;
use drive::Drive;
use faults::LineFaults;
use std::collections::VecDeque;
use std::io;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Line timing: a real RS232 line carries each 10-byte frame at `baud` (10 bits a byte:
/// start, 8 data, stop; seed §1's 8N1), and the drive thinks `latency` before answering.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pace {
    pub baud: u32,
    pub latency: Duration,
}

impl Pace {
    /// The served simulator's default: the factory 38400 baud and 1 ms think-time (a
    /// drive's real think-time is not documented; 1 ms is a guess, configurable).
    pub const REALISTIC: Pace = Pace { baud: 38_400, latency: Duration::from_millis(1) };

    /// One frame's time on the wire.
    pub fn frame_time(&self) -> Duration {
        Duration::from_secs_f64(FRAME_LEN as f64 * 10.0 / self.baud.max(1) as f64)
    }
}

/// What the line sends back for one request, and when (relative to the request's end as
/// the line sees it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Answer {
    pub echo: Option<[u8; FRAME_LEN]>,
    pub reply: Option<[u8; FRAME_LEN]>,
    /// When the echo is complete (its frame time, if paced).
    pub echo_after: Duration,
    /// When the reply is complete.
    pub reply_after: Duration,
}

/// Drives sharing one simulated line.
#[derive(Debug)]
pub struct SimLine {
    drives: Vec<Drive>,
    pub clock: Clock,
    /// Loop mode: echo every request before answering.
    pub echo: bool,
    /// Requests received (including ones nobody answered).
    pub received: u64,
    /// Line timing; `None` answers at once.
    pub pace: Option<Pace>,
    /// Armed faults.
    pub faults: LineFaults,
}

impl SimLine {
    pub fn new(ids: &[u8], clock: Clock) -> SimLine {
        let t = clock.now().as_secs_f64();
        SimLine {
            drives: ids.iter().map(|&id| Drive::new(id, t)).collect(),
            clock,
            echo: false,
            received: 0,
            pace: None,
            faults: LineFaults::default(),
        }
    }

    /// The line's virtual time, seconds.
    pub fn now(&self) -> f64 {
        self.clock.now().as_secs_f64()
    }

    pub fn ids(&self) -> Vec<u8> {
        self.drives.iter().map(|d| d.id).collect()
    }

    /// Adds a drive with `id` if the line has none.
    pub fn add_drive(&mut self, id: u8) {
        if self.drive(id).is_none() {
            let t = self.now();
            let strict = self.drives.first().is_some_and(|d| d.strict);
            let mut d = Drive::new(id, t);
            d.strict = strict;
            self.drives.push(d);
        }
    }

    pub fn drive(&mut self, id: u8) -> Option<&mut Drive> {
        self.drives.iter_mut().find(|d| d.id == id)
    }

    /// Every drive on the line refuses (or accepts) writes of the wrong size.
    pub fn set_strict(&mut self, on: bool) {
        for d in &mut self.drives {
            d.strict = on;
        }
    }

    /// Answers one request frame as the drives would, with the armed faults and timing.
    pub fn exchange(&mut self, bytes: &[u8; FRAME_LEN]) -> Answer {
        self.received += 1;
        let frame = self.pace.map(|p| p.frame_time()).unwrap_or_default();
        let latency = self.pace.map(|p| p.latency).unwrap_or_default();
        let mut a = Answer { echo: self.echo.then_some(*bytes), reply: None, echo_after: frame, reply_after: frame };
        let Ok(f) = Frame::from_bytes(bytes) else { return a };
        let fx = self.faults.take(f.id, f.index, f.sub);
        if fx.drop_echo {
            a.echo = None;
        }
        let t = self.now();
        let Some(d) = self.drives.iter_mut().find(|d| d.id == f.id) else { return a };
        if fx.no_reply {
            return a;
        }
        let reply = match fx.abort {
            Some(code) => Some(Frame { func: func::ERROR, data: code, ..f }),
            None => d.request(&f, t),
        };
        a.reply = reply.map(|r| {
            let mut b = r.to_bytes();
            if fx.bad_checksum {
                b[9] ^= 0x5A;
            }
            b
        });
        a.reply_after = frame + latency + frame + fx.delay;
        a
    }

    /// Answers one request frame; `None` is silence (no timing, no echo).
    pub fn answer(&mut self, bytes: &[u8; FRAME_LEN]) -> Option<[u8; FRAME_LEN]> {
        self.exchange(bytes).reply
    }

    /// Puts drive `id` into Fault with `code` (603F.00). False if no such drive.
    pub fn inject_fault(&mut self, id: u8, code: u16) -> bool {
        let t = self.now();
        match self.drive(id) {
            Some(d) => {
                d.inject_fault(code, t);
                true
            }
            None => false,
        }
    }

    /// Moves drive `id`'s simulated home switch to `pos` (increments).
    pub fn set_home_switch(&mut self, id: u8, pos: f64) -> bool {
        match self.drive(id) {
            Some(d) => {
                d.switches.home = pos;
                true
            }
            None => false,
        }
    }

    /// Feeds `count` pulses at `freq` Hz to drive `id`'s pulse input from now on (queued
    /// after pulses still arriving); returns when they start and end (virtual seconds).
    pub fn add_pulses(&mut self, id: u8, freq: f64, count: u64, dir: i8) -> Result<(f64, f64), String> {
        let t = self.now();
        self.drive(id).ok_or_else(|| msg!("servo-sim-no-drive-short", id = id).text)?.add_pulses(t, freq, count, dir)
    }
}

impl SimLine {
    /// Every drive's state, for snapshots (`crate::snapshot`). A [`Drive`] is saved whole
    /// (serde names each of its fields); every field of the line is named below (no `..`), so
    /// a field added to it does not compile until it is saved or named as not the machine's.
    pub fn save_drives(&self) -> Vec<Drive> {
        let SimLine {
            drives,
            // The session's clock: the snapshot's `clock_us`.
            clock: _,
            // The line's echo mode, timing and transport faults come from the device URL and
            // the link (docs/snapshots.md: what belongs to the link is not kept).
            echo: _,
            pace: _,
            faults: _,
            // Requests the line carried: the link's traffic, not a drive's state.
            received: _,
        } = self;
        drives.clone()
    }

    /// Replaces the drives with saved ones.
    pub fn restore_drives(&mut self, drives: Vec<Drive>) {
        self.drives = drives;
    }
}

/// The in-process transport: frames go straight to a [`SimLine`]. With line timing the
/// bytes become readable only when a real line would have delivered them (wall clock).
pub struct SimLink {
    line: Arc<Mutex<SimLine>>,
    buf: FrameBuffer,
    rx: VecDeque<u8>,
    /// When what is in `rx` has arrived.
    ready_at: Option<Instant>,
}

impl SimLink {
    pub fn new(line: Arc<Mutex<SimLine>>) -> SimLink {
        SimLink { line, buf: FrameBuffer::new(), rx: VecDeque::new(), ready_at: None }
    }
}

impl Transport for SimLink {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.buf.push(bytes);
        let mut line = self.line.lock().unwrap_or_else(|p| p.into_inner());
        let now = Instant::now();
        while let Some(req) = self.buf.next_raw() {
            let a = line.exchange(&req);
            if let Some(e) = a.echo {
                self.rx.extend(e);
            }
            if let Some(r) = a.reply {
                self.rx.extend(r);
            }
            let paced = line.pace.is_some() || a.reply_after > a.echo_after;
            self.ready_at = paced.then(|| now + a.reply_after.max(a.echo_after));
        }
        Ok(())
    }

    /// Without timing the simulator answers synchronously: what is not here now will never
    /// come, so an empty queue returns at once (no waiting out the timeout in-process).
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        if let Some(at) = self.ready_at {
            let now = Instant::now();
            if at > now {
                if at - now > timeout {
                    return Ok(0);
                }
                std::thread::sleep(at - now);
            }
            self.ready_at = None;
        }
        let n = buf.len().min(self.rx.len());
        for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }

    fn discard_input(&mut self) -> io::Result<()> {
        self.rx.clear();
        self.buf.clear();
        self.ready_at = None;
        Ok(())
    }

    fn sim_line(&self) -> Option<Arc<dyn std::any::Any + Send + Sync>> {
        Some(self.line.clone())
    }
}

/// The simulated line behind a transport, when it is one ([`Transport::sim_line`]).
pub fn sim_line_of(t: &dyn Transport) -> Option<Arc<Mutex<SimLine>>> {
    t.sim_line()?.downcast::<Mutex<SimLine>>().ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::servo::frame::{abort, func, Size};

    fn hex(s: &str) -> [u8; 10] {
        let v: Vec<u8> = s.split_whitespace().map(|b| u8::from_str_radix(b, 16).unwrap()).collect();
        v.try_into().unwrap()
    }

    fn line() -> (SimLine, Clock) {
        let clock = Clock::stepped();
        (SimLine::new(&[1], clock.clone()), clock)
    }

    #[test]
    fn answers_the_manuals_frames_byte_for_byte() {
        let (mut l, _) = line();
        // A freshly powered drive is "ready to switch on": statusword 0x4231, as in §2.
        assert_eq!(l.answer(&hex("01 40 41 60 00 00 00 00 00 1E")), Some(hex("01 4B 41 60 00 31 42 00 00 A0")));
        assert_eq!(l.answer(&hex("01 2B 40 60 00 0F 00 00 00 25")), Some(hex("01 60 40 60 00 0F 00 00 00 F0")));
        // 0x0F from "ready to switch on" enables (the manual's one-frame enable).
        let r = Frame::from_bytes(&l.answer(&hex("01 40 41 60 00 00 00 00 00 1E")).unwrap()).unwrap();
        assert_eq!(r.data & 0x6F, 0x27, "operation enabled");
    }

    #[test]
    fn silence_for_wrong_id_unknown_object_and_bad_checksum() {
        let (mut l, _) = line();
        assert_eq!(l.answer(&Frame::read(2, 0x6041, 0).to_bytes()), None, "wrong id");
        assert_eq!(l.answer(&Frame::read(1, 0x3FFF, 1).to_bytes()), None, "unknown object");
        let mut bad = Frame::read(1, 0x6041, 0).to_bytes();
        bad[9] ^= 1;
        assert_eq!(l.answer(&bad), None, "bad checksum");
        let odd = Frame { func: 0x99, ..Frame::read(1, 0x6041, 0) }.to_bytes();
        assert_eq!(l.answer(&odd), None, "unknown function code");
        assert_eq!(l.received, 4);
    }

    #[test]
    fn read_only_and_length_errors_are_aborts() {
        let (mut l, _) = line();
        let r = l.answer(&Frame::write(1, 0x6041, 0, Size::B2, 1).to_bytes()).unwrap();
        let f = Frame::from_bytes(&r).unwrap();
        assert_eq!((f.func, f.data), (func::ERROR, abort::READ_ONLY));
        // A 4-byte write to the 16-bit controlword: lenient by default, refused when strict.
        let r = l.answer(&Frame::write(1, 0x6040, 0, Size::B4, 6).to_bytes()).unwrap();
        assert_eq!(Frame::from_bytes(&r).unwrap().func, func::WRITE_OK);
        l.set_strict(true);
        let r = l.answer(&Frame::write(1, 0x6040, 0, Size::B4, 6).to_bytes()).unwrap();
        assert_eq!(Frame::from_bytes(&r).unwrap().data, abort::LENGTH_MISMATCH);
        l.set_strict(false);
        let r = l.answer(&Frame::write(1, 0x6060, 0, Size::B1, 2).to_bytes()).unwrap();
        assert_eq!(Frame::from_bytes(&r).unwrap().data, abort::VALUE_RANGE, "mode 2 is not a Kinco mode");
    }

    fn read(l: &mut SimLine, index: u16, sub: u8) -> u32 {
        Frame::from_bytes(&l.answer(&Frame::read(1, index, sub).to_bytes()).unwrap()).unwrap().data
    }

    fn write(l: &mut SimLine, index: u16, sub: u8, size: Size, v: i64) {
        let r = l.answer(&Frame::write(1, index, sub, size, v as u32).to_bytes()).unwrap();
        assert_eq!(r[1], func::WRITE_OK, "{index:04X}.{sub:02X} = {v}");
    }

    #[test]
    fn profile_move_in_virtual_time() {
        let (mut l, clock) = line();
        for cw in [0x06, 0x07, 0x0F] {
            write(&mut l, 0x6040, 0, Size::B2, cw);
        }
        write(&mut l, 0x607A, 0, Size::B4, 10_000);
        write(&mut l, 0x6081, 0, Size::B4, 819_200); // 300 rpm
        write(&mut l, 0x6040, 0, Size::B2, 0x2F);
        write(&mut l, 0x6040, 0, Size::B2, 0x3F);
        let sw = read(&mut l, 0x6041, 0);
        assert_eq!(sw & (1 << 10), 0, "moving: target not reached");
        assert_ne!(sw & (1 << 12), 0, "set-point acknowledged");
        // 100 rps/s default acceleration: 0.05 s ramps, 0.25 s in total.
        clock.step(Duration::from_millis(125));
        assert_eq!(read(&mut l, 0x6063, 0) as i32, 5000);
        assert_eq!(read(&mut l, 0x606C, 0) as i32, 819_200, "cruising at 300 rpm");
        clock.step(Duration::from_millis(125));
        assert_eq!(read(&mut l, 0x6063, 0) as i32, 10_000);
        assert_ne!(read(&mut l, 0x6041, 0) & (1 << 10), 0, "target reached");
        // Relative move of -2500 from there.
        write(&mut l, 0x607A, 0, Size::B4, -2500);
        write(&mut l, 0x6040, 0, Size::B2, 0x4F);
        write(&mut l, 0x6040, 0, Size::B2, 0x5F);
        clock.step(Duration::from_secs(1));
        assert_eq!(read(&mut l, 0x6063, 0) as i32, 7500);
    }

    #[test]
    fn velocity_modes_quick_stop_fault_and_homing() {
        let (mut l, clock) = line();
        write(&mut l, 0x6060, 0, Size::B1, 3);
        write(&mut l, 0x60FF, 0, Size::B4, 819_200);
        write(&mut l, 0x6040, 0, Size::B2, 0x0F);
        clock.step(Duration::from_secs(1));
        assert_eq!(read(&mut l, 0x606C, 0) as i32, 819_200);
        assert_ne!(read(&mut l, 0x6041, 0) & (1 << 10), 0, "at speed");
        // Quick stop: 1000 rps/s from 5 rps takes 5 ms; the drive stays in quick stop active.
        write(&mut l, 0x6040, 0, Size::B2, 0x0B);
        clock.step(Duration::from_millis(10));
        assert_eq!(read(&mut l, 0x606C, 0), 0);
        assert_eq!(read(&mut l, 0x6041, 0) & 0x6F, 0x07);
        // Immediate velocity has no ramp.
        write(&mut l, 0x6040, 0, Size::B2, 0x0F);
        write(&mut l, 0x6060, 0, Size::B1, -3i64);
        write(&mut l, 0x60FF, 0, Size::B4, -16_384);
        assert_eq!(read(&mut l, 0x606C, 0) as i32, -16_384);
        // Fault: stops, statusword fault, error code; reset on bit 7's rising edge.
        assert!(l.inject_fault(1, 0x2310));
        assert_eq!(read(&mut l, 0x6041, 0) & 0x4F, 0x08);
        assert_eq!(read(&mut l, 0x603F, 0), 0x2310);
        write(&mut l, 0x6040, 0, Size::B2, 0x0F);
        assert_eq!(read(&mut l, 0x6041, 0) & 0x4F, 0x08, "enable is ignored in fault");
        write(&mut l, 0x6040, 0, Size::B2, 0x86);
        assert_eq!(read(&mut l, 0x6041, 0) & 0x4F, 0x40, "switch on disabled after reset");
        assert_eq!(read(&mut l, 0x603F, 0), 0);
        // Homing to the switch at 2000 with home offset 100.
        let p = read(&mut l, 0x6063, 0) as i32;
        l.set_home_switch(1, p as f64 + 2000.0);
        for cw in [0x06, 0x07, 0x0F] {
            write(&mut l, 0x6040, 0, Size::B2, cw);
        }
        write(&mut l, 0x6060, 0, Size::B1, 6);
        write(&mut l, 0x607C, 0, Size::B4, 100);
        write(&mut l, 0x6040, 0, Size::B2, 0x1F);
        assert_eq!(read(&mut l, 0x6041, 0) & (1 << 12), 0, "homing not attained yet");
        clock.step(Duration::from_secs(5));
        let sw = read(&mut l, 0x6041, 0);
        assert_ne!(sw & (1 << 12), 0, "homing attained");
        assert_ne!(sw & (1 << 15), 0, "Kinco home found");
        assert_eq!(sw >> 16, 0xFFFF, "16-bit replies are sign-extended like the FD5P's");
        assert_eq!(read(&mut l, 0x6063, 0), 100, "position is the home offset at the switch");
    }

    #[test]
    fn link_echoes_in_loop_mode() {
        let clock = Clock::stepped();
        let line = Arc::new(Mutex::new(SimLine::new(&[1, 2], clock)));
        line.lock().unwrap().echo = true;
        let mut link = SimLink::new(line);
        let req = Frame::read(2, 0x6041, 0).to_bytes();
        link.send(&req).unwrap();
        let mut got = [0u8; 20];
        assert_eq!(link.recv(&mut got, Duration::ZERO).unwrap(), 20);
        assert_eq!(got[..10], req);
        assert_eq!(got[10], 2);
        link.send(&Frame::read(3, 0x6041, 0).to_bytes()).unwrap();
        assert_eq!(link.recv(&mut got, Duration::ZERO).unwrap(), 10, "echo only: no drive 3");
    }
}
