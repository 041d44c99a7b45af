//! The CiA 402 (DS402) drive profile as Kinco drives use it (`../shared/spec/kinco-public-notes.md`,
//! "Controlword / statusword"): the state machine (shared by the simulator, so both sides
//! agree), statusword decoding, and the helpers behind the `servo` shell commands, which run
//! on any [`ServoOps`] — the serial driver and the simulator alike.
//!
//! Helpers follow the manual's ordering rule (`../shared/spec/kinco-servo.md` §3): every
//! parameter first, the controlword last, "so the drive does not start before its
//! parameters are set"; a move then raises the new-set-point bit (bit 4) as a rising edge.
//! Every state change is verified by reading the statusword back.

use super::objects::{self, ObjRef};
use super::ServoOps;
use crate::core::{Clock, Error, ErrorKind, Result, Value};
use crate::msg;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

/// Controlword commands (public notes; CiA 402).
pub mod cw {
    pub const DISABLE_VOLTAGE: u16 = 0x00;
    pub const SHUTDOWN: u16 = 0x06;
    pub const SWITCH_ON: u16 = 0x07;
    pub const ENABLE_OPERATION: u16 = 0x0F;
    /// Quick stop as Kinco's examples write it (bit 2 low, bits 0, 1, 3 high).
    pub const QUICK_STOP: u16 = 0x0B;
    pub const FAULT_RESET: u16 = 0x80;
    pub const NEW_SETPOINT: u16 = 1 << 4;
    pub const CHANGE_IMMEDIATELY: u16 = 1 << 5;
    pub const RELATIVE: u16 = 1 << 6;
    /// Halt: brake to a stop and hold; clearing it resumes (CiA 402).
    pub const HALT: u16 = 1 << 8;
    /// Kinco absolute move: 0x2F, then 0x3F (bit 4 rising).
    pub const MOVE_ABS: u16 = ENABLE_OPERATION | CHANGE_IMMEDIATELY;
    /// Kinco relative move: 0x4F, then 0x5F.
    pub const MOVE_REL: u16 = ENABLE_OPERATION | RELATIVE;
}

/// DS402 states.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum State {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
}

impl State {
    /// The statusword bits 0-6 of this state (bit 5 set where the pattern requires it).
    pub fn pattern(self) -> u16 {
        match self {
            State::NotReadyToSwitchOn => 0x00,
            State::SwitchOnDisabled => 0x40,
            State::ReadyToSwitchOn => 0x21,
            State::SwitchedOn => 0x23,
            State::OperationEnabled => 0x27,
            State::QuickStopActive => 0x07,
            State::FaultReactionActive => 0x0F,
            State::Fault => 0x08,
        }
    }

    /// Decodes the state from a statusword (masks 0x4F and 0x6F, CiA 402).
    pub fn from_statusword(sw: u16) -> Option<State> {
        Some(match (sw & 0x4F, sw & 0x6F) {
            (0x00, _) => State::NotReadyToSwitchOn,
            (0x40, _) => State::SwitchOnDisabled,
            (0x0F, _) => State::FaultReactionActive,
            (0x08, _) => State::Fault,
            (_, 0x21) => State::ReadyToSwitchOn,
            (_, 0x23) => State::SwitchedOn,
            (_, 0x27) => State::OperationEnabled,
            (_, 0x07) => State::QuickStopActive,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            State::NotReadyToSwitchOn => "not ready to switch on",
            State::SwitchOnDisabled => "switch on disabled",
            State::ReadyToSwitchOn => "ready to switch on",
            State::SwitchedOn => "switched on",
            State::OperationEnabled => "operation enabled",
            State::QuickStopActive => "quick stop active",
            State::FaultReactionActive => "fault reaction active",
            State::Fault => "fault",
        }
    }
}

/// The state after writing controlword `cw` (previous value `prev`) in `state`
/// (CiA 402 transitions; from "ready to switch on", 0x0F goes straight to "operation
/// enabled", as the manual's one-frame enable example needs).
pub fn next_state(state: State, prev: u16, cw: u16) -> State {
    use State::*;
    let fault_reset = cw & 0x80 != 0 && prev & 0x80 == 0;
    match state {
        Fault => return if fault_reset { SwitchOnDisabled } else { Fault },
        FaultReactionActive | NotReadyToSwitchOn => return state,
        _ => {}
    }
    if cw & 0x80 != 0 {
        return state; // bit 7 high outside Fault: no command
    }
    if cw & 0x02 == 0 {
        return SwitchOnDisabled; // disable voltage
    }
    if cw & 0x06 == 0x02 {
        // quick stop
        return match state {
            OperationEnabled | QuickStopActive => QuickStopActive,
            _ => SwitchOnDisabled,
        };
    }
    match cw & 0x0F {
        0x06 | 0x0E => match state {
            SwitchOnDisabled | ReadyToSwitchOn | SwitchedOn | OperationEnabled => ReadyToSwitchOn,
            s => s,
        },
        0x07 => match state {
            ReadyToSwitchOn | SwitchedOn | OperationEnabled => SwitchedOn,
            s => s,
        },
        0x0F => match state {
            ReadyToSwitchOn | SwitchedOn | OperationEnabled | QuickStopActive => OperationEnabled,
            s => s,
        },
        _ => state,
    }
}

/// Statusword bit names (public notes); bits 12 and 13 depend on the mode.
pub fn bit_name(bit: u8, mode: Option<i8>) -> &'static str {
    match bit {
        0 => "ready to switch on",
        1 => "switched on",
        2 => "operation enabled",
        3 => "fault",
        4 => "voltage enabled",
        // Set means quick stop is NOT active (CiA 402: the bit is active low).
        5 => "quick stop: off",
        6 => "switch on disabled",
        7 => "warning",
        9 => "remote",
        10 => "target reached",
        11 => "internal limit active",
        12 => match mode {
            Some(1) => "set-point acknowledge",
            Some(3) | Some(-3) => "speed zero",
            Some(6) => "homing attained",
            _ => "set-point acknowledge / speed zero / homing attained",
        },
        13 => match mode {
            Some(6) => "homing error",
            _ => "following error",
        },
        14 => "commutation found (Kinco)",
        15 => "home found (Kinco)",
        _ => "manufacturer specific",
    }
}

