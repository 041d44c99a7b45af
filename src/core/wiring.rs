//! The signal model of virtual wiring between simulated devices: a K2's pulse output to a
//! drive's pulse input, the drive's encoder output to the K2's counter inputs, outputs to
//! inputs (loopback), a drive's digital outputs and the switches on its axis to PLC inputs.
//!
//! It lives in the core, below the families, because it is what they share: the host (the K2
//! simulator, `k2::sim::wired`) and its peers (the drive simulator, `servo::sim::wired`) both
//! speak it without naming each other. Opening the wired devices in a session (`sim wire`,
//! benches) is the session layer's part, `crate::wiring`.
//!
//! Wiring is data, not special cases (design guide, "Simulated devices can be wired"): each
//! family names its terminals and says what *signal* each one speaks ([`Role`]): a pulse
//! output and a pulse input speak [`PulseTrain`]s, an encoder output speaks a position
//! plan ([`Piece`]s of constant acceleration) that a quadrature counter input turns into
//! A/B edges, a digital output and input speak levels. A [`Wire`] joins two roles that
//! speak the same signal; [`connect`] checks that and refuses the rest with the pairs that
//! work.
//!
//! Coupling is analytic in virtual time. The device that counts (the K2) is the *host*: when
//! it advances, it asks its peers (the drives, through [`Peer`]) for their signals over the
//! interval and advances piecewise, one piece per stretch where every wired signal is
//! described by one formula (an encoder following a constant-acceleration stretch of the
//! motion, a pulse train's stretch, a steady level). A cruise at 200 kHz for an hour is one
//! piece, and so is a whole ramp; only the ends of motion segments and level changes cost a
//! step. Pulse outputs are pushed to the
//! drive the moment they start or stop (`PLS`, `PSTOP`), so the drive follows them from
//! their first pulse.
//!
//! Exactness: an encoder output is its position, not a wave at some rate. Each piece hands
//! the counter the motion itself (`x(t)` in 4× counts, `x = p · 4 · lines / resolution`,
//! constant acceleration within the piece, moving one way: a piece ends where the motion
//! stops or reverses), and the A/B state is a function of `x` ([`Track`]):
//! the edges between any two instants follow from the position at those instants, so
//! counts never drift, ramps included, and do not depend on where pieces or polls fall.
//! At 1× a decoder counts one edge per period (A's edge while B is low: A rising up, A
//! falling down), `⌊x / 4⌋`; at 4× every state change, `⌊x⌋`. A pulse output wired to an
//! input carries the train's pulses exactly (whole-ns cycles, the count put out), delayed
//! by the wire's delay whether or not the output still runs then.

use crate::core::signal::{PulseTrain, Track, Train};
use crate::core::{Error, Result};
use crate::msg;

/// One stretch of a planned motion: from `t0` for `dur` seconds (infinite for the last),
/// starting at position `p0` (increments) with velocity `v0` and constant acceleration `a`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    pub t0: f64,
    pub dur: f64,
    pub p0: f64,
    pub v0: f64,
    pub a: f64,
}

impl Piece {
    pub fn at(&self, t: f64) -> f64 {
        let dt = (t - self.t0).clamp(0.0, self.dur);
        self.p0 + self.v0 * dt + 0.5 * self.a * dt * dt
    }
}

/// A drive's digital output, wired to a PLC input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DriveOut {
    /// Statusword bit 10 (target reached / at rest).
    TargetReached,
    /// In Fault (statusword bit 3).
    Fault,
    /// Operation enabled (power stage on).
    Enabled,
}

/// A switch on a drive's axis, actuated by the drive's position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Switch {
    /// Active at and above the position (the drive's home input too).
    Home(f64),
    /// Active at and above the position (the drive's positive limit input too).
    PosLimit(f64),
    /// Active at and below the position (the drive's negative limit input too).
    NegLimit(f64),
}

impl Switch {
    pub fn active(&self, p: f64) -> bool {
        match *self {
            Switch::Home(x) | Switch::PosLimit(x) => p >= x,
            Switch::NegLimit(x) => p <= x,
        }
    }
    pub fn position(&self) -> f64 {
        match *self {
            Switch::Home(x) | Switch::PosLimit(x) | Switch::NegLimit(x) => x,
        }
    }
    fn name(&self) -> &'static str {
        match self {
            Switch::Home(_) => "home",
            Switch::PosLimit(_) => "limit+",
            Switch::NegLimit(_) => "limit-",
        }
    }
}

