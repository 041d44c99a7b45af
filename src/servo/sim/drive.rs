//! One simulated drive: its object dictionary (the same table the driver uses), the DS402
//! state machine, the operating modes 1 (profile position), 3 (profile velocity), -3
//! (immediate velocity), 6 (homing, methods by number: [`super::homing`]), -4 (pulse train
//! through the electronic gear) and 4 (torque: accepted and stored; no load model, so the
//! motor does not move), halt, quick stop by option code, limit switches, software limits,
//! the following-error window and injectable faults.
//!
//! It answers requests as `../shared/spec/kinco-servo.md` §2 says a drive does: nothing at
//! all for an object it does not have or a function code it does not know, `0x80` with a
//! CiA-301 abort code for a write to a read-only object (public notes), `0x60` echoing the
//! data for an accepted write, `0x4F/0x4B/0x43` for reads. Like the FD5P the notes quote,
//! 16-bit values are sent sign-extended (bit 15 set → `FF FF` in D2..D3).
//!
//! **Write sizes.** Field clients choose the write code from the value's magnitude, not the
//! object (a public Python client sends `0x2F` for 0…255 and `0x2B` for -32768…32767 on any
//! object, e.g. mode -3 as `2B … FD FF`), and this works on real drives: the public FD5P
//! manual's own RS232 example (§10) writes 2FF0.09 with `0x23` and reads it back as a 2-byte
//! `4B` reply. The seed never says a drive checks the length. So by default a write whose size differs
//! from the object's is accepted: a shorter one is widened to the object (a 1-byte write
//! as 0…255, the Python client's rule; a 2-byte write sign-extended into a signed object),
//! a longer one is read at its size (signed for a signed object) and must fit the object,
//! else abort 0x06070012 "length too high". What a drive does with a short write is not
//! documented anywhere we found — uncertain. `strict` restores refusal with 0x06070010
//! (public notes' abort table) for users who want to catch masters that send loose sizes.
//!
//! State at power-up is "ready to switch on" with bits 9 (remote) and 14 set: statusword
//! 0x4231, the manual's worked read example. Time is the virtual clock's, in seconds; motion
//! is [`super::motion`]'s analytic profiles, and everything that happens *during* a motion
//! (a limit switch reached, a buffered set-point taking over, homing done, a following error
//! timing out) is found by solving the profile for the moment it happens ([`Drive::advance`]).

use super::homing::{self, Onto, Switches};
use super::motion::{accel_from_dec, speed_from_dec, speed_to_dec, Motion};
use crate::core::signal::PulseTrain;
use crate::core::{DataType, Value};
use crate::servo::ds402::{self, State};
use crate::servo::frame::{abort, func, Frame, Size};
use crate::servo::objects::{self, Access, Object};
use std::collections::HashMap;

/// What the drive is doing.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
enum Task {
    /// Holding position (nothing commanded).
    Idle,
    /// A profile position move (mode 1).
    Move,
    /// Following the target velocity (modes 3, -3).
    Velocity,
    /// Homing (mode 6).
    Homing,
    /// Following the pulse input through the gear (mode -4).
    Pulse,
    /// Quick stop deceleration; `disable` ends it in "switch on disabled" (605A 0-4).
    QuickStop { disable: bool },
    /// Braking at a limit (switch or software limit); the drive holds there.
    LimitStop,
    /// Braking for halt (bit 8) or holding halted; resumes `resume` on release.
    Halt,
}

/// Default values at power-up, by object name (everything else starts at 0).
static DEFAULTS: &[(&str, i64)] = &[
    ("operating_mode", 1),
    ("profile_velocity", 273_067),       // 100 rpm at R = 10000
    ("profile_acceleration", 16_384),    // 100 rps/s
    ("profile_deceleration", 16_384),    // 100 rps/s
    ("quickstop_deceleration", 163_840), // 1000 rps/s
    ("homing_speed_switch", 136_533),    // 50 rpm
    ("homing_speed_zero", 27_307),       // 10 rpm
    ("homing_acceleration", 16_384),     // 100 rps/s
    ("homing_method", 19),
    ("position_window", 10),
    ("max_following_error", 10_000),
    ("following_error_timeout", 10),
    // Quick stop ends in "quick stop active" (6; Kinco's factory value is uncertain,
    // CiA 402's default is 2). Halt brakes on the profile deceleration (1).
    ("quickstop_option", 6),
    ("halt_option", 1),
    ("max_speed", 3000),
    ("gear_factor", 1),
    ("gear_divider", 1),
    ("pulse_mode", 1), // pulse + direction (factory value uncertain)
    ("baud_code", 270),
    ("encoder_resolution", 10_000),
];