/// A decoded statusword.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Status {
    pub statusword: u16,
    pub state: String,
    /// `(bit, name)` of every bit that is set.
    pub bits: Vec<(u8, &'static str)>,
    pub fault: bool,
    pub target_reached: bool,
    pub mode: Option<i8>,
}

pub fn decode_status(sw: u16, mode: Option<i8>) -> Status {
    let state = State::from_statusword(sw).map(State::name).unwrap_or("unknown state pattern");
    Status {
        statusword: sw,
        state: state.to_string(),
        bits: (0..16).filter(|b| sw & (1 << b) != 0).map(|b| (b, bit_name(b, mode))).collect(),
        fault: sw & (1 << 3) != 0,
        target_reached: sw & (1 << 10) != 0,
        mode,
    }
}

/// Mode names for `servo mode`.
/// The operating modes `servo mode` takes, by number (their names: [`mode_name`]).
pub const MODES: &[i8] = &[1, 3, -3, 6, 4, -4];

pub fn mode_number(name: &str) -> Option<i8> {
    Some(match name {
        "position" | "pp" | "1" => 1,
        "velocity" | "pv" | "3" => 3,
        "immediate-velocity" | "-3" => -3,
        "homing" | "hm" | "6" => 6,
        "torque" | "4" => 4,
        "pulse" | "-4" => -4,
        _ => return None,
    })
}

pub fn mode_name(m: i8) -> &'static str {
    match m {
        1 => "position",
        3 => "velocity",
        -3 => "immediate-velocity",
        4 => "torque",
        6 => "homing",
        -4 => "pulse",
        _ => "unknown",
    }
}

/// How helpers wait: on the session's virtual clock for simulators (a stepped clock
/// advances instantly), on the wall clock for real drives; Ctrl-C interrupts.
pub struct Waiter<'a> {
    pub clock: Clock,
    pub interrupt: &'a AtomicBool,
}

impl Waiter<'_> {
    fn sleep(&self, d: Duration) -> Result<()> {
        if !self.clock.sleep(d, self.interrupt) || self.interrupt.load(Ordering::Relaxed) {
            return Err(Error::new(ErrorKind::Interrupted, "interrupted"));
        }
        Ok(())
    }
}

/// Poll period of waits.
pub const POLL: Duration = Duration::from_millis(10);
/// How long `move` waits for a full set-point buffer to take a new set-point.
pub const BUFFER_WAIT: Duration = Duration::from_secs(30);
/// How long a state change may take before `enable` and friends call it failed.
pub const STEP_TIMEOUT: Duration = Duration::from_millis(500);

fn obj(name: &str) -> ObjRef {
    ObjRef::of(objects::named(name))
}

