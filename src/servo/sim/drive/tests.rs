//! State-machine tests of the simulated drive: frames in, statusword and position out, on a
//! stepped virtual clock (CiA 402 behaviour as cited in the drive's module doc).

use super::*;
use crate::servo::frame::{abort, func, Frame, Size};

struct T {
    d: Drive,
    t: f64,
}

impl T {
    fn new() -> T {
        T { d: Drive::new(1, 0.0), t: 0.0 }
    }
    fn step(&mut self, s: f64) {
        self.t += s;
    }
    fn w(&mut self, index: u16, sub: u8, size: Size, v: i64) -> Frame {
        self.d.request(&Frame::write(1, index, sub, size, v as u32), self.t).expect("an answer")
    }
    fn ok(&mut self, index: u16, sub: u8, size: Size, v: i64) {
        let r = self.w(index, sub, size, v);
        assert_eq!(r.func, func::WRITE_OK, "{index:04X}.{sub:02X} = {v}: abort {:08X}", r.data);
    }
    fn cw(&mut self, v: u16) {
        self.ok(0x6040, 0, Size::B2, v as i64);
    }
    fn r(&mut self, index: u16, sub: u8) -> i64 {
        let o = objects::lookup(index, sub).unwrap();
        let f = self.d.request(&Frame::read(1, index, sub), self.t).unwrap();
        o.dtype.decode(f.data & o.size().mask()).as_i64()
    }
    fn pos(&mut self) -> i64 {
        self.r(0x6063, 0)
    }
    fn sw(&mut self) -> i64 {
        self.r(0x6041, 0)
    }
    fn enable(&mut self) {
        for c in [0x06, 0x07, 0x0F] {
            self.cw(c);
        }
    }
}

const TARGET_REACHED: i64 = 1 << 10;
const LIMIT: i64 = 1 << 11;
const ACK: i64 = 1 << 12;
const ERR13: i64 = 1 << 13;

#[test]
fn lenient_sizes_widen_by_the_object_and_strict_refuses() {
    let mut t = T::new();
    // Python-client style: 200 as one byte into the 32-bit target position.
    t.ok(0x607A, 0, Size::B1, 200);
    assert_eq!(t.r(0x607A, 0), 200);
    // -100 as two bytes (signed short) into the signed 32-bit target velocity.
    t.ok(0x60FF, 0, Size::B2, -100);
    assert_eq!(t.r(0x60FF, 0), -100);
    // Mode -3 as two bytes into the signed 8-bit mode object.
    t.ok(0x6060, 0, Size::B2, -3);
    assert_eq!(t.r(0x6060, 0), -3);
    // Too large for the object: length too high.
    let r = t.w(0x6060, 0, Size::B2, 300);
    assert_eq!((r.func, r.data), (func::ERROR, 0x0607_0012));
    // Strict: any size other than the object's is refused with 0x06070010.
    t.d.strict = true;
    let r = t.w(0x607A, 0, Size::B1, 5);
    assert_eq!((r.func, r.data), (func::ERROR, abort::LENGTH_MISMATCH));
    assert_eq!(t.r(0x607A, 0), 200, "not applied");
}