/// An input or output bit of a PLC: (byte, bit).
pub type Bit = (u32, u8);

/// What a terminal speaks, as its family resolved it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Role {
    /// A pulse output (a PTO channel) with its direction output.
    PulseOut { channel: u8, out: Bit, dir: Bit },
    /// A plain digital output.
    DigitalOut(Bit),
    /// A digital input.
    DigitalIn(Bit),
    /// Two inputs a counter reads as A/B.
    QuadIn { a: Bit, b: Bit },
    /// A drive's pulse input (mode -4).
    PulseIn,
    /// A drive's encoder output (A/B).
    Encoder,
    /// A drive's digital output.
    DriveOut(DriveOut),
    /// A switch on a drive's axis.
    Switch(Switch),
}

/// One end of a wire as written: `DEVICE:TERMINAL[,TERMINAL]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Endpoint {
    pub device: String,
    pub terminal: String,
}

impl std::fmt::Display for Endpoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}", self.device, self.terminal)
    }
}

/// Parses `plc:Q0.0`, `servo:encoder`, `plc:I0.0,I0.1`, `servo:home@20000`.
pub fn endpoint(text: &str) -> Result<Endpoint> {
    let t = text.trim();
    let (d, term) = t.split_once(':').ok_or_else(|| {
        Error::usage(msg!("wire-not-terminal", text = t))
            .hint("e.g. plc:Q0.0, servo:pulse, servo:encoder, plc:I0.0,I0.1, servo:home@20000")
    })?;
    if d.is_empty() || term.is_empty() {
        return Err(Error::usage(msg!("wire-no-device-or-terminal", text = t)).hint("e.g. plc:Q0.0"));
    }
    Ok(Endpoint { device: d.to_string(), terminal: term.to_string() })
}

/// A wire declaration: `FROM -> TO [lines=N] [delay=D]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Decl {
    pub from: Endpoint,
    pub to: Endpoint,
    /// Encoder output lines per revolution (A/B periods per turn), `None`: resolution / 4.
    pub lines: Option<u32>,
    /// Loopback delay, ns.
    pub delay_ns: u64,
}

impl std::fmt::Display for Decl {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} -> {}", self.from, self.to)?;
        if let Some(l) = self.lines {
            write!(f, " lines={l}")?;
        }
        if self.delay_ns > 0 {
            write!(f, " delay={}us", self.delay_ns / 1000)?;
        }
        Ok(())
    }
}

/// Parses `plc:Q0.0 -> servo:pulse`, `servo:encoder -> plc:I0.1,I0.0 lines=1250`,
/// `plc:Q0.1 -> plc:I0.3 delay=2ms`.
pub fn parse(text: &str) -> Result<Decl> {
    let (from, rest) = text
        .split_once("->")
        .ok_or_else(|| Error::usage(msg!("wire-not-wire", text = text.trim())).hint(msg!("wire-not-wire-hint")))?;
    let mut words = rest.split_whitespace();
    let to = words.next().ok_or_else(|| Error::usage(msg!("wire-no-destination")))?;
    let mut d = Decl { from: endpoint(from)?, to: endpoint(to)?, lines: None, delay_ns: 0 };
    for w in words {
        let (k, v) = w.split_once('=').ok_or_else(|| {
            Error::usage(msg!("wire-options-key-value", word = w)).hint(msg!("wire-options-short-hint"))
        })?;
        match k {
            "lines" => {
                let n: u32 = v
                    .parse()
                    .ok()
                    .filter(|n| *n > 0)
                    .ok_or_else(|| Error::usage(msg!("wire-lines-positive", value = v)))?;
                d.lines = Some(n);
            }
            "delay" => {
                let us = crate::core::literal::parse_option_duration_us(v)
                    .map_err(|m| Error::usage(format!("delay={v}: {m}")).hint("e.g. delay=2ms"))?;
                if us < 0 {
                    return Err(Error::usage(msg!("wire-delay-negative", value = v)).hint("e.g. delay=2ms"));
                }
                // A wire's delay is held in ns: refused past u64, not wrapped.
                d.delay_ns = (us as u64).checked_mul(1000).ok_or_else(|| {
                    Error::usage(msg!("wire-delay-too-long", value = v, max = (u64::MAX / 1000).to_string()))
                })?;
            }
            _ => return Err(Error::usage(msg!("wire-no-option", key = k)).hint(msg!("wire-options-hint"))),
        }
    }
    Ok(d)
}