/// Asks the write guard for every object a helper will write, before it writes any, so
/// a refused helper sends nothing.
fn declare(ops: &dyn ServoOps, names: &[&str]) -> Result<()> {
    let changes: Vec<_> = names.iter().map(|n| super::changes::write(obj(n))).collect();
    ops.permits(&changes)
}

/// The objects a move or jog writes: the mode, the target, the profile given, the controlword.
fn motion_objects(target: &'static str, p: &Profile, speed: bool) -> Vec<&'static str> {
    let mut v = vec!["operating_mode", target];
    for (given, name) in [
        (speed && p.speed.is_some(), "profile_velocity"),
        (p.acc.is_some(), "profile_acceleration"),
        (p.dec.is_some(), "profile_deceleration"),
    ] {
        if given {
            v.push(name);
        }
    }
    v.push("controlword");
    v
}

/// Reads a table object as a number.
pub fn read(ops: &mut dyn ServoOps, name: &str) -> Result<i64> {
    let r = obj(name);
    Ok(r.dtype.decode(ops.read_raw(r)?).as_i64())
}

/// Writes a table object, checking that the value fits it first.
pub fn write(ops: &mut dyn ServoOps, name: &str, v: i64) -> Result<()> {
    let r = obj(name);
    let (lo, hi) = r.dtype.int_range();
    if v < lo || v > hi {
        let (v, lo, hi) = (v.to_string(), lo.to_string(), hi.to_string());
        return Err(Error::new(
            ErrorKind::Value,
            msg!("tbl-ds402-does-not-fit", value = v, name = name, lo = lo, hi = hi),
        )
        .operand(name));
    }
    ops.write_raw(r, r.dtype.encode(&Value::Int(v)))
}

pub fn statusword(ops: &mut dyn ServoOps) -> Result<u16> {
    Ok(read(ops, "statusword")? as u16)
}

/// Reads and decodes the statusword (with the operating mode for bits 12-13).
pub fn status(ops: &mut dyn ServoOps) -> Result<Status> {
    let sw = statusword(ops)?;
    let mode = read(ops, "operating_mode")? as i8;
    Ok(decode_status(sw, Some(mode)))
}

/// Writes controlword `cw` and waits until the state is `want`.
fn step(ops: &mut dyn ServoOps, w: &Waiter, what: &str, cw: u16, want: &[State]) -> Result<State> {
    write(ops, "controlword", cw as i64)?;
    let start = w.clock.now();
    loop {
        let sw = statusword(ops)?;
        let st = State::from_statusword(sw);
        if let Some(s) = st.filter(|s| want.contains(s)) {
            return Ok(s);
        }
        if w.clock.now() - start >= STEP_TIMEOUT {
            // "A or B or C": the states the step accepts, joined as the language joins alternatives.
            let names =
                want.iter().map(|s| s.name().to_string()).reduce(|a, b| msg!("tbl-ds402-or", a = a, b = b).text);
            let names = names.unwrap_or_default();
            let (cw, sw) = (format!("{cw:04X}"), format!("{sw:04X}"));
            let m = match st {
                Some(st) => {
                    msg!("tbl-ds402-step-stuck", what = what, cw = &cw, want = &names, sw = &sw, state = st.name())
                }
                None => msg!("tbl-ds402-step-stuck-unknown", what = what, cw = &cw, want = &names, sw = &sw),
            };
            let faulted = u16::from_str_radix(&sw, 16).unwrap_or(0) & 0x08 != 0;
            return Err(Error::state(m).hint(if faulted {
                msg!("tbl-ds402-in-fault-hint")
            } else {
                msg!("tbl-ds402-check-status-hint")
            }));
        }
        w.sleep(POLL)?;
    }
}

/// `servo enable`: shutdown → switch on → enable operation, verifying each step.
/// Returns the steps taken (empty when the drive was already enabled).
pub fn enable(ops: &mut dyn ServoOps, w: &Waiter) -> Result<Vec<&'static str>> {
    declare(ops, &["controlword"])?;
    let sw = statusword(ops)?;
    match State::from_statusword(sw) {
        Some(State::OperationEnabled) => return Ok(Vec::new()),
        Some(State::QuickStopActive) => {
            // CiA 402 transition 16: quick stop active → operation enabled directly.
            step(ops, w, "enable operation", cw::ENABLE_OPERATION, &[State::OperationEnabled])?;
            return Ok(vec!["enable operation"]);
        }
        Some(State::Fault | State::FaultReactionActive) => {
            return Err(Error::state(msg!("tbl-ds402-in-fault", sw = format!("{sw:04X}")))
                .hint(msg!("tbl-ds402-in-fault-enable-hint")))
        }
        _ => {}
    }
    step(ops, w, "shutdown", cw::SHUTDOWN, &[State::ReadyToSwitchOn])?;
    step(ops, w, "switch on", cw::SWITCH_ON, &[State::SwitchedOn])?;
    step(ops, w, "enable operation", cw::ENABLE_OPERATION, &[State::OperationEnabled])?;
    Ok(vec!["shutdown", "switch on", "enable operation"])
}

