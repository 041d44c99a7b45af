//! One simulated drive: its object dictionary (the same table the driver uses), the DS402
//! state machine, the operating modes 1 (profile position), 3 (profile velocity), -3
//! (immediate velocity) and 6 (homing to a simulated switch), quick stop, and an
//! injectable fault.
//!
//! It answers requests exactly as `../shared/spec/kinco-servo.md` §2 says a drive does:
//! nothing at all for an object it does not have (or a function code it does not know),
//! `0x80` with a CiA-301 abort code for a write to a read-only object or of the wrong
//! length (public notes), `0x60` echoing the data for an accepted write, `0x4F/0x4B/0x43`
//! for reads. Like the FD5P the notes quote, 16-bit values are sent sign-extended (bit 15
//! set → `FF FF` in D2..D3), so drivers must mask to the object's size.
//!
//! State at power-up is "ready to switch on" with bits 9 (remote) and 14 set: statusword
//! 0x4231, the value in the manual's worked read example. Time is the virtual clock's, in
//! seconds; motion is [`super::motion`]'s analytic profiles.

use super::motion::{accel_from_dec, speed_from_dec, speed_to_dec, Motion};
use crate::core::DataType;
use crate::servo::ds402::{self, State};
use crate::servo::frame::{abort, func, Frame, Size};
use crate::servo::objects::{self, Access, Object};
use std::collections::HashMap;

/// What the drive is doing, beyond the profile itself.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
enum Task {
    /// Holding position (nothing commanded).
    Idle,
    /// A profile position move (mode 1).
    Move,
    /// Following the target velocity (modes 3, -3).
    Velocity,
    /// Homing to the switch (mode 6).
    Homing,
    /// Quick stop deceleration.
    QuickStop,
}

/// Default values at power-up, by object name (everything else starts at 0).
const DEFAULTS: &[(&str, i64)] = &[
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
    ("max_speed", 3000),
    ("gear_factor", 1),
    ("gear_divider", 1),
    ("baud_code", 270),
    ("encoder_resolution", 10_000),
];

/// Fault code injected when none is given (DS402 0x5000 "device hardware").
pub const DEFAULT_FAULT: u16 = 0x5000;

/// A simulated Kinco drive.
#[derive(Clone, Debug)]
pub struct Drive {
    pub id: u8,
    values: HashMap<(u16, u8), u32>,
    state: State,
    motion: Motion,
    task: Task,
    /// Position commanded by the last move (relative moves add to it).
    commanded: f64,
    last_cw: u16,
    setpoint_ack: bool,
    fault: Option<u16>,
    homed: bool,
    homing_error: bool,
    /// Where the simulated home switch is, in the current position coordinates.
    pub home_switch: f64,
    /// How many times parameters were stored (2FF0.01 = 1).
    pub saves: u32,
}

impl Drive {
    pub fn new(id: u8, t: f64) -> Drive {
        let mut values = HashMap::new();
        for o in objects::OBJECTS {
            values.insert((o.index, o.sub), 0);
        }
        for (name, v) in DEFAULTS {
            let o = objects::named(name);
            values.insert((o.index, o.sub), o.dtype.encode(&crate::core::Value::Int(*v)));
        }
        values.insert((0x100B, 0), id as u32);
        Drive {
            id,
            values,
            state: State::ReadyToSwitchOn,
            motion: Motion::still(t, 0.0),
            task: Task::Idle,
            commanded: 0.0,
            last_cw: 0,
            setpoint_ack: false,
            fault: None,
            homed: false,
            homing_error: false,
            home_switch: 5_000.0,
            saves: 0,
        }
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

    /// Brings lazy transitions up to time `t`: homing completion and the position it defines.
    pub fn advance(&mut self, t: f64) {
        if self.task == Task::Homing && self.motion.settled(t) {
            let end = self.motion.end_time();
            let offset = self.stored("home_offset") as f64;
            self.motion = Motion::still(end, offset);
            self.commanded = offset;
            self.home_switch = offset;
            self.homed = true;
            self.task = Task::Idle;
        }
    }

    /// Injects a fault: the drive stops where it is and enters Fault (DS402 via fault
    /// reaction, which the simulator completes at once).
    pub fn inject_fault(&mut self, code: u16, t: f64) {
        self.advance(t);
        self.halt(t);
        self.fault = Some(code);
        self.state = State::Fault;
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
            (Task::QuickStop, _) => settled,
            (Task::Homing, _) => false,
            (Task::Velocity, _) => settled,
            (_, 6) => self.homed && settled,
            _ => settled,
        };
        if active && reached {
            s |= 1 << 10;
        }
        match self.mode() {
            1 if self.setpoint_ack => s |= 1 << 12,
            3 | -3 if v == 0.0 => s |= 1 << 12,
            6 if self.homed && self.task != Task::Homing => s |= 1 << 12,
            _ => {}
        }
        if self.homing_error {
            s |= 1 << 13;
        }
        s
    }