/// A drive (or any device the host counts from), reached while the host advances.
pub trait Peer: Send {
    /// Connects a pulse signal to the pulse input, replacing what was there, from `t`.
    fn pulses(&mut self, train: PulseTrain, t: f64);
    /// Brings the peer to `t` and returns its position plan from `t` on (the last piece open).
    fn motion(&mut self, t: f64) -> Vec<Piece>;
    /// Identifies the current plan: it changes whenever the plan is replaced.
    fn plan_id(&mut self, t: f64) -> u64;
    /// The time of the peer's next own event after `t` (a limit, a fault), if any.
    fn next_event(&mut self, t: f64) -> Option<f64>;
    /// A digital output's level at `t` (the peer is brought to `t`).
    fn output(&mut self, what: DriveOut, t: f64) -> bool;
    /// Increments per revolution (the encoder resolution).
    fn resolution(&mut self) -> f64;
    /// Puts a switch on the peer's own inputs (`None` takes it away).
    fn set_switch(&mut self, s: Switch, on: bool);
    /// Checks that a pulse train can reach the pulse input as a step/direction signal.
    fn check_pulse_input(&mut self) -> std::result::Result<(), String> {
        Ok(())
    }
}

/// Makes the peer of a new wire when the host does not know it yet.
pub type MakePeer = Box<dyn FnOnce() -> Box<dyn Peer>>;

/// What a wire joins, resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// Host pulse output → peer pulse input.
    Pulses { channel: u8, dir: Bit },
    /// Peer encoder → host counter inputs.
    Encoder { a: Bit, b: Bit, lines: Option<u32> },
    /// Peer digital output → host input.
    Output { what: DriveOut, pin: Bit },
    /// Peer axis switch → host input (and the peer's own input).
    Switch { switch: Switch, pin: Bit },
    /// Host digital output → host input, `delay_ns` later.
    Loop { from: Bit, to: Bit, delay_ns: u64 },
    /// Host pulse output → host input (the pulses, `delay_ns` later).
    PulseLoop { channel: u8, to: Bit, delay_ns: u64 },
}

/// Joins two resolved terminals, or says which pairs work.
pub fn connect(d: &Decl, from: Role, to: Role) -> Result<Kind> {
    let k = match (from, to) {
        (Role::PulseOut { channel, dir, .. }, Role::PulseIn) => Kind::Pulses { channel, dir },
        (Role::Encoder, Role::QuadIn { a, b }) => Kind::Encoder { a, b, lines: d.lines },
        (Role::DriveOut(what), Role::DigitalIn(pin)) => Kind::Output { what, pin },
        (Role::Switch(switch), Role::DigitalIn(pin)) => Kind::Switch { switch, pin },
        (Role::DigitalOut(from), Role::DigitalIn(to)) => Kind::Loop { from, to, delay_ns: d.delay_ns },
        (Role::PulseOut { channel, .. }, Role::DigitalIn(to)) => Kind::PulseLoop { channel, to, delay_ns: d.delay_ns },
        _ => {
            return Err(Error::usage(msg!("wire-cannot-join", from = d.from.to_string(), to = d.to.to_string()))
                .hint(msg!("wire-cannot-join-hint")))
        }
    };
    if d.lines.is_some() && !matches!(k, Kind::Encoder { .. }) {
        return Err(Error::usage(msg!("wire-lines-encoder-only")));
    }
    if d.delay_ns > 0 && !matches!(k, Kind::Loop { .. } | Kind::PulseLoop { .. }) {
        return Err(Error::usage(msg!("wire-delay-loop-only")));
    }
    Ok(k)
}