/// `servo disable`: shutdown (0x06), so the motor is no longer powered; from "quick stop
/// active", where CiA 402 has no shutdown transition, disable voltage (0x00).
pub fn disable(ops: &mut dyn ServoOps, w: &Waiter) -> Result<State> {
    declare(ops, &["controlword"])?;
    if State::from_statusword(statusword(ops)?) == Some(State::QuickStopActive) {
        return step(ops, w, "disable voltage", cw::DISABLE_VOLTAGE, &[State::SwitchOnDisabled]);
    }
    step(ops, w, "shutdown", cw::SHUTDOWN, &[State::ReadyToSwitchOn, State::SwitchOnDisabled])
}

/// `servo fault-reset`: a rising edge on bit 7 (0x06, then 0x86 as Kinco's examples do).
/// A drive that is not in fault is left alone (0x06 would disable it).
pub fn fault_reset(ops: &mut dyn ServoOps, w: &Waiter) -> Result<State> {
    declare(ops, &["controlword"])?;
    let sw = statusword(ops)?;
    match State::from_statusword(sw) {
        Some(State::Fault | State::FaultReactionActive) | None => {}
        Some(s) => return Ok(s),
    }
    write(ops, "controlword", cw::SHUTDOWN as i64)?;
    step(
        ops,
        w,
        "fault reset",
        cw::FAULT_RESET | cw::SHUTDOWN,
        &[State::SwitchOnDisabled, State::ReadyToSwitchOn, State::SwitchedOn, State::OperationEnabled],
    )
}

/// `servo quickstop`: controlword 0x0B; an enabled drive brakes with 6085.00 and stays in
/// "quick stop active".
pub fn quickstop(ops: &mut dyn ServoOps, w: &Waiter) -> Result<State> {
    declare(ops, &["controlword"])?;
    step(ops, w, "quick stop", cw::QUICK_STOP, &[State::QuickStopActive, State::SwitchOnDisabled])
}

/// `servo mode NAME`: writes 6060.00 and reads it back.
pub fn set_mode(ops: &mut dyn ServoOps, mode: i8) -> Result<()> {
    declare(ops, &["operating_mode"])?;
    write(ops, "operating_mode", mode as i64)?;
    let got = read(ops, "operating_mode")? as i8;
    if got != mode {
        return Err(Error::state(msg!("tbl-ds402-mode-readback", got = got, mode = mode)));
    }
    Ok(())
}

fn require_enabled(ops: &mut dyn ServoOps, what: &str) -> Result<()> {
    let sw = statusword(ops)?;
    if State::from_statusword(sw) != Some(State::OperationEnabled) {
        let sw = format!("{sw:04X}");
        let m = match State::from_statusword(u16::from_str_radix(&sw, 16).unwrap_or(0)) {
            Some(st) => msg!("tbl-ds402-not-enabled", what = what, state = st.name(), sw = &sw),
            None => msg!("tbl-ds402-not-enabled-unknown", what = what, sw = &sw),
        };
        return Err(Error::state(m).hint(msg!("tbl-ds402-not-enabled-hint")));
    }
    Ok(())
}

/// Optional profile parameters of a move or jog (raw DEC values).
#[derive(Clone, Copy, Debug, Default)]
pub struct Profile {
    pub speed: Option<i64>,
    pub acc: Option<i64>,
    pub dec: Option<i64>,
}

