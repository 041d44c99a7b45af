//! `servo …`: DS402 helpers for Kinco drives (`servo::ds402`), running through
//! `servo::ops` on the serial driver and the simulator alike.
//!
//! Which drive: `servo [DEVICE] SUBCOMMAND …`. A first word that names an open device
//! (and is not a subcommand) picks it; otherwise the current device if it is a servo,
//! otherwise the only servo device open (the default session's `servo`).
//! Waits run on the session's virtual clock for simulated drives (a stepped clock advances
//! instantly) and on the wall clock for real ones; Ctrl-C interrupts them.

use super::CommandSpec;
use crate::core::literal::parse_option_duration_us;
use crate::core::{Clock, Error, Result};
use crate::output::Outcome;
use crate::servo::ds402::{self, Profile, Waiter};
use crate::servo::frame::{abort_text, func, Frame, FRAME_LEN};
use crate::servo::objects::{self, ObjRef, ServoSpace};
use crate::servo::{units, ServoOps};
use crate::session::Reading;
use crate::shell::{lex, Args, Shell};
use std::time::Duration;

pub const SERVO: CommandSpec = CommandSpec {
    name: "servo",
    aliases: &[],
    usage: "servo [DEVICE] status|enable|disable|fault-reset|quickstop|mode NAME|move abs|rel POS [speed=300rpm] [acc=100rps/s] [dec=100rps/s]|jog SPEED [acc=100rps/s] [dec=100rps/s]|halt [on|off]|home [method=N]|wait target [timeout=5s]|save|params save FILE [group…]|params diff FILE [FILE2]|params diff --with DRIVE|params load FILE [--store]|read OBJ…|encoder [N|auto]|raw BYTES…|sim fault [drive] [CODE] [id=N]|sim fault no-reply|bad-checksum|drop-echo [count=N] [all]|sim fault delay D|sim fault late D|sim fault abort OBJ CODE|sim fault clear|sim switch [home|neg|pos] POS|off|sim pulses freq=HZ count=N [dir=fwd|rev]|sim strict on|off",
    summary: || crate::msg!("summary-servo"),
    subcommands: &[
        "status",
        "enable",
        "disable",
        "fault-reset",
        "quickstop",
        "mode",
        "move",
        "jog",
        "halt",
        "home",
        "wait",
        "save",
        "params",
        "read",
        "encoder",
        "raw",
        "sim",
    ],
    run: servo,
};

/// Default `servo wait target` timeout.
const DEFAULT_WAIT: Duration = Duration::from_secs(10);