/// Fault code injected when none is given (DS402 0x5000 "device hardware").
pub const DEFAULT_FAULT: u16 = 0x5000;
/// DS402 error code of a following error.
pub const FOLLOWING_ERROR_FAULT: u16 = 0x8611;
/// The simulated position loop lags the demand by this much: following error = v × LAG.
pub const LAG: f64 = 0.002;
/// "length of service parameter too high" (public notes' abort table).
const LENGTH_TOO_HIGH: u32 = 0x0607_0012;

/// Something that happens during a motion, at a solved time.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Event {
    /// The move ended and a buffered set-point takes over.
    NextSetpoint,
    /// Homing reached its home point.
    Homed,
    /// A quick stop with option 0-4 came to rest: switch on disabled.
    QuickStopDone,
    /// A limit switch or software limit was reached moving into it.
    Limit,
    /// The following error stayed outside its window for the time-out.
    FollowingError,
    /// The motion crossed an armed fault position (index into `faults_at`).
    PositionFault(usize),
}

/// A simulated Kinco drive. Its whole state is data, so a snapshot (`crate::snapshot`)
/// saves the drive itself: object values, the DS402 state machine, motion and set-point
/// buffer, halt, limits, faults, homing, switches and the pulse input.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct Drive {
    pub id: u8,
    #[serde(with = "values_sorted")]
    values: HashMap<(u16, u8), u32>,
    state: State,
    motion: Motion,
    task: Task,
    /// Position commanded by the last set-point (relative set-points add to it).
    #[serde(with = "crate::core::float_serde")]
    commanded: f64,
    /// A set-point waiting for the current move to end (bit 5 low: set of set-points).
    #[serde(with = "crate::core::float_serde::option")]
    pending: Option<f64>,
    last_cw: u16,
    setpoint_ack: bool,
    fault: Option<u16>,
    homed: bool,
    homing_error: bool,
    following_error: bool,
    /// Bit 11: a limit stopped the drive or clamped a target.
    limit_active: bool,
    /// The homing plan's limit switch (reaching it is the goal).
    homing_onto: Onto,
    /// What halt interrupted, resumed when bit 8 drops.
    resume: Option<Task>,
    /// The last time events were brought up to.
    #[serde(with = "crate::core::float_serde")]
    seen: f64,
    /// Limit switches and the home switch.
    pub switches: Switches,
    /// The pulse input (mode -4), described analytically.
    pub pulses: PulseTrain,
    /// Refuse writes whose size code differs from the object's (0x06070010).
    pub strict: bool,
    /// How many times parameters were stored (2FF0.01 = 1).
    pub saves: u32,
    /// Faults armed at a position: `(position, code)`, injected when the motion crosses it.
    #[serde(with = "crate::core::float_serde::pairs")]
    pub faults_at: Vec<(f64, u16)>,
    /// Armed faults that acted: `(virtual time s, position, code)`.
    #[serde(with = "crate::core::float_serde::triples")]
    pub fault_events: Vec<(f64, f64, u16)>,
    /// Plans replaced while a wire follows the drive, `(time replaced, plan)`, oldest first:
    /// a wire reading the motion later sees it as it was ([`Drive::pieces_from`]), so what
    /// it counts does not depend on when it reads.
    #[serde(default, with = "crate::core::float_serde::pairs")]
    pub history: Vec<(f64, Motion)>,
    /// How many wire hosts follow the drive: while any does, [`Self::history`] is kept.
    #[serde(default)]
    pub followers: u32,
}

/// Most replaced plans a drive keeps for its wires (they are dropped once read).
const HISTORY: usize = 4096;