#[test]
fn halt_brakes_holds_and_resumes_in_position_velocity_and_homing_modes() {
    let mut t = T::new();
    t.enable();
    t.ok(0x607A, 0, Size::B4, 100_000);
    t.cw(0x2F);
    t.cw(0x3F);
    t.step(0.5);
    let p = t.pos();
    t.cw(0x13F); // halt
    t.step(0.5);
    let held = t.pos();
    assert!(held > p && held < 100_000, "braked short of the target: {p} → {held}");
    assert_ne!(t.sw() & TARGET_REACHED, 0, "halted at rest: bit 10");
    t.step(1.0);
    assert_eq!(t.pos(), held, "holds while halted");
    t.cw(0x3F); // release
    assert_eq!(t.sw() & TARGET_REACHED, 0, "moving again");
    t.step(10.0);
    assert_eq!(t.pos(), 100_000, "resumed to the same target");

    // Velocity mode.
    t.ok(0x6060, 0, Size::B1, 3);
    t.ok(0x60FF, 0, Size::B4, 819_200);
    t.cw(0x0F);
    t.step(1.0);
    assert_eq!(t.r(0x606C, 0), 819_200);
    t.cw(0x10F);
    t.step(1.0);
    assert_eq!(t.r(0x606C, 0), 0, "halted");
    t.cw(0x0F);
    t.step(1.0);
    assert_eq!(t.r(0x606C, 0), 819_200, "resumed");

    // Homing: halt midway, resume, still homes.
    t.ok(0x6060, 0, Size::B1, 6);
    t.step(1.0);
    t.cw(0x0F);
    t.cw(0x1F);
    t.step(0.2);
    t.cw(0x11F);
    t.step(5.0);
    assert_eq!(t.sw() & ACK, 0, "not homed while halted");
    t.cw(0x1F);
    t.step(60.0);
    assert_ne!(t.sw() & ACK, 0, "homing attained after the release");
}

#[test]
fn bit_5_low_buffers_the_set_point_and_the_acknowledge_handshake_holds_it() {
    let mut t = T::new();
    t.enable();
    t.ok(0x607A, 0, Size::B4, 10_000);
    t.cw(0x0F);
    t.cw(0x1F); // bit 5 low
    assert_ne!(t.sw() & ACK, 0);
    t.cw(0x0F);
    assert_eq!(t.sw() & ACK, 0, "acknowledge follows bit 4 down: the buffer is free");
    t.step(0.1);
    // A second set-point during the move, bit 5 low: buffered.
    t.ok(0x607A, 0, Size::B4, -5_000);
    t.cw(0x1F);
    assert_ne!(t.sw() & ACK, 0, "accepted into the buffer");
    t.cw(0x0F);
    assert_ne!(t.sw() & ACK, 0, "buffer full: acknowledge stays high");
    // A third one is not taken while the buffer is full.
    t.ok(0x607A, 0, Size::B4, 99_999);
    t.cw(0x1F);
    t.cw(0x0F);
    t.step(0.4);
    let p = t.pos();
    assert!(p > 0 && p <= 10_000, "still on the first move or just past it: {p}");
    t.step(5.0);
    assert_eq!(t.pos(), -5_000, "the buffered set-point ran after the first");
    assert_eq!(t.sw() & ACK, 0, "buffer drained");
    assert_ne!(t.sw() & TARGET_REACHED, 0);
    // Bit 5 high: the new set-point replaces the running move at once.
    t.ok(0x607A, 0, Size::B4, 20_000);
    t.cw(0x2F);
    t.cw(0x3F);
    t.step(0.05);
    t.ok(0x607A, 0, Size::B4, 0);
    t.cw(0x2F);
    t.cw(0x3F);
    t.step(5.0);
    assert_eq!(t.pos(), 0, "single set-point: the second target replaced the first");
    // Kinco relative pattern 0x4F → 0x5F during a move queues relative to the first goal.
    t.ok(0x607A, 0, Size::B4, 1_000);
    t.cw(0x4F);
    t.cw(0x5F);
    t.cw(0x4F);
    t.step(0.01);
    t.cw(0x5F);
    t.step(5.0);
    assert_eq!(t.pos(), 2_000, "two relative moves of 1000");
}

#[test]
fn controlword_103f_starts_a_move_on_a_target_write_alone() {
    let mut t = T::new();
    t.enable();
    t.cw(0x2F);
    t.cw(0x103F);
    t.step(5.0);
    t.ok(0x607A, 0, Size::B4, 4_000);
    assert_eq!(t.sw() & TARGET_REACHED, 0, "moving on the target write alone");
    t.step(5.0);
    assert_eq!(t.pos(), 4_000);
    t.ok(0x607A, 0, Size::B4, -1_000);
    t.step(5.0);
    assert_eq!(t.pos(), -1_000, "and again, without touching the controlword");
    t.cw(0x105F); // relative variant; bit 4 was already high, so no edge of its own
    t.step(5.0);
    assert_eq!(t.pos(), -1_000);
    t.ok(0x607A, 0, Size::B4, 500);
    t.step(5.0);
    assert_eq!(t.pos(), -500, "0x105F: the target write moved relatively");
    t.cw(0x2F);
    t.ok(0x607A, 0, Size::B4, 9_999);
    t.step(5.0);
    assert_eq!(t.pos(), -500, "without bit 12 a target write waits for the edge");
}