fn servo(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words = lex::words(args.text).map_err(|e| e.shift(args.offset))?;
    let (dev, rest) = pick_device(sh, &words).map_err(|e| match e.column {
        Some(_) => e.shift(args.offset),
        None => e.column(args.offset),
    })?;
    sh.session.ready(dev)?;
    let Some(&(col, sub)) = rest.first() else {
        return Err(Error::usage(crate::msg!("shell-servo-needs-subcommand")).hint(SERVO.usage).column(args.offset));
    };
    let rest = &rest[1..];
    let name = sh.session.entries()[dev].name.clone();
    if sub == "params" {
        return params(sh, dev, rest, args.offset, args.offset + col).map_err(|e| e.device(name));
    }
    let simulated = sh.session.entries()[dev].device.info().simulated;
    let clock = if simulated { sh.session.clock.clone() } else { Clock::following() };
    let interrupt = sh.session.interrupt.clone();
    let entry = sh.session.entry(dev);
    let mut access = crate::servo::ops(entry.device.as_mut()).expect("picked a servo");
    let space = ServoSpace::new(access.resolution());
    let ops: &mut dyn ServoOps = &mut access;
    let w = Waiter { clock, interrupt: &interrupt };
    let at = |c: usize| args.offset + c;
    if let (true, Some(&(c, w))) =
        (matches!(sub, "status" | "enable" | "disable" | "fault-reset" | "quickstop"), rest.first())
    {
        return Err(Error::usage(crate::msg!("shell-servo-nothing-after", sub = sub, extra = w))
            .hint(format!("servo {sub}"))
            .column(at(c))
            .device(&name));
    }
    // Every error of a subcommand names the drive (a refusal by the write guard included).
    let r = (|| match sub {
        "status" => status(ops),
        "enable" => {
            let steps = ds402::enable(ops, &w)?;
            let msg = if steps.is_empty() {
                crate::msg!("shell-servo-already-enabled").text
            } else {
                crate::msg!("shell-servo-enabled", steps = steps.join(" → ")).text
            };
            Ok(Outcome::new("servo").text(msg).with("state", "operation enabled").with("steps", steps))
        }
        "disable" => state_outcome(ds402::disable(ops, &w)?),
        "fault-reset" => state_outcome(ds402::fault_reset(ops, &w)?),
        "quickstop" => state_outcome(ds402::quickstop(ops, &w)?),
        "mode" => {
            let Some(&(c, m)) = rest.first() else {
                return Err(Error::usage(crate::msg!("shell-servo-mode-needs")).column(at(col)));
            };
            let n = ds402::mode_number(m).ok_or_else(|| {
                Error::usage(crate::msg!("shell-servo-unknown-mode", mode = m))
                    .column(at(c))
                    .hint(crate::msg!("shell-hint-servo-modes"))
            })?;
            ds402::set_mode(ops, n)?;
            Ok(Outcome::new("servo")
                .text(crate::msg!("shell-servo-mode-set", number = n, name = ds402::mode_name(n)).text)
                .with("mode", n)
                .with("mode_name", ds402::mode_name(n)))
        }
        "move" => move_cmd(ops, &w, &space, rest, args.offset, at(col)),
        "jog" => jog(ops, &space, rest, args.offset, at(col)),
        "halt" => {
            let on = match rest {
                [] | [(_, "on")] => true,
                [(_, "off")] => false,
                _ => {
                    return Err(
                        Error::usage(crate::msg!("shell-usage-line", line = "servo halt [on|off]")).column(at(col))
                    )
                }
            };
            let cw = ds402::halt(ops, on)?;
            let cw_hex = format!("{cw:04X}");
            let text = if on {
                crate::msg!("shell-servo-halted", controlword = cw_hex)
            } else {
                crate::msg!("shell-servo-halt-released", controlword = cw_hex)
            };
            Ok(Outcome::new("servo").text(text.text).with("halt", on).with("controlword", cw))
        }
        "home" => {
            let (_, opts) = lex::options(rest);
            let method = opt_int(&opts, "method", at)?;
            ds402::home(ops, method)?;
            Ok(Outcome::new("servo").text(crate::msg!("shell-servo-homing").text))
        }
        "wait" => wait(ops, &w, rest, args.offset, at(col)),
        "save" => {
            ds402::save(ops)?;
            Ok(Outcome::new("servo").text(crate::msg!("shell-servo-saved").text))
        }
        "read" => read(ops, &space, rest, args.offset, at(col)),
        "encoder" => encoder(ops, rest, args.offset, at(col)),
        "raw" => raw(ops, rest, args.offset, at(col)),
        "sim" => sim(ops, rest, args.offset, at(col)),
        other => Err(Error::usage(crate::msg!("shell-servo-unknown", sub = other)).column(at(col)).hint(SERVO.usage)),
    })();
    r.map(|mut o| {
        if matches!(sub, "enable" | "move" | "jog" | "home") {
            o = o.acted_on(&name, simulated);
        }
        o.device = Some(name.clone());
        o
    })
    .map_err(|e| e.device(name))
}