/// `servo move abs|rel POS`: mode 1, target position, profile speed/acc/dec, then the
/// controlword (0x2F/0x4F) and the set-point edge (0x3F/0x5F), verified by the set-point
/// acknowledge bit; bit 4 is dropped again afterwards so the next move has its edge.
pub fn move_to(ops: &mut dyn ServoOps, w: &Waiter, relative: bool, pos: i64, p: Profile) -> Result<()> {
    declare(ops, &motion_objects("target_position", &p, true))?;
    require_enabled(ops, "move")?;
    write(ops, "operating_mode", 1)?;
    write(ops, "target_position", pos)?;
    if let Some(v) = p.speed {
        write(ops, "profile_velocity", v)?;
    }
    if let Some(a) = p.acc {
        write(ops, "profile_acceleration", a)?;
    }
    if let Some(d) = p.dec {
        write(ops, "profile_deceleration", d)?;
    }
    let base = if relative { cw::MOVE_REL } else { cw::MOVE_ABS };
    write(ops, "controlword", base as i64)?;
    // CiA 402 handshake: a set-point acknowledge still high with bit 4 low means the drive's
    // set-point buffer is full (a relative move queued behind a running one); a new edge
    // now would be ignored, so wait for the buffer to drain first.
    let start = w.clock.now();
    loop {
        let sw = statusword(ops)?;
        if sw & (1 << 12) == 0 || sw & 0x08 != 0 {
            break;
        }
        if w.clock.now() - start >= BUFFER_WAIT {
            return Err(Error::state(msg!(
                "tbl-ds402-buffer-full",
                seconds = BUFFER_WAIT.as_secs(),
                sw = format!("{sw:04X}")
            ))
            .hint(msg!("tbl-ds402-buffer-full-hint")));
        }
        w.sleep(POLL)?;
    }
    write(ops, "controlword", (base | cw::NEW_SETPOINT) as i64)?;
    let start = w.clock.now();
    loop {
        let sw = statusword(ops)?;
        if sw & (1 << 12) != 0 {
            break;
        }
        if sw & 0x08 != 0 || w.clock.now() - start >= STEP_TIMEOUT {
            return Err(Error::state(msg!("tbl-ds402-no-ack", sw = format!("{sw:04X}")))
                .hint(msg!("tbl-ds402-check-status-hint")));
        }
        w.sleep(POLL)?;
    }
    write(ops, "controlword", base as i64)
}

/// `servo jog SPEED`: mode 3, target velocity, acc/dec, then controlword 0x0F.
pub fn jog(ops: &mut dyn ServoOps, speed: i64, p: Profile) -> Result<()> {
    declare(ops, &motion_objects("target_velocity", &p, false))?;
    require_enabled(ops, "jog")?;
    write(ops, "operating_mode", 3)?;
    write(ops, "target_velocity", speed)?;
    if let Some(a) = p.acc {
        write(ops, "profile_acceleration", a)?;
    }
    if let Some(d) = p.dec {
        write(ops, "profile_deceleration", d)?;
    }
    write(ops, "controlword", cw::ENABLE_OPERATION as i64)
}

/// `servo home`: mode 6 (optionally a method), then 0x0F and the 0x1F edge.
pub fn home(ops: &mut dyn ServoOps, method: Option<i64>) -> Result<()> {
    declare(
        ops,
        if method.is_some() {
            &["operating_mode", "homing_method", "controlword"]
        } else {
            &["operating_mode", "controlword"]
        },
    )?;
    require_enabled(ops, "home")?;
    write(ops, "operating_mode", 6)?;
    if let Some(m) = method {
        write(ops, "homing_method", m)?;
    }
    write(ops, "controlword", cw::ENABLE_OPERATION as i64)?;
    write(ops, "controlword", (cw::ENABLE_OPERATION | cw::NEW_SETPOINT) as i64)
}

/// `servo wait target`: polls the statusword until bit 10 (target reached) is set.
/// Returns the final statusword.
pub fn wait_target(ops: &mut dyn ServoOps, w: &Waiter, timeout: Duration) -> Result<u16> {
    let start = w.clock.now();
    loop {
        let sw = statusword(ops)?;
        if sw & 0x08 != 0 {
            return Err(Error::state(msg!("tbl-ds402-fault-while-waiting", sw = format!("{sw:04X}")))
                .hint(msg!("tbl-ds402-fault-while-waiting-hint")));
        }
        let st = State::from_statusword(sw);
        if sw & (1 << 10) != 0 && matches!(st, Some(State::OperationEnabled | State::QuickStopActive)) {
            if sw & (1 << 13) != 0 && read(ops, "operating_mode")? == 6 {
                return Err(Error::state(msg!("tbl-ds402-homing-error", sw = format!("{sw:04X}")))
                    .hint(msg!("tbl-ds402-homing-error-hint")));
            }
            return Ok(sw);
        }
        if w.clock.now() - start >= timeout {
            return Err(Error::new(
                ErrorKind::Timeout,
                match read(ops, "position_actual") {
                    Ok(p) => msg!(
                        "tbl-ds402-target-timeout-at",
                        seconds = format!("{:.3}", timeout.as_secs_f64()),
                        sw = format!("{sw:04X}"),
                        position = p.to_string()
                    ),
                    Err(_) => msg!(
                        "tbl-ds402-target-timeout",
                        seconds = format!("{:.3}", timeout.as_secs_f64()),
                        sw = format!("{sw:04X}")
                    ),
                },
            )
            .hint(msg!("tbl-ds402-target-timeout-hint")));
        }
        w.sleep(POLL)?;
    }
}