#[test]
fn quick_stop_option_codes_decide_where_quick_stop_ends() {
    for (option, ends) in [(0, 0x40), (1, 0x40), (2, 0x40), (5, 0x07), (6, 0x07)] {
        let mut t = T::new();
        t.ok(0x605A, 0, Size::B2, option);
        t.ok(0x6060, 0, Size::B1, 3);
        t.ok(0x60FF, 0, Size::B4, 819_200);
        t.enable();
        t.step(1.0);
        t.cw(0x0B);
        let braking = t.r(0x606C, 0);
        t.step(2.0);
        assert_eq!(t.r(0x606C, 0), 0, "option {option}: stopped");
        assert_eq!(t.sw() & 0x6F, ends, "option {option}");
        if option == 0 {
            assert_eq!(braking, 0, "option 0: power off at once");
        } else {
            assert_ne!(braking, 0, "option {option}: still braking right after the command");
        }
    }
    // Profile deceleration (option 1, 100 rps/s) takes longer than the quick-stop ramp (2).
    let stop_time = |option: i64| {
        let mut t = T::new();
        t.ok(0x605A, 0, Size::B2, option);
        t.ok(0x6060, 0, Size::B1, 3);
        t.ok(0x60FF, 0, Size::B4, 819_200);
        t.enable();
        t.step(1.0);
        t.cw(0x0B);
        t.step(0.02);
        t.r(0x606C, 0)
    };
    assert_ne!(stop_time(1), 0);
    assert_eq!(stop_time(2), 0);
    let mut t = T::new();
    let r = t.w(0x605A, 0, Size::B2, 9);
    assert_eq!((r.func, r.data), (func::ERROR, abort::VALUE_RANGE));
}

fn home(method: i64, setup: impl Fn(&mut T)) -> T {
    let mut t = T::new();
    setup(&mut t);
    t.enable();
    t.ok(0x6060, 0, Size::B1, 6);
    t.ok(0x6098, 0, Size::B1, method);
    t.ok(0x607C, 0, Size::B4, 7);
    t.cw(0x1F);
    t.step(60.0);
    t
}

#[test]
fn each_homing_method_homes_where_its_number_says() {
    let switches = |t: &mut T| {
        t.d.switches = Switches { home: 2_000.0, neg_limit: Some(-3_000.0), pos_limit: Some(4_000.0) };
        t.ok(0x6099, 1, Size::B4, 1_365_333); // 500 rpm: faster searches
    };
    for (method, home_at) in [(17, -3_000.0), (18, 4_000.0), (19, 2_000.0), (20, 2_000.0), (21, 2_000.0), (22, 2_000.0)]
    {
        let mut t = home(method, switches);
        let sw = t.sw();
        assert_ne!(sw & ACK, 0, "method {method}: homing attained");
        assert_eq!(sw & ERR13, 0, "method {method}: no homing error");
        assert_eq!(t.pos(), 7, "method {method}: the home offset at the home point");
        assert_eq!(
            t.d.switches.home - 2_000.0,
            7.0 - home_at,
            "method {method}: the switches moved with the coordinates"
        );
    }
    // Index pulses every 10000 inc: from 2500, 33 homes at 0 and 34 at 10000.
    for (method, travelled) in [(33, -2_500), (34, 7_500)] {
        let mut t = home(method, |t| t.d.motion = Motion::still(0.0, 2_500.0));
        assert_ne!(t.sw() & ACK, 0, "method {method}");
        assert_eq!(t.pos(), 7, "method {method} (travelled {travelled})");
    }
    // 35 / 37: here is home, no motion.
    for method in [35, 37] {
        let mut t = home(method, |t| t.d.motion = Motion::still(0.0, 1_234.0));
        assert_eq!((t.sw() & ACK != 0, t.pos()), (true, 7), "method {method}");
    }
    // A limit in the way is a homing error; an unsimulated method too.
    let mut t = home(19, |t| t.d.switches = Switches { home: 9_000.0, neg_limit: None, pos_limit: Some(4_000.0) });
    assert_ne!(t.sw() & ERR13, 0, "the positive limit stopped the search");
    assert_ne!(t.sw() & LIMIT, 0);
    let mut t = home(1, |_| {});
    assert_ne!(t.sw() & ERR13, 0, "method 1 is not simulated: homing error");
    let mut t = home(17, |_| {});
    assert_ne!(t.sw() & ERR13, 0, "no negative limit switch wired");
}