    /// The raw value of an object at time `t`.
    fn read(&mut self, o: &Object, t: f64) -> u32 {
        let (p, v) = self.motion.at(t);
        let int = |dt: DataType, i: i64| dt.encode(&crate::core::Value::Int(i));
        match o.name {
            "statusword" => self.statusword(t) as u32,
            "position_actual" => int(o.dtype, p.round() as i64),
            "velocity_actual" => int(o.dtype, speed_to_dec(v)),
            "mode_display" => self.values[&(0x6060, 0)],
            "error_code" => self.fault.unwrap_or(0) as u32,
            "error_state" => u32::from(self.fault.is_some()),
            "digital_inputs" => u32::from(p >= self.home_switch) << 2,
            "controlword" => self.last_cw as u32,
            _ => self.values[&(o.index, o.sub)],
        }
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
        if size != o.size() {
            return reply(func::ERROR, abort::LENGTH_MISMATCH);
        }
        let raw = f.data & size.mask();
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
                if value != self.mode() as i64 && self.task != Task::Idle {
                    self.stop_with("profile_deceleration", t);
                }
            }
            "store_parameters" if value == 1 => self.saves += 1,
            _ => {}
        }
        self.values.insert((o.index, o.sub), raw);
        if o.name == "target_velocity" && self.state == State::OperationEnabled && matches!(self.mode(), 3 | -3) {
            self.start_velocity(t);
        }
        Ok(())
    }

    /// Stops dead (drive disabled or faulted): the motor holds where it is.
    fn halt(&mut self, t: f64) {
        let (p, _) = self.motion.at(t);
        self.motion = Motion::still(t, p);
        self.commanded = p;
        self.task = Task::Idle;
    }

    fn stop_with(&mut self, decel: &str, t: f64) {
        let (p, v) = self.motion.at(t);
        self.motion = Motion::stop(t, p, v, accel_from_dec(self.stored(decel) as f64));
        self.task = Task::QuickStop;
    }

    fn controlword(&mut self, cw: u16, t: f64) {
        let prev = self.last_cw;
        self.last_cw = cw;
        let was = self.state;
        self.state = ds402::next_state(self.state, prev, cw);
        if self.state == State::SwitchOnDisabled && was == State::Fault {
            self.fault = None;
        }
        if was == State::OperationEnabled && self.state == State::QuickStopActive {
            self.stop_with("quickstop_deceleration", t);
        } else if self.state != State::OperationEnabled && self.state != State::QuickStopActive {
            self.halt(t);
        }
        if self.state != State::OperationEnabled {
            self.setpoint_ack = false;
            return;
        }
        let rising = |bit: u16| cw & bit != 0 && prev & bit == 0;
        if was != State::OperationEnabled && matches!(self.mode(), 3 | -3) {
            self.start_velocity(t);
        }
        match self.mode() {
            1 => {
                if rising(1 << 4) {
                    self.start_move(cw & (1 << 6) != 0, t);
                    self.setpoint_ack = true;
                } else if cw & (1 << 4) == 0 {
                    self.setpoint_ack = false;
                }
            }
            6 if rising(1 << 4) => self.start_homing(t),
            _ => {}
        }
    }

    fn start_move(&mut self, relative: bool, t: f64) {
        let (p, v) = self.motion.at(t);
        let target = self.stored("target_position") as f64;
        let base = if self.task == Task::Move { self.commanded } else { p.round() };
        let goal = if relative { base + target } else { target };
        self.commanded = goal;
        self.motion = Motion::position(
            t,
            p,
            v,
            goal,
            speed_from_dec(self.stored("profile_velocity") as f64),
            accel_from_dec(self.stored("profile_acceleration") as f64),
            accel_from_dec(self.stored("profile_deceleration") as f64),
        );
        self.task = Task::Move;
    }

    fn start_velocity(&mut self, t: f64) {
        let (p, v) = self.motion.at(t);
        let target = speed_from_dec(self.stored("target_velocity") as f64);
        self.motion = if self.mode() == -3 {
            // Immediate velocity: no ramp.
            Motion::velocity(t, p, target, target, 1.0, 1.0)
        } else {
            Motion::velocity(
                t,
                p,
                v,
                target,
                accel_from_dec(self.stored("profile_acceleration") as f64),
                accel_from_dec(self.stored("profile_deceleration") as f64),
            )
        };
        self.task = Task::Velocity;
    }

    fn start_homing(&mut self, t: f64) {
        let (p, v) = self.motion.at(t);
        self.homed = false;
        self.homing_error = false;
        self.motion = Motion::position(
            t,
            p,
            v,
            self.home_switch,
            speed_from_dec(self.stored("homing_speed_switch") as f64),
            accel_from_dec(self.stored("homing_acceleration") as f64),
            accel_from_dec(self.stored("homing_acceleration") as f64),
        );
        self.task = Task::Homing;
    }
}
/// A drive's complete state for snapshots (`crate::snapshot`): object values, the DS402
/// state machine, the motion in progress, faults and homing.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct DriveState {
    pub id: u8,
    /// `(index, sub, raw value)`, sorted.
    values: Vec<(u16, u8, u32)>,
    state: State,
    motion: Motion,
    task: Task,
    commanded: f64,
    last_cw: u16,
    setpoint_ack: bool,
    fault: Option<u16>,
    homed: bool,
    homing_error: bool,
    home_switch: f64,
    saves: u32,
}

impl Drive {
    pub fn save(&self) -> DriveState {
        let mut values: Vec<(u16, u8, u32)> = self.values.iter().map(|(&(i, s), &v)| (i, s, v)).collect();
        values.sort_unstable();
        DriveState {
            id: self.id,
            values,
            state: self.state,
            motion: self.motion.clone(),
            task: self.task,
            commanded: self.commanded,
            last_cw: self.last_cw,
            setpoint_ack: self.setpoint_ack,
            fault: self.fault,
            homed: self.homed,
            homing_error: self.homing_error,
            home_switch: self.home_switch,
            saves: self.saves,
        }
    }

    pub fn from_state(s: DriveState) -> Drive {
        Drive {
            id: s.id,
            values: s.values.into_iter().map(|(i, sub, v)| ((i, sub), v)).collect(),
            state: s.state,
            motion: s.motion,
            task: s.task,
            commanded: s.commanded,
            last_cw: s.last_cw,
            setpoint_ack: s.setpoint_ack,
            fault: s.fault,
            homed: s.homed,
            homing_error: s.homing_error,
            home_switch: s.home_switch,
            saves: s.saves,
        }
    }
}