/// Resolves a drive's terminal: `pulse`, `encoder`, `target_reached`, `fault`, `enabled`,
/// `home@POS`, `limit+@POS`, `limit-@POS` (positions in increments).
pub fn drive_terminal(ep: &Endpoint) -> Result<Role> {
    let t = ep.terminal.to_ascii_lowercase();
    let sw = |text: &str| -> Result<f64> {
        text.trim().parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
            Error::usage(msg!("wire-not-position", terminal = ep.to_string(), text = text))
                .hint("e.g. servo:home@20000")
        })
    };
    Ok(match t.split_once('@') {
        Some(("home", p)) => Role::Switch(Switch::Home(sw(p)?)),
        Some(("limit+" | "pos", p)) => Role::Switch(Switch::PosLimit(sw(p)?)),
        Some(("limit-" | "neg", p)) => Role::Switch(Switch::NegLimit(sw(p)?)),
        Some(_) => return Err(Error::usage(msg!("wire-only-switches-at", terminal = ep.to_string()))),
        None => match t.as_str() {
            "pulse" | "pulses" => Role::PulseIn,
            "encoder" => Role::Encoder,
            "target_reached" | "target" => Role::DriveOut(DriveOut::TargetReached),
            "fault" => Role::DriveOut(DriveOut::Fault),
            "enabled" => Role::DriveOut(DriveOut::Enabled),
            _ => {
                return Err(Error::usage(msg!(
                    "wire-unknown-drive-terminal",
                    name = ep.terminal.as_str(),
                    terminal = ep.to_string()
                ))
                .hint(msg!("wire-drive-terminals-hint")))
            }
        },
    })
}

/// One wire, resolved, with what it keeps between pieces.
#[derive(Clone, Debug)]
pub struct Wire {
    pub decl: Decl,
    pub kind: Kind,
    /// Index of the peer in [`Harness::peers`] (wires between host terminals have none).
    pub peer: Option<usize>,
    pub state: WireState,
}

/// One stretch of pulses a pulse output put out, as a wire carries them to an input
/// (delayed): `count` cycles of `cycle_ns`, the first rising at `first_ns`.
pub type LoopSeg = Train;

/// What a wire carries over between pieces (saved whole in snapshots).
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct WireState {
    /// Encoder: the signal of the current piece (its A/B state follows from it).
    pub track: Option<Track>,
    /// Encoder: added to the drive's position (4× counts) so the output stays where it was
    /// when the drive re-references its position (homing): an incremental encoder's
    /// outputs change only when the shaft turns.
    #[serde(with = "crate::core::float_serde")]
    pub offset: f64,
    /// The current piece is valid until this time (ns) while the peer's plan is `plan`.
    pub until_ns: u64,
    pub plan: u64,
    /// Pulses: the train last pushed (start ns, total), so a change is pushed once.
    pub pushed: Option<(u64, u64)>,
    pub train: PulseTrain,
    /// Loopback: level changes waiting for their delay (time ns, level).
    pub pending: std::collections::VecDeque<(u64, bool)>,
    pub last_level: Option<bool>,
    /// Pulse loop: the pulses put out and still to arrive, oldest first, and the one on
    /// the input now.
    pub segs: std::collections::VecDeque<LoopSeg>,
    pub playing: Option<LoopSeg>,
}

/// The wiring a host holds: its peers (by device name) and its wires.
pub struct Harness {
    pub peers: Vec<(String, Box<dyn Peer>)>,
    pub wires: Vec<Wire>,
}

impl std::fmt::Debug for Harness {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Harness").field("wires", &self.wires).finish()
    }
}

impl Harness {
    pub fn new() -> Harness {
        Harness { peers: Vec::new(), wires: Vec::new() }
    }

    /// The peer named `name`, adding it with `make` when new.
    pub fn peer_index(&mut self, name: &str, make: impl FnOnce() -> Box<dyn Peer>) -> usize {
        match self.peers.iter().position(|(n, _)| n == name) {
            Some(i) => i,
            None => {
                self.peers.push((name.to_string(), make()));
                self.peers.len() - 1
            }
        }
    }

    /// Describes a wire for `sim wires`.
    pub fn describe(w: &Wire) -> String {
        let what = match w.kind {
            Kind::Pulses { channel, .. } => msg!("wire-describe-pulses", channel = channel),
            Kind::Encoder { lines, .. } => match lines {
                Some(l) => msg!("wire-describe-encoder-lines", lines = l),
                None => msg!("wire-describe-encoder"),
            },
            Kind::Output { what, .. } => msg!(
                "wire-describe-drive-output",
                output = match what {
                    DriveOut::TargetReached => "target-reached",
                    DriveOut::Fault => "fault",
                    DriveOut::Enabled => "enabled",
                }
            ),
            Kind::Switch { switch, .. } => {
                msg!("wire-describe-switch", switch = switch.name(), position = switch.position().to_string())
            }
            Kind::Loop { delay_ns, .. } => msg!("wire-describe-loop", delay = delay_ns / 1000),
            Kind::PulseLoop { channel, delay_ns, .. } => {
                msg!("wire-describe-pulse-loop", channel = channel, delay = delay_ns / 1000)
            }
        };

        format!("{}  ({what})", w.decl)
    }
}