#[test]
fn limits_stop_the_drive_and_inputs_show_the_switches() {
    let mut t = T::new();
    t.d.switches.pos_limit = Some(3_000.0);
    t.d.switches.neg_limit = Some(-3_000.0);
    assert_eq!(t.r(0x60FD, 0), 0);
    t.enable();
    t.ok(0x6060, 0, Size::B1, 3);
    t.ok(0x60FF, 0, Size::B4, 81_920); // 5000 inc/s
    t.cw(0x0F);
    t.step(5.0);
    let p = t.pos();
    assert!((3_000..3_100).contains(&p), "stopped just past the positive limit: {p}");
    assert_eq!(t.r(0x606C, 0), 0);
    assert_ne!(t.sw() & LIMIT, 0, "bit 11 internal limit active");
    assert_eq!(t.r(0x60FD, 0) & 0b11, 0b10, "60FD bit 1: positive limit");
    assert_eq!(t.r(0x2010, 0x0A) & 0b11, 0b10, "din_real mirrors it");
    // Moving out of the limit is allowed.
    t.ok(0x60FF, 0, Size::B4, -81_920);
    t.step(1.0);
    assert!(t.pos() < 3_000);
    assert_eq!(t.sw() & LIMIT, 0);
    // Software limits clamp position targets.
    t.ok(0x607D, 1, Size::B4, 1_000);
    t.ok(0x607D, 2, Size::B4, -1_000);
    t.ok(0x6060, 0, Size::B1, 1);
    t.step(1.0);
    t.ok(0x607A, 0, Size::B4, 50_000);
    t.cw(0x2F);
    t.cw(0x3F);
    assert_ne!(t.sw() & LIMIT, 0, "clamped target: bit 11");
    t.step(5.0);
    assert_eq!(t.pos(), 1_000);
}

#[test]
fn following_error_outside_its_window_faults_the_drive() {
    let mut t = T::new();
    t.ok(0x6065, 0, Size::B4, 50); // 50 inc: faster than 25000 inc/s breaks the window
    t.enable();
    t.ok(0x607A, 0, Size::B4, 100_000);
    t.ok(0x6081, 0, Size::B4, 819_200); // 50000 inc/s
    t.cw(0x2F);
    t.cw(0x3F);
    t.step(0.01);
    assert_eq!(t.sw() & 0x08, 0, "not yet");
    t.step(1.0);
    let sw = t.sw();
    assert_ne!(sw & 0x08, 0, "fault");
    assert_ne!(sw & ERR13, 0, "bit 13 following error");
    assert_eq!(t.r(0x603F, 0), FOLLOWING_ERROR_FAULT as i64);
    // The time-out (10 ms) runs from when the error passed 50 inc (25000 inc/s at 1e6 inc/s²: 25 ms).
    let p = t.pos();
    assert!((300..1_000).contains(&p), "stopped early in the ramp: {p}");
    t.cw(0x06);
    t.cw(0x86);
    assert_eq!(t.sw() & (0x08 | ERR13), 0, "reset clears it");
    assert_eq!(t.r(0x60F4, 0), 0);
}