impl Drive {
    pub fn new(id: u8, t: f64) -> Drive {
        let mut values = HashMap::with_capacity(objects::OBJECTS.len() + 1);
        for o in objects::OBJECTS {
            values.insert((o.index, o.sub), 0);
        }
        for (name, v) in DEFAULTS {
            let o = objects::named(name);
            values.insert((o.index, o.sub), o.dtype.encode(&Value::Int(*v)));
        }
        values.insert((0x100B, 0), id as u32);
        Drive {
            id,
            values,
            state: State::ReadyToSwitchOn,
            motion: Motion::still(t, 0.0),
            task: Task::Idle,
            commanded: 0.0,
            pending: None,
            last_cw: 0,
            setpoint_ack: false,
            fault: None,
            homed: false,
            homing_error: false,
            following_error: false,
            limit_active: false,
            homing_onto: Onto::Nothing,
            resume: None,
            seen: t,
            switches: Switches::default(),
            pulses: PulseTrain::new(),
            strict: false,
            saves: 0,
            faults_at: Vec::new(),
            fault_events: Vec::new(),
            history: Vec::new(),
            followers: 0,
        }
    }

    /// Replaces the plan at `t` (kept in the history while a wire follows the drive).
    fn set_motion(&mut self, m: Motion, t: f64) {
        let old = std::mem::replace(&mut self.motion, m);
        if self.followers > 0 {
            if self.history.len() >= HISTORY {
                self.history.remove(0);
            }
            self.history.push((t, old));
        }
    }

    /// The motion from `t` on as it happened and is planned: the pieces of the plans
    /// replaced since `t` (each up to its replacement), then the current plan's; each
    /// `(t0, dur, p0, v0, a)`, the last one open-ended.
    pub fn pieces_from(&self, t: f64) -> Vec<(f64, f64, f64, f64, f64)> {
        let mut out = Vec::new();
        let mut from = t;
        for (until, m) in &self.history {
            if *until <= from {
                continue;
            }
            for (t0, dur, p0, v0, a) in m.pieces_from(from) {
                if t0 >= *until {
                    break;
                }
                out.push((t0, dur.min(until - t0), p0, v0, a));
            }
            from = *until;
        }
        out.extend(self.motion.pieces_from(from));
        out
    }

    /// Drops the replaced plans that ended by `t` (a wire has read past them).
    pub fn forget_before(&mut self, t: f64) {
        self.history.retain(|(until, _)| *until > t);
    }

    fn stored(&self, name: &str) -> i64 {
        let o = objects::named(name);
        o.dtype.decode(*self.values.get(&(o.index, o.sub)).unwrap_or(&0)).as_i64()
    }

    pub fn mode(&self) -> i8 {
        self.stored("operating_mode") as i8
    }

    pub fn state(&self) -> State {
        self.state
    }