impl Default for Harness {
    fn default() -> Self {
        Harness::new()
    }
}

/// Rounds a count position that is within float noise of a whole count onto it.
pub fn snap(x: f64) -> f64 {
    let r = x.round();
    if (x - r).abs() < 1e-6 {
        r
    } else {
        x
    }
}

/// The first time at or after `t` a position plan reaches `x` (`None` if it never does;
/// a piece at rest on `x` does not reach it again).
pub fn first_reach(pieces: &[Piece], x: f64, t: f64) -> Option<f64> {
    for p in pieces {
        let (t0, dur) = (p.t0.max(t), p.dur);
        let end = p.t0 + dur;
        if end < t0 {
            continue;
        }
        let (c, b, a) = (p.at(t0) - x, p.v0 + p.a * (t0 - p.t0), 0.5 * p.a);
        if c == 0.0 {
            if b == 0.0 && a == 0.0 {
                // At rest on `x`: it stays there, nothing is crossed.
                continue;
            }
            return Some(t0);
        }
        let roots: Vec<f64> = if a == 0.0 {
            if b == 0.0 {
                vec![]
            } else {
                vec![-c / b]
            }
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc < 0.0 {
                vec![]
            } else {
                let r = disc.sqrt();
                vec![(-b - r) / (2.0 * a), (-b + r) / (2.0 * a)]
            }
        };
        if let Some(tau) = roots.into_iter().filter(|tau| *tau >= 0.0 && t0 + *tau <= end).min_by(|a, b| a.total_cmp(b))
        {
            return Some(t0 + tau);
        }
    }
    None
}

/// The pulses of `train` that are out by `t`: the train cut there (a stopped output).
pub fn cut(train: &PulseTrain, t: f64) -> PulseTrain {
    let mut out = PulseTrain::new();
    for s in train.segments() {
        let n = s.pulses_at(t);
        if n > 0 {
            let _ = out.push(s.start, s.freq, n, s.dir);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wire_declarations_parse_and_refuse() {
        let d = parse("servo:encoder -> plc:I0.1,I0.0 lines=1250").unwrap();
        assert_eq!(d.from.device, "servo");
        assert_eq!(d.to.terminal, "I0.1,I0.0");
        assert_eq!(d.lines, Some(1250));
        assert_eq!(d.to_string(), "servo:encoder -> plc:I0.1,I0.0 lines=1250");
        let d = parse("plc:Q0.1 -> plc:I0.3 delay=2ms").unwrap();
        assert_eq!(d.delay_ns, 2_000_000);
        let e = parse("plc:Q0.1 -> plc:I0.3 delay=18446744073709552us").unwrap_err();
        assert!(e.to_string().contains("at most 18446744073709551 µs"), "{e}");
        assert!(parse("plc:Q0.0 servo:pulse").unwrap_err().to_string().contains("FROM -> TO"));
        assert!(parse("plc:Q0.0 -> servo:pulse gain=2").is_err());
        assert!(parse("Q0.0 -> servo:pulse").is_err());
        assert!(parse("servo:encoder -> plc:I0.0 lines=0").is_err());
        let e = connect(&parse("servo:encoder -> servo:pulse").unwrap(), Role::Encoder, Role::PulseIn).unwrap_err();
        assert!(e.to_string().contains("cannot be wired"), "{e}");
    }

    #[test]
    fn drive_terminals() {
        let r = |t: &str| drive_terminal(&endpoint(&format!("servo:{t}")).unwrap());
        assert_eq!(r("pulse").unwrap(), Role::PulseIn);
        assert_eq!(r("home@20000").unwrap(), Role::Switch(Switch::Home(20000.0)));
        assert_eq!(r("limit-@-5").unwrap(), Role::Switch(Switch::NegLimit(-5.0)));
        assert!(r("home@x").is_err());
        assert!(r("brake").unwrap_err().to_string().contains("unknown"));
    }
}