/// `servo halt [off]`: sets (or clears) controlword bit 8, keeping the other bits as the
/// drive last saw them, so a move or jog brakes to a stop and resumes on release (CiA 402).
/// Returns the controlword written.
pub fn halt(ops: &mut dyn ServoOps, on: bool) -> Result<u16> {
    declare(ops, &["controlword"])?;
    require_enabled(ops, if on { "halt" } else { "release-halt" })?;
    let cw = read(ops, "controlword")? as u16;
    let new = if on { cw | cw::HALT } else { cw & !cw::HALT };
    write(ops, "controlword", new as i64)?;
    Ok(new)
}

/// `servo save`: 2FF0.01 = 1 (store all parameters).
pub fn save(ops: &mut dyn ServoOps) -> Result<()> {
    declare(ops, &["store_parameters"])?;
    write(ops, "store_parameters", 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statusword_examples_decode_as_the_notes_say() {
        // Public notes' decoded examples.
        let s = decode_status(0x4231, None);
        assert_eq!(s.state, "ready to switch on");
        assert!(s.bits.iter().any(|b| b.0 == 9) && s.bits.iter().any(|b| b.0 == 14));
        let s = decode_status(0x0437, Some(1));
        assert_eq!(s.state, "operation enabled");
        assert!(s.target_reached);
        assert_eq!(decode_status(0xC437, None).bits.iter().filter(|b| b.0 >= 14).count(), 2);
        assert_eq!(decode_status(0xC031, None).state, "ready to switch on");
        assert_eq!(State::from_statusword(0x0008), Some(State::Fault));
        assert_eq!(State::from_statusword(0x0007), Some(State::QuickStopActive));
        for s in [
            State::SwitchOnDisabled,
            State::ReadyToSwitchOn,
            State::SwitchedOn,
            State::OperationEnabled,
            State::QuickStopActive,
            State::FaultReactionActive,
            State::Fault,
        ] {
            assert_eq!(State::from_statusword(s.pattern() | 0x4210), Some(s), "{s:?}");
        }
    }

    #[test]
    fn the_state_machine_follows_cia_402() {
        use State::*;
        assert_eq!(next_state(SwitchOnDisabled, 0, cw::SHUTDOWN), ReadyToSwitchOn);
        assert_eq!(next_state(SwitchOnDisabled, 0, cw::ENABLE_OPERATION), SwitchOnDisabled, "needs shutdown first");
        assert_eq!(next_state(ReadyToSwitchOn, 6, cw::SWITCH_ON), SwitchedOn);
        assert_eq!(next_state(SwitchedOn, 7, cw::ENABLE_OPERATION), OperationEnabled);
        assert_eq!(next_state(ReadyToSwitchOn, 6, cw::ENABLE_OPERATION), OperationEnabled, "manual's one-frame enable");
        assert_eq!(next_state(OperationEnabled, 0x0F, 0x3F), OperationEnabled, "move bits keep the state");
        assert_eq!(next_state(OperationEnabled, 0x0F, cw::QUICK_STOP), QuickStopActive);
        assert_eq!(next_state(QuickStopActive, 0x0B, cw::ENABLE_OPERATION), OperationEnabled);
        assert_eq!(next_state(OperationEnabled, 0x0F, cw::SWITCH_ON), SwitchedOn);
        assert_eq!(next_state(OperationEnabled, 0x0F, cw::DISABLE_VOLTAGE), SwitchOnDisabled);
        assert_eq!(next_state(Fault, 0x06, cw::ENABLE_OPERATION), Fault);
        assert_eq!(next_state(Fault, 0x06, 0x86), SwitchOnDisabled, "rising edge of bit 7");
        assert_eq!(next_state(Fault, 0x86, 0x86), Fault, "no edge");
    }

    #[test]
    fn mode_names() {
        assert_eq!(mode_number("immediate-velocity"), Some(-3));
        assert_eq!(mode_name(mode_number("homing").unwrap()), "homing");
        assert_eq!(mode_number("dance"), None);
    }
}