    /// Actual position and velocity (inc, inc/s) at time `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        self.motion.at(t)
    }

    /// The planned motion (what wiring reads the encoder output from).
    pub fn plan(&self) -> &Motion {
        &self.motion
    }

    /// When the drive next handles an event of its own (a limit, a following error …).
    pub fn next_event_time(&self) -> Option<f64> {
        self.next_event().map(|(t, _)| t)
    }

    /// Increments per revolution (6410.03).
    pub fn resolution(&self) -> f64 {
        self.stored("encoder_resolution").max(1) as f64
    }

    /// The pulse input's mode (2508.03): 2 and 12 are A/B quadrature.
    pub fn pulse_mode(&self) -> i64 {
        self.stored("pulse_mode")
    }

    fn accel(&self, name: &str) -> f64 {
        accel_from_dec(self.stored(name) as f64)
    }

    fn moving(&self) -> bool {
        matches!(self.task, Task::Move | Task::Velocity | Task::Homing | Task::Pulse)
    }

    /// Software limits (607D.02 ≤ position ≤ 607D.01), when set (+ above -).
    fn soft_limits(&self) -> Option<(f64, f64)> {
        let (lo, hi) = (self.stored("soft_limit_neg"), self.stored("soft_limit_pos"));
        (hi > lo).then_some((lo as f64, hi as f64))
    }

    /// The next thing that happens in the current motion after `self.seen`, if any.
    fn next_event(&self) -> Option<(f64, Event)> {
        let from = self.seen;
        let end = self.motion.end_time();
        let mut best: Option<(f64, Event)> = None;
        let mut consider = |t: Option<f64>, e: Event| {
            if let Some(t) = t.filter(|t| t.is_finite()) {
                if best.is_none_or(|(b, _)| t < b) {
                    best = Some((t.max(from), e));
                }
            }
        };
        match self.task {
            Task::Move if self.pending.is_some() => consider(Some(end), Event::NextSetpoint),
            Task::Homing => consider(Some(end), Event::Homed),
            Task::QuickStop { disable: true } => consider(Some(end), Event::QuickStopDone),
            _ => {}
        }
        if self.moving() {
            let m = &self.motion;
            // Reaching a limit while moving into it (moving out of one is allowed).
            let into = |x: f64, dir: f64| {
                m.first_reach(x, from).filter(|&t| {
                    let v = m.at(t + 1e-9).1;
                    v * dir > 0.0
                })
            };
            if let Some(l) = self.switches.neg_limit.filter(|_| self.homing_onto != Onto::NegLimit) {
                consider(into(l, -1.0), Event::Limit);
            }
            if let Some(l) = self.switches.pos_limit.filter(|_| self.homing_onto != Onto::PosLimit) {
                consider(into(l, 1.0), Event::Limit);
            }
            if let (Some((lo, hi)), Task::Velocity | Task::Pulse) = (self.soft_limits(), self.task) {
                consider(into(lo, -1.0), Event::Limit);
                consider(into(hi, 1.0), Event::Limit);
            }
            for (k, &(x, _)) in self.faults_at.iter().enumerate() {
                // Crossing it: standing on the position (within half an increment) does not
                // count; from there, it is reached again after leaving it.
                let reach = if (m.at(from).0 - x).abs() < 0.5 {
                    let leave = [m.first_reach(x + 0.5, from), m.first_reach(x - 0.5, from)]
                        .into_iter()
                        .flatten()
                        .fold(f64::INFINITY, f64::min);
                    leave.is_finite().then(|| m.first_reach(x, leave)).flatten()
                } else {
                    m.first_reach(x, from)
                };
                consider(reach, Event::PositionFault(k));
            }
            let window = self.stored("max_following_error") as f64;
            if window > 0.0 {
                let timeout = self.stored("following_error_timeout") as f64 / 1000.0;
                let limit = window / LAG;
                // From the plan's start: the time-out runs from when the error first exceeded.
                if let Some(tc) = m.first_speed(limit, f64::NEG_INFINITY) {
                    let te = tc + timeout;
                    if m.at(te).1.abs() >= limit {
                        consider(Some(te), Event::FollowingError);
                    }
                }
            }
        }
        best
    }

    /// Brings the drive up to time `t`: every event of the current motion up to then is
    /// handled at the moment it happens (solved from the profile, never stepped).
    pub fn advance(&mut self, t: f64) {
        for _ in 0..64 {
            match self.next_event() {
                Some((te, e)) if te <= t => {
                    self.seen = te;
                    self.handle(e, te);
                }
                _ => break,
            }
        }
        self.seen = self.seen.max(t);
    }

    fn handle(&mut self, e: Event, t: f64) {
        match e {
            Event::NextSetpoint => {
                let goal = self.pending.take().expect("pending set-point");
                self.plan_move(goal, t);
                if self.last_cw & (1 << 4) == 0 {
                    self.setpoint_ack = false;
                }
            }
            Event::Homed => {
                let (p, _) = self.motion.at(t);
                let offset = self.stored("home_offset") as f64;
                self.switches.shift(offset - p);
                self.set_motion(Motion::still(t, offset), t);
                self.commanded = offset;
                self.homed = true;
                self.homing_onto = Onto::Nothing;
                self.task = Task::Idle;
            }
            Event::QuickStopDone => {
                self.state = State::SwitchOnDisabled;
                self.stop_dead(t);
            }
            Event::Limit => {
                self.limit_active = true;
                if self.task == Task::Homing {
                    self.homing_error = true;
                    self.homing_onto = Onto::Nothing;
                }
                self.brake("quickstop_deceleration", t);
                self.task = Task::LimitStop;
                self.pending = None;
            }
            Event::FollowingError => {
                self.following_error = true;
                self.fault_now(FOLLOWING_ERROR_FAULT, t);
            }
            Event::PositionFault(k) => {
                let (x, code) = self.faults_at.remove(k);
                self.fault_events.push((t, x, code));
                self.fault_now(code, t);
            }
        }
    }

    /// Injects a fault: the drive stops where it is and enters Fault (DS402 via fault
    /// reaction, which the simulator completes at once).
    pub fn inject_fault(&mut self, code: u16, t: f64) {
        self.advance(t);
        self.fault_now(code, t);
    }

    fn fault_now(&mut self, code: u16, t: f64) {
        self.stop_dead(t);
        self.fault = Some(code);
        self.state = State::Fault;
    }

    /// Adds pulses at the pulse input from `t` on (queued after pulses still arriving).
    pub fn add_pulses(&mut self, t: f64, freq: f64, count: u64, dir: i8) -> Result<(f64, f64), String> {
        self.advance(t);
        self.pulses.forget_before(t);
        let s = self.pulses.push(t, freq, count, dir)?;
        if self.state == State::OperationEnabled && self.mode() == -4 && self.task != Task::Halt {
            self.start_pulse(t);
        }
        Ok((s.start, s.end()))
    }

    /// Connects a whole pulse signal to the pulse input (wiring: e.g. a K2 PTO output's
    /// train), replacing what was there, and follows it from `t` when in mode -4.
    pub fn connect_pulses(&mut self, train: PulseTrain, t: f64) {
        self.advance(t);
        self.pulses = train;
        if self.state == State::OperationEnabled && self.mode() == -4 && self.task != Task::Halt {
            self.start_pulse(t);
        }
    }

    /// The statusword at time `t` (DS402 bits, Kinco bits 14-15; public notes).
    pub fn statusword(&self, t: f64) -> u16 {
        let mut s = self.state.pattern();
        s |= 1 << 4; // voltage enabled (main power on)
        s |= 1 << 9; // remote
        s |= 1 << 14; // Kinco: commutation found
        if self.homed {
            s |= 1 << 15; // Kinco: home found
        }
        let (_, v) = self.motion.at(t);
        let active = matches!(self.state, State::OperationEnabled | State::QuickStopActive);
        let settled = self.motion.settled(t);
        let reached = match (self.task, self.mode()) {
            (Task::Homing, _) => false,
            (Task::Move, _) => settled && self.pending.is_none(),
            (Task::Idle, 6) => self.homed || self.homing_error,
            _ => settled,
        };
        if active && reached {
            s |= 1 << 10;
        }
        if self.limit_active {
            s |= 1 << 11;
        }
        match self.mode() {
            1 if self.setpoint_ack => s |= 1 << 12,
            3 | -3 if v == 0.0 => s |= 1 << 12,
            6 if self.homed && self.task != Task::Homing => s |= 1 << 12,
            _ => {}
        }
        if self.homing_error || self.following_error {
            s |= 1 << 13;
        }
        s
    }

    /// The raw value of an object at time `t`.
    fn read(&mut self, o: &Object, t: f64) -> u32 {
        let (p, v) = self.motion.at(t);
        let int = |dt: DataType, i: i64| dt.encode(&Value::Int(i));
        let inputs = self.switches.inputs(p);
        match o.name {
            "statusword" => self.statusword(t) as u32,
            "position_actual" | "position_actual_value" => int(o.dtype, p.round() as i64),
            "velocity_actual" => int(o.dtype, speed_to_dec(v)),
            "following_error_actual" => int(o.dtype, (v * LAG).round() as i64),
            "mode_display" => self.values[&(0x6060, 0)],
            "error_code" => self.fault.unwrap_or(0) as u32,
            "error_state" => u32::from(self.fault.is_some()),
            "digital_inputs" | "din_real" => inputs,
            "controlword" => self.last_cw as u32,
            "torque_actual" if self.state == State::OperationEnabled && self.mode() == 4 => self.values[&(0x6071, 0)],
            "torque_actual" => 0,
            "master_speed" => int(o.dtype, (self.pulses.rate_at(t) / 1000.0).round() as i64),
            _ => self.values[&(o.index, o.sub)],
        }
    }

    /// A write's data at the object's width, under the size rule (see the module doc):
    /// `Err` is the abort code.
    fn widen(&self, o: &Object, size: Size, data: u32) -> Result<u32, u32> {
        let raw = data & size.mask();
        if size == o.size() {
            return Ok(raw);
        }
        if self.strict {
            return Err(abort::LENGTH_MISMATCH);
        }
        let signed = o.dtype.is_signed() && size != Size::B1;
        let v = match (signed, size) {
            (true, Size::B2) => raw as u16 as i16 as i64,
            (true, _) => raw as i32 as i64,
            (false, _) => raw as i64,
        };
        let (lo, hi) = o.dtype.int_range();
        if v < lo || v > hi {
            return Err(LENGTH_TOO_HIGH);
        }
        Ok(o.dtype.encode(&Value::Int(v)))
    }

    /// Answers one request addressed to this drive; `None` means the drive stays silent.
    pub fn request(&mut self, f: &Frame, t: f64) -> Option<Frame> {
        let o = objects::lookup(f.index, f.sub)?;
        self.advance(t);
        let reply = |func: u8, data: u32| Some(Frame { func, data, ..*f });
        if f.func == func::READ {
            if o.access == Access::WriteOnly {
                return reply(func::ERROR, abort::WRITE_ONLY);
            }
            let raw = self.read(o, t) & o.size().mask();
            // Sign-extend 16-bit values with bit 15 set, as the FD5P does (public notes).
            let data = if o.size() == Size::B2 { raw as u16 as i16 as i32 as u32 } else { raw };
            return reply(o.size().read_reply_func(), data);
        }
        let size = f.write_size()?;
        if o.access == Access::ReadOnly {
            return reply(func::ERROR, abort::READ_ONLY);
        }
        let raw = match self.widen(o, size, f.data) {
            Ok(raw) => raw,
            Err(code) => return reply(func::ERROR, code),
        };
        match self.write(o, raw, t) {
            Ok(()) => reply(func::WRITE_OK, f.data),
            Err(code) => reply(func::ERROR, code),
        }
    }

    fn write(&mut self, o: &Object, raw: u32, t: f64) -> Result<(), u32> {
        let value = o.dtype.decode(raw).as_i64();
        match o.name {
            "controlword" => {
                self.controlword(raw as u16, t);
                return Ok(());
            }
            "operating_mode" => {
                if ![1, 3, -3, 4, 6, -4].contains(&value) {
                    return Err(abort::VALUE_RANGE);
                }
                if value != self.mode() as i64 && self.moving() {
                    self.brake("profile_deceleration", t);
                    self.task = Task::QuickStop { disable: false };
                }
            }
            "quickstop_option" if !(0..=8).contains(&value) => return Err(abort::VALUE_RANGE),
            "halt_option" if !(1..=4).contains(&value) => return Err(abort::VALUE_RANGE),
            "gear_divider" if value == 0 => return Err(abort::VALUE_RANGE),
            "pulse_mode" if !matches!(value, 0..=2 | 10..=12) => return Err(abort::VALUE_RANGE),
            "store_parameters" if value == 1 => self.saves += 1,
            _ => {}
        }
        self.values.insert((o.index, o.sub), raw);
        let enabled = self.state == State::OperationEnabled && self.task != Task::Halt;
        match (o.name, self.mode()) {
            ("target_velocity", 3 | -3) if enabled => self.start_velocity(t),
            // Kinco's immediate start (public C# client: controlword 0x103F "absolute
            // positioning with target position"): with controlword bit 12 set, writing the
            // target position alone starts the move (relative with bit 6: 0x105F).
            ("target_position", 1) if self.state == State::OperationEnabled && self.last_cw & (1 << 12) != 0 => {
                self.setpoint(t, self.last_cw & (1 << 6) != 0, true)
            }
            ("operating_mode", -4) if enabled => self.start_pulse(t),
            ("operating_mode", 3 | -3) if enabled => self.start_velocity(t),
            _ => {}
        }
        Ok(())
    }

    /// Stops dead (drive disabled or faulted): the motor holds where it is.
    fn stop_dead(&mut self, t: f64) {
        let (p, _) = self.motion.at(t);
        self.set_motion(Motion::still(t, p), t);
        self.commanded = p;
        self.task = Task::Idle;
        self.pending = None;
        self.resume = None;
        self.homing_onto = Onto::Nothing;
    }

    /// Decelerates to rest with the deceleration object `decel` (the task is the caller's).
    fn brake(&mut self, decel: &str, t: f64) {
        let (p, v) = self.motion.at(t);
        self.set_motion(Motion::stop(t, p, v, self.accel(decel)), t);
    }

    /// Quick stop from "operation enabled", as 605A.00 says (CiA 402 option codes).
    fn quick_stop(&mut self, t: f64) {
        let option = self.stored("quickstop_option");
        self.pending = None;
        self.resume = None;
        match option {
            // 0: disable the drive function — the power stage is off at once (the motor
            // would coast; the simulator has no load model, so it stops where it is).
            0 => {
                self.state = State::SwitchOnDisabled;
                self.stop_dead(t);
                return;
            }
            1 | 5 => self.brake("profile_deceleration", t),
            // 2, 6; 3/4/7/8 (current/voltage limit) are braked on the quick-stop ramp too.
            _ => self.brake("quickstop_deceleration", t),
        }
        self.task = Task::QuickStop { disable: option <= 4 };
    }

    fn controlword(&mut self, cw: u16, t: f64) {
        let prev = self.last_cw;
        self.last_cw = cw;
        let was = self.state;
        self.state = ds402::next_state(self.state, prev, cw);
        if self.state == State::SwitchOnDisabled && was == State::Fault {
            self.fault = None;
            self.following_error = false;
        }
        if was == State::OperationEnabled && self.state == State::QuickStopActive {
            self.quick_stop(t);
        } else if self.state != State::OperationEnabled && self.state != State::QuickStopActive {
            self.stop_dead(t);
        }
        if self.state != State::OperationEnabled {
            self.setpoint_ack = false;
            return;
        }
        let rising = |bit: u16| cw & bit != 0 && prev & bit == 0;
        let halt = cw & (1 << 8) != 0;
        if was != State::OperationEnabled {
            if matches!(self.task, Task::QuickStop { .. }) {
                self.task = Task::Idle;
            }
            if !halt {
                match self.mode() {
                    3 | -3 => self.start_velocity(t),
                    -4 => self.start_pulse(t),
                    _ => {}
                }
            }
        }
        // Halt (bit 8) in position, velocity, homing and pulse modes: brake, hold, resume.
        if halt && self.task != Task::Halt && self.mode() != 4 {
            self.resume = self.moving().then_some(self.task);
            let decel = if self.stored("halt_option") == 2 { "quickstop_deceleration" } else { "profile_deceleration" };
            self.brake(decel, t);
            self.task = Task::Halt;
        } else if !halt && self.task == Task::Halt {
            self.task = Task::Idle;
            match self.resume.take() {
                Some(Task::Move) => self.plan_move(self.commanded, t),
                Some(Task::Velocity) => self.start_velocity(t),
                Some(Task::Homing) => self.start_homing(t),
                Some(Task::Pulse) => self.start_pulse(t),
                _ => {}
            }
        }
        match self.mode() {
            1 => {
                if rising(1 << 4) {
                    self.setpoint(t, cw & (1 << 6) != 0, cw & (1 << 5) != 0);
                } else if cw & (1 << 4) == 0 && self.pending.is_none() {
                    self.setpoint_ack = false;
                }
            }
            6 if rising(1 << 4) && !halt => self.start_homing(t),
            _ => {}
        }
    }

    /// A new set-point (bit 4 rising, or a target write under 0x103F): with bit 5 high (or
    /// no move running) it applies at once; with bit 5 low during a move it waits in the
    /// one-deep buffer until the move ends (CiA 402 "set of set-points"). A full buffer
    /// does not acknowledge; the master waits for bit 12 to drop first.
    fn setpoint(&mut self, t: f64, relative: bool, immediate: bool) {
        let target = self.stored("target_position") as f64;
        let goal_from = |base: f64| if relative { base + target } else { target };
        self.limit_active = false;
        if self.task == Task::Halt {
            self.commanded = self.clamp(goal_from(self.commanded));
            self.resume = Some(Task::Move);
            self.setpoint_ack = true;
            return;
        }
        let running = self.task == Task::Move && !self.motion.settled(t);
        if running && !immediate {
            if self.pending.is_none() {
                let base = self.commanded;
                self.pending = Some(self.clamp(goal_from(base)));
                self.setpoint_ack = true;
            }
            return;
        }
        let base = if self.task == Task::Move { self.commanded } else { self.motion.at(t).0.round() };
        let goal = self.clamp(goal_from(base));
        self.pending = None;
        self.plan_move(goal, t);
        self.setpoint_ack = true;
    }

    /// Limits a target to the software limits (bit 11 when it had to).
    fn clamp(&mut self, goal: f64) -> f64 {
        match self.soft_limits() {
            Some((lo, hi)) if goal < lo || goal > hi => {
                self.limit_active = true;
                goal.clamp(lo, hi)
            }
            _ => goal,
        }
    }

    fn plan_move(&mut self, goal: f64, t: f64) {
        let (p, v) = self.motion.at(t);
        self.commanded = goal;
        self.set_motion(
            Motion::position(
                t,
                p,
                v,
                goal,
                speed_from_dec(self.stored("profile_velocity") as f64),
                self.accel("profile_acceleration"),
                self.accel("profile_deceleration"),
            ),
            t,
        );
        self.task = Task::Move;
    }

    fn start_velocity(&mut self, t: f64) {
        let (p, v) = self.motion.at(t);
        self.limit_active = false;
        let target = speed_from_dec(self.stored("target_velocity") as f64);
        self.set_motion(
            if self.mode() == -3 {
                // Immediate velocity: no ramp.
                Motion::velocity(t, p, target, target, 1.0, 1.0)
            } else {
                Motion::velocity(
                    t,
                    p,
                    v,
                    target,
                    self.accel("profile_acceleration"),
                    self.accel("profile_deceleration"),
                )
            },
            t,
        );
        self.task = Task::Velocity;
    }

    fn start_homing(&mut self, t: f64) {
        let (p, v) = self.motion.at(t);
        self.homed = false;
        self.homing_error = false;
        self.limit_active = false;
        let method = self.stored("homing_method") as i8;
        let r = self.stored("encoder_resolution") as f64;
        match homing::plan(method, p, &self.switches, r) {
            Ok(plan) => {
                let acc = self.accel("homing_acceleration");
                let speed = speed_from_dec(self.stored("homing_speed_switch") as f64);
                self.set_motion(Motion::position(t, p, v, plan.target, speed, acc, acc), t);
                self.homing_onto = plan.onto;
                self.task = Task::Homing;
            }
            Err(_) => {
                self.homing_error = true;
                self.brake("quickstop_deceleration", t);
                self.task = Task::Idle;
            }
        }
    }

    /// Pulse-train mode (-4): the position follows the pulse input through the gear,
    /// `increments = counts × 2508.01 / 2508.02`, where one pulse is one count in CW/CCW and
    /// pulse+direction modes and four in A/B mode (quadrature ×4 — uncertain for Kinco).
    fn start_pulse(&mut self, t: f64) {
        let (p, _) = self.motion.at(t);
        let counts = if matches!(self.stored("pulse_mode"), 2 | 12) { 4.0 } else { 1.0 };
        let gear = self.stored("gear_factor") as f64 / (self.stored("gear_divider").max(1)) as f64;
        let pieces: Vec<(f64, f64)> =
            self.pulses.pieces_from(t).into_iter().map(|(d, rate)| (d, rate * counts * gear)).collect();
        self.set_motion(Motion::cruise(t, p, &pieces), t);
        self.limit_active = false;
        self.task = Task::Pulse;
    }
}

/// Object values in a snapshot: `(index, sub, raw value)` sorted, since JSON maps take
/// text keys only and a sorted list keeps snapshot files stable.
mod values_sorted {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    use std::collections::HashMap;

    pub fn serialize<S: Serializer>(v: &HashMap<(u16, u8), u32>, s: S) -> Result<S::Ok, S::Error> {
        let mut list: Vec<(u16, u8, u32)> = v.iter().map(|(&(i, sub), &raw)| (i, sub, raw)).collect();
        list.sort_unstable();
        list.serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<HashMap<(u16, u8), u32>, D::Error> {
        let list = Vec::<(u16, u8, u32)>::deserialize(d)?;
        Ok(list.into_iter().map(|(i, sub, raw)| ((i, sub), raw)).collect())
    }
}

#[cfg(test)]
mod tests;