/// Splits an optional leading device name off the words.
fn pick_device<'a>(sh: &mut Shell, words: &'a [lex::Word<'a>]) -> Result<(usize, &'a [lex::Word<'a>])> {
    // By family, so a drive not connected yet is still found (and tried) by name.
    let is_servo = |sh: &mut Shell, i: usize| sh.session.entries()[i].device.info().family == "servo";
    if let Some(&(col, first)) = words.first() {
        if !SERVO.subcommands.contains(&first) {
            if let Ok(i) = sh.session.index(first) {
                if !is_servo(sh, i) {
                    return Err(Error::usage(crate::msg!("shell-servo-not-servo", name = first)).column(col));
                }
                return Ok((i, &words[1..]));
            }
        }
    }
    if let Ok(i) = sh.session.current_index() {
        if is_servo(sh, i) {
            return Ok((i, words));
        }
    }
    let servos: Vec<usize> = (0..sh.session.entries().len()).filter(|&i| is_servo(sh, i)).collect();
    match servos.as_slice() {
        [i] => Ok((*i, words)),
        [] => Err(Error::usage(crate::msg!("shell-servo-none-open"))
            .hint(crate::msg!("shell-hint-servo-open", port = crate::core::platform::words::port!()))),
        many => {
            let names: Vec<String> = many.iter().map(|&i| sh.session.entries()[i].name.clone()).collect();
            Err(Error::usage(crate::msg!("shell-servo-several")).hint(crate::msg!(
                "shell-hint-servo-several",
                first = names[0].as_str(),
                names = names.join(", ")
            )))
        }
    }
}

fn state_outcome(s: ds402::State) -> Result<Outcome> {
    Ok(Outcome::new("servo").text(s.name().to_string()).with("state", s.name()))
}

fn status(ops: &mut dyn ServoOps) -> Result<Outcome> {
    let st = ds402::status(ops)?;
    let r = ops.resolution().get();
    let pos = ds402::read(ops, "position_actual")?;
    let vel = ds402::read(ops, "velocity_actual")?;
    let rpm = units::dec_to_rpm(vel, r);
    let mode = st.mode.unwrap_or(0);
    let mut rows: Vec<Vec<String>> = vec![
        vec!["state".into(), format!("{} (statusword 16#{:04X})", st.state, st.statusword)],
        vec!["mode".into(), format!("{mode} ({})", ds402::mode_name(mode))],
        vec!["position_actual".into(), format!("{pos} inc")],
        vec!["velocity_actual".into(), format!("{vel} DEC = {} rpm", units::show(rpm))],
    ];
    for (bit, name) in &st.bits {
        rows.push(vec![format!("bit {bit}"), name.to_string()]);
    }
    let bits: Vec<serde_json::Value> = st.bits.iter().map(|(b, n)| serde_json::json!({"bit": b, "name": n})).collect();
    Ok(Outcome::new("servo")
        .table(&["field", "value"], rows)
        .with("state", &st.state)
        .with("statusword", st.statusword)
        .with("bits", bits)
        .with("fault", st.fault)
        .with("target_reached", st.target_reached)
        .with("mode", mode)
        .with("mode_name", ds402::mode_name(mode))
        .with("position_actual", pos)
        .with("velocity_actual", vel)
        .with("velocity_rpm", rpm))
}

/// Parses a value for a table object with the device's units (`300rpm`, `2.5rev`, DEC).
fn value_for(space: &ServoSpace, name: &str, text: &str, col: usize) -> Result<i64> {
    let r = ObjRef::of(objects::named(name));
    // Command arguments follow the unit rule: bare speeds are rpm, bare accelerations rps/s.
    let text = units::command_value(text, objects::named(name).unit);
    space.parse_value(&r, &text).map(|v| v.as_i64()).map_err(|e| {
        let c = e.column.unwrap_or(0);
        let mut e = e.operand(name);
        e.column = Some(col + c);
        e
    })
}

fn opt_int(opts: &[lex::Opt], key: &str, at: impl Fn(usize) -> usize) -> Result<Option<i64>> {
    match opts.iter().find(|o| o.1 == key) {
        None => Ok(None),
        Some(&(c, _, v)) => v
            .parse()
            .map(Some)
            .map_err(|_| Error::usage(crate::msg!("shell-servo-not-whole", key = key, value = v)).column(at(c))),
    }
}

fn profile(space: &ServoSpace, opts: &[lex::Opt], known: &[&str], at: usize, with_speed: bool) -> Result<Profile> {
    let mut p = Profile::default();
    for &(c, k, v) in opts {
        let c = at + c;
        let v_col = c + k.len() + 1;
        match k {
            "speed" if with_speed => p.speed = Some(value_for(space, "profile_velocity", v, v_col)?),
            "acc" => p.acc = Some(value_for(space, "profile_acceleration", v, v_col)?),
            "dec" => p.dec = Some(value_for(space, "profile_deceleration", v, v_col)?),
            _ => {
                return Err(Error::usage(crate::msg!("shell-unknown-option", key = k))
                    .column(c)
                    .hint(crate::msg!("shell-hint-servo-options", options = known.join(", "))))
            }
        }
    }
    Ok(p)
}

fn move_cmd(
    ops: &mut dyn ServoOps,
    w: &Waiter,
    space: &ServoSpace,
    rest: &[lex::Word],
    base: usize,
    col: usize,
) -> Result<Outcome> {
    let (pos, opts) = lex::options(rest);
    let (kind, target) = match pos.as_slice() {
        [(_, k), (c, p)] if *k == "abs" || *k == "rel" => (*k, value_for(space, "target_position", p, base + c)?),
        _ => {
            return Err(Error::usage(crate::msg!(
                "shell-usage-line",
                line = "servo move abs|rel POS [speed=300rpm acc=100rps/s dec=100rps/s]"
            ))
            .column(col))
        }
    };
    let p = profile(space, &opts, &["speed", "acc", "dec"], base, true)?;
    if let (Some(s), Some(&(c, _, _))) = (p.speed, opts.iter().find(|o| o.1 == "speed")) {
        within_max_speed(ops, space, s, base + c)?;
    }
    ds402::move_to(ops, w, kind == "rel", target, p)?;
    let r = space.resolution.get();
    let text = match p.speed {
        Some(s) => {
            let rpm = units::show(units::dec_to_rpm(s, r));
            crate::msg!("shell-servo-move-speed", kind = kind, target = target, rpm = rpm, dec = s).text
        }
        None => crate::msg!("shell-servo-move", kind = kind, target = target).text,
    };
    let mut o = Outcome::new("servo").text(text).with("move", kind).with("target_position", target);
    for (k, v) in [("profile_velocity", p.speed), ("profile_acceleration", p.acc), ("profile_deceleration", p.dec)] {
        if let Some(v) = v {
            o = o.with(k, v);
        }
    }
    Ok(o)
}

fn jog(ops: &mut dyn ServoOps, space: &ServoSpace, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    let (pos, opts) = lex::options(rest);
    let [(c, s)] = pos.as_slice() else {
        return Err(Error::usage(crate::msg!("shell-servo-jog-usage")).column(col));
    };
    let speed = value_for(space, "target_velocity", s, base + c)?;
    within_max_speed(ops, space, speed, base + c)?;
    let p = profile(space, &opts, &["acc", "dec"], base, false)?;
    ds402::jog(ops, speed, p)?;
    let rpm = units::dec_to_rpm(speed, space.resolution.get());
    Ok(Outcome::new("servo")
        .text(crate::msg!("shell-servo-jogging", rpm = units::show(rpm), dec = speed).text)
        .with("target_velocity", speed)
        .with("rpm", rpm))
}

/// Refuses a speed (DEC) above the drive's configured maximum speed, object 6080.00
/// `max_speed` (Kinco public notes, object table: "max speed", 16 bits; read as rpm, the unit
/// the drive's own speed settings use, 3000 on the simulated drive). A drive that does not
/// answer for the object, or holds 0 there, sets no limit here.
fn within_max_speed(ops: &mut dyn ServoOps, space: &ServoSpace, speed: i64, col: usize) -> Result<()> {
    let Ok(max) = ops.read_raw(ObjRef::of(objects::named("max_speed"))) else { return Ok(()) };
    let max_rpm = f64::from(max & 0xFFFF);
    let rpm = units::dec_to_rpm(speed, space.resolution.get());
    if max_rpm > 0.0 && rpm.abs() > max_rpm {
        return Err(Error::new(
            crate::core::ErrorKind::Range,
            crate::msg!("shell-servo-over-max", rpm = units::show(rpm), max = max_rpm.to_string()),
        )
        .operand("max_speed")
        .column(col)
        .hint(crate::msg!("shell-hint-servo-max", max = max_rpm.to_string())));
    }
    Ok(())
}

fn wait(ops: &mut dyn ServoOps, w: &Waiter, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    let (pos, opts) = lex::options(rest);
    if !matches!(pos.as_slice(), [(_, "target")]) {
        return Err(Error::usage(crate::msg!("shell-usage-line", line = "servo wait target [timeout=5s]")).column(col));
    }
    let mut timeout = DEFAULT_WAIT;
    for &(c, k, v) in &opts {
        if k != "timeout" {
            return Err(Error::usage(crate::msg!("shell-unknown-option", key = k))
                .column(base + c)
                .hint(crate::msg!("shell-hint-servo-wait")));
        }
        let us = parse_option_duration_us(v).map_err(|m| Error::usage(m).column(base + c + k.len() + 1))?;
        timeout = Duration::from_micros(us.max(0) as u64);
    }
    let start = w.clock.now();
    let sw = ds402::wait_target(ops, w, timeout)?;
    let took = w.clock.now() - start;
    let pos = ds402::read(ops, "position_actual")?;
    Ok(Outcome::new("servo")
        .text(
            crate::msg!("shell-servo-target-reached", seconds = format!("{:.3}", took.as_secs_f64()), position = pos)
                .text,
        )
        .with("statusword", sw)
        .with("position_actual", pos)
        .with("waited_s", took.as_secs_f64()))
}

/// `servo read OBJ…`: raw value plus engineering units. JSON: `values` as `get` gives,
/// plus `objects: [{operand, index, value, unit, eng, eng_unit}]`.
fn read(ops: &mut dyn ServoOps, space: &ServoSpace, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    if rest.is_empty() {
        return Err(Error::usage(crate::msg!("shell-servo-read-needs")).column(col));
    }
    let r = space.resolution.get();
    let mut rows = Vec::new();
    let mut values = Vec::new();
    let mut objs = Vec::new();
    for &(c, text) in rest {
        let o = objects::parse(text).map_err(|e| {
            let e = if e.column.is_none() { e.column(0) } else { e };
            e.shift(base + c)
        })?;
        let v = o.dtype.decode(ops.read_raw(o)?);
        let unit = o.object().map(|x| x.unit).unwrap_or(units::Unit::None);
        let eng = units::engineering(unit, v.as_i64(), r);
        rows.push(vec![
            o.name(),
            o.address(),
            v.to_string(),
            unit.raw_label().to_string(),
            eng.map(|(e, u)| format!("{} {u}", units::show(e))).unwrap_or_default(),
        ]);
        objs.push(serde_json::json!({
            "operand": o.name(), "index": o.address(), "value": v, "unit": unit.raw_label(),
            "eng": eng.map(|e| e.0), "eng_unit": eng.map(|e| e.1),
        }));
        values.push(Reading::plain(o.name(), v, o.dtype));
    }
    let mut out = Outcome::new("servo")
        .table(&crate::output::headings(crate::msg!("shell-servo-read-columns")), rows)
        .with("objects", objs)
        .with("encoder_resolution", r);
    out.values = values;
    Ok(out)
}

fn encoder(ops: &mut dyn ServoOps, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    let res = ops.resolution();
    match rest {
        [] => {}
        [(_, "auto")] | [(_, "read")] => {
            ops.read_resolution()?;
        }
        [(c, v)] => res.set(units::parse_resolution(v).map_err(|m| Error::usage(m).column(base + c))?),
        _ => return Err(Error::usage(crate::msg!("shell-usage-line", line = "servo encoder [N|auto]")).column(col)),
    }
    let r = res.get();
    let text = crate::msg!("shell-servo-encoder", resolution = r.to_string()).text;
    Ok(Outcome::new("servo").text(text).with("encoder_resolution", r))
}

/// `servo raw 01 40 41 60 00 00 00 00 00 [CS]`: 9 bytes get their checksum appended;
/// 10 are sent as typed (to check a hand-computed checksum).
fn raw(ops: &mut dyn ServoOps, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    let mut bytes = Vec::new();
    for &(c, w) in rest {
        let h = w.trim_start_matches("0x").trim_start_matches("16#");
        let b = u8::from_str_radix(h, 16)
            .map_err(|_| Error::usage(crate::msg!("shell-servo-not-hex-byte", text = w)).column(base + c))?;
        bytes.push(b);
    }
    let frame: [u8; FRAME_LEN] = match bytes.len() {
        9 => {
            let mut f = [0u8; FRAME_LEN];
            f[..9].copy_from_slice(&bytes);
            f[9] = crate::servo::frame::checksum(&bytes);
            f
        }
        10 => bytes.try_into().expect("10 bytes"),
        n => {
            return Err(Error::usage(crate::msg!("shell-servo-frame-length", count = n))
                .column(col)
                .hint(crate::msg!("shell-hint-servo-raw")))
        }
    };
    let reply = ops.raw_frame(frame)?;
    let hex = crate::core::trace::hex_bytes;
    let meaning = match Frame::from_bytes(&reply) {
        Err(e) => format!("reply has a {e}"),
        Ok(f) if f.func == func::ERROR => {
            format!("0x80 error: abort code 16#{:08X} — {}", f.data, abort_text(f.data))
        }
        Ok(f) if f.func == func::WRITE_OK => format!("write to {} acknowledged", f.object()),
        Ok(f) => raw_value(&f),
    };
    let mut o = Outcome::new("servo")
        .text(format!("→ {}\n← {}  {meaning}", hex(&frame), hex(&reply)))
        .with("sent", hex(&frame))
        .with("reply", hex(&reply))
        .with("meaning", &meaning);
    if let Ok(f) = Frame::from_bytes(&reply) {
        if f.func == func::ERROR {
            o = o.with("abort_code", f.data).with("abort", abort_text(f.data));
        }
    }
    Ok(o)
}

/// A read reply's value at the object's width and signedness (the reply's length code for
/// objects outside the table): a sign-extended statusword shows as 16 bits, not 32.
fn raw_value(f: &Frame) -> String {
    use crate::core::DataType;
    let unsized_type = match f.func {
        func::READ_1 => DataType::Byte,
        func::READ_2 => DataType::Word,
        func::READ_4 => DataType::DWord,
        other => return format!("{} answered with function code {other:02X}, data 16#{:08X}", f.object(), f.data),
    };
    let (dtype, name) = match objects::lookup(f.index, f.sub) {
        Some(o) => (o.dtype, format!("{} {}", f.object(), o.name)),
        None => (unsized_type, f.object()),
    };
    let bits = dtype.bits().min(unsized_type.bits());
    let raw = f.data & (u32::MAX >> (32 - bits));
    format!("{name} = {} (16#{raw:0w$X}, {})", dtype.decode(raw), objects::short_type(dtype), w = bits as usize / 4)
}

/// Simulator controls (`servo::sim::control`'s language): on an in-process drive
/// (`sim-servo:`) they apply directly; on a `kinco:` port served by `plcsh sim serve` they go
/// to its control socket (`LINK.ctl`, or `control=` in the URL).
fn sim(ops: &mut dyn ServoOps, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    use crate::servo::sim::control;
    let id = ops.drive_id();
    let words: Vec<(usize, &str)> = rest.iter().map(|&(c, w)| (base + c, w)).collect();
    if words.is_empty() {
        return Err(Error::usage(crate::msg!("shell-servo-sim-needs")).column(col).hint(control::USAGE));
    }
    let req = control::parse(&words)?;
    let (text, data) = if let Some(line) = ops.simulator() {
        let mut l = line.lock().unwrap_or_else(|p| p.into_inner());
        control::apply(&mut l, &req, Some(id))?
    } else if let Some(path) = ops.sim_control() {
        let mut line = rest.iter().map(|w| w.1).collect::<Vec<_>>().join(" ");
        if req.id.is_none() {
            line = format!("id={id} {line}");
        }
        control::send(&path, &line)?
    } else {
        return Err(Error::unsupported(crate::msg!("shell-servo-sim-needs-simulator"))
            .column(col)
            .hint(crate::msg!("shell-hint-servo-sim-control")));
    };
    let mut o = Outcome::new("servo").text(text);
    if let serde_json::Value::Object(m) = data {
        for (k, v) in m {
            if k != "ok" && k != "text" {
                o = o.with(&k, v);
            }
        }
    }
    Ok(o)
}

/// The difference of two parameter sets as `servo params diff` shows it.
fn diff_outcome(
    left: &crate::servo::params::ParamSet,
    right: &crate::servo::params::ParamSet,
    left_label: &str,
    right_label: &str,
) -> Outcome {
    let d = crate::servo::params::diff(left, right);
    let rows: Vec<Vec<String>> =
        d.iter().map(|x| vec![x.name.clone(), x.object.clone(), x.left.shown.clone(), x.right.shown.clone()]).collect();
    let o = Outcome::new("servo");
    let o = if rows.is_empty() {
        o.text(crate::msg!("servo-params-same"))
    } else {
        o.table(&["parameter", "object", left_label, right_label], rows)
    };
    o.with("left", left_label).with("right", right_label).with("count", d.len()).with("differences", &d)
}

fn entry_name(sh: &Shell, dev: usize) -> String {
    sh.session.entries()[dev].name.clone()
}

/// `servo params save FILE [group…]`, `servo params diff FILE [FILE2]`, `servo params diff
/// --with DRIVE` (this drive against another open one), `servo params load
/// FILE [--store]`: parameter sets ([`crate::servo::params`]; docs/servo.md "Parameter sets").
fn params(sh: &mut Shell, dev: usize, rest: &[lex::Word], base: usize, col: usize) -> Result<Outcome> {
    use crate::servo::params::{self, ParamSet};
    let usage = || Error::usage(crate::msg!("servo-params-usage")).column(col);
    let words: Vec<(usize, String)> = rest.iter().map(|&(c, w)| (base + c, lex::unquote(w).into_owned())).collect();
    let Some((verb, files)) = words.split_first() else { return Err(usage()) };
    let read_file = |sh: &Shell, (c, f): &(usize, String)| -> Result<ParamSet> {
        sh.session.check_read(f).map_err(|e| e.column(*c))?;
        let text = std::fs::read_to_string(f)
            .map_err(|e| Error::io(crate::msg!("servo-params-cannot-read", file = f.as_str())).cause(e).column(*c))?;
        ParamSet::parse(&text, f).map_err(|e| e.column(*c))
    };
    let entry = &sh.session.entries()[dev];
    let identity = params::Identity {
        kind: params::DRIVE_TYPE.to_string(),
        model: entry.device.info().model.clone(),
        id: 0,
        url: entry.url.clone(),
        saved: params::utc_now(),
        plcsh: env!("CARGO_PKG_VERSION").to_string(),
        encoder_resolution: 0,
        groups: Vec::new(),
    };
    let simulated = entry.device.info().simulated;
    match (verb.1.as_str(), files) {
        ("save", [(c, file), groups @ ..]) => {
            for (gc, g) in groups {
                params::check_group(g).map_err(|e| e.column(*gc))?;
            }
            crate::shell::files::check_write(&sh.write_rule, file).map_err(|e| e.column(*c))?;
            let groups: Vec<&str> = groups.iter().map(|g| g.1.as_str()).collect();
            let set = {
                let mut access = crate::servo::ops(sh.session.entry(dev).device.as_mut()).expect("picked a servo");
                let id = ServoOps::drive_id(&access);
                params::read_set(&mut access, &groups, params::Identity { id, ..identity })?
            };
            crate::core::durable::write_atomic(std::path::Path::new(file), set.to_toml().as_bytes())?;
            let refused = set.parameters.iter().filter(|e| e.value.is_none()).count();
            Ok(Outcome::new("servo")
                .text(crate::msg!(
                    "servo-params-saved",
                    count = set.parameters.len() as u64,
                    file = file.as_str(),
                    refused = refused as u64
                ))
                .with("file", file)
                .with("drive", &set.drive)
                .with("parameters", &set.parameters))
        }
        ("diff", [(_, with), (dc, other)]) if with == "--with" => {
            // This drive against another open drive, read now, every parameter of both.
            let other_dev = sh.session.index(other).map_err(|e| e.column(*dc))?;
            sh.session.ready(other_dev)?;
            let mut sets = Vec::new();
            for (i, label) in [(dev, entry_name(sh, dev)), (other_dev, other.clone())] {
                let e = &sh.session.entries()[i];
                let identity =
                    params::Identity { model: e.device.info().model.clone(), url: e.url.clone(), ..identity.clone() };
                let Some(mut access) = crate::servo::ops(sh.session.entry(i).device.as_mut()) else {
                    return Err(Error::unsupported(crate::msg!("data-not-a-drive", device = label.as_str()))
                        .device(label)
                        .column(*dc));
                };
                let id = ServoOps::drive_id(&access);
                sets.push((params::read_set(&mut access, &[], params::Identity { id, ..identity })?, label));
            }
            let (right, right_label) = sets.pop().expect("two drives");
            let (left, left_label) = sets.pop().expect("two drives");
            Ok(diff_outcome(&left, &right, &left_label, &right_label))
        }
        ("diff", [a]) | ("diff", [a, _]) => {
            let left = read_file(sh, a)?;
            let (right, right_label) = match files {
                [_, b] => (read_file(sh, b)?, b.1.clone()),
                _ => {
                    let mut access = crate::servo::ops(sh.session.entry(dev).device.as_mut()).expect("picked a servo");
                    let id = ServoOps::drive_id(&access);
                    let groups: Vec<&str> = left.drive.groups.iter().map(|g| g.as_str()).collect();
                    (params::read_set(&mut access, &groups, params::Identity { id, ..identity })?, "drive".to_string())
                }
            };
            Ok(diff_outcome(&left, &right, &a.1, &right_label))
        }
        ("load", [f]) | ("load", [f, (_, _)]) => {
            let store = match files {
                [_, (sc, s)] if s != "--store" => {
                    return Err(Error::usage(crate::msg!("servo-params-usage")).column(*sc))
                }
                [_, _] => true,
                _ => false,
            };
            let set = read_file(sh, f)?;
            let mut access = crate::servo::ops(sh.session.entry(dev).device.as_mut()).expect("picked a servo");
            let done = params::load(&mut access, &set, store)?;
            let mut text: String = if store {
                crate::msg!(
                    "servo-params-loaded-stored",
                    written = done.written.len() as u64,
                    unchanged = done.unchanged as u64
                )
            } else {
                crate::msg!(
                    "servo-params-loaded",
                    written = done.written.len() as u64,
                    unchanged = done.unchanged as u64
                )
            }
            .into();
            for w in &done.written {
                text.push_str(&format!("\n  {} ({}) {} → {}", w.name, w.object, w.old, w.new));
            }
            let name = sh.session.entries()[dev].name.clone();
            Ok(Outcome::new("servo")
                .text(text)
                .with("file", &f.1)
                .with("written", &done.written)
                .with("unchanged", done.unchanged)
                .with("skipped", &done.skipped)
                .with("stored", done.stored)
                .acted_on(&name, simulated))
        }
        _ => Err(usage()),
    }
}