#[test]
fn pulse_train_mode_follows_the_input_through_the_gear() {
    let mut t = T::new();
    t.ok(0x6060, 0, Size::B1, -4);
    t.ok(0x2508, 1, Size::B2, 2);
    t.ok(0x2508, 2, Size::B2, 1);
    t.enable();
    t.d.add_pulses(t.t, 1_000.0, 500, 1).unwrap();
    t.step(0.25);
    assert_eq!(t.pos(), 500, "250 pulses so far × 2");
    assert_eq!(t.r(0x606C, 0), speed_to_dec(2_000.0), "1000 Hz × 2 = 2000 inc/s");
    t.step(1.0);
    assert_eq!(t.pos(), 1_000, "N pulses at gear 2/1: 2N increments");
    // Reverse pulses, gear 1/4, A/B mode (×4): 400 pulses → -400 inc.
    t.ok(0x2508, 1, Size::B2, 1);
    t.ok(0x2508, 2, Size::B2, 4);
    t.ok(0x2508, 3, Size::B2, 2);
    t.d.add_pulses(t.t, 400.0, 400, -1).unwrap();
    t.step(2.0);
    assert_eq!(t.pos(), 600);
    // Disabled, the input is ignored.
    t.cw(0x06);
    t.d.add_pulses(t.t, 1_000.0, 100, 1).unwrap();
    t.step(1.0);
    assert_eq!(t.pos(), 600);
    let r = t.w(0x2508, 2, Size::B2, 0);
    assert_eq!((r.func, r.data), (func::ERROR, abort::VALUE_RANGE));
}

#[test]
fn a_connected_pulse_train_is_followed_like_a_wired_output() {
    let mut t = T::new();
    t.ok(0x6060, 0, Size::B1, -4);
    t.enable();
    let mut train = PulseTrain::new();
    train.push(0.5, 2_000.0, 1_000, 1).unwrap(); // 0.5 s … 1.0 s
    train.push(0.0, 500.0, 100, -1).unwrap(); // then 0.2 s back
    t.d.connect_pulses(train, t.t);
    t.step(0.75);
    assert_eq!(t.pos(), 500);
    t.step(1.0);
    assert_eq!(t.pos(), 900);
}

/// A fault armed at a position acts where the motion crosses it (either way), at that
/// moment, and not merely for standing on it when armed.
#[test]
fn a_fault_armed_at_a_position_acts_where_the_motion_crosses_it() {
    let mut t = T::new();
    t.enable();
    t.cw(0x2F);
    t.cw(0x103F);
    t.d.faults_at.push((2_000.0, 0x7500));
    t.ok(0x607A, 0, Size::B4, 4_000);
    t.step(5.0);
    assert_ne!(t.sw() & 0x08, 0, "in Fault");
    assert_eq!(t.pos(), 2_000, "stopped dead where it crossed");
    assert_eq!(t.r(0x603F, 0), 0x7500);
    let (te, x, code) = t.d.fault_events[0];
    assert!(te > 0.0 && te < 5.0 && x == 2_000.0 && code == 0x7500, "{:?}", t.d.fault_events);
    assert!(t.d.faults_at.is_empty(), "an armed fault acts once");
    // Reset, arm at the position it stands on: moving away does not trip it, coming back does.
    t.cw(0x80);
    t.enable();
    t.cw(0x2F);
    t.cw(0x103F);
    t.d.faults_at.push((2_000.0, 0x7501));
    t.ok(0x607A, 0, Size::B4, 3_000);
    t.step(5.0);
    assert_eq!((t.pos(), t.sw() & 0x08), (3_000, 0), "moved away from it without a fault");
    t.ok(0x607A, 0, Size::B4, 0);
    t.step(5.0);
    assert_eq!((t.pos(), t.r(0x603F, 0)), (2_000, 0x7501), "crossing it backwards");
    assert_eq!(t.d.fault_events.len(), 2);
}
