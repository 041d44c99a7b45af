//! Fault injection on the simulated K2: break it on purpose, on a schedule in virtual time,
//! so a commissioning script or a test sees what a failing PLC or line does to plcsh.
//!
//! A fault is a kind, an optional operand range it applies to, and a window: from a virtual
//! time (`at=2s`, or `after=500ms` from now), for a duration (`for=1s`) and/or a number of
//! requests (`times=3`). Kinds:
//!
//! | kind | what the client sees | where |
//! |---|---|---|
//! | `no-reply` | nothing: a timeout | in-process and served |
//! | `exception CODE` | Modbus exception CODE (01 illegal function … 04 device failure) | in-process and served |
//! | `late DURATION` | the reply after DURATION of wall time | served |
//! | `bad-crc` | the reply with its CRC corrupted | served, Modbus RTU on a pty |
//! | `drop` | the TCP connection closed before the reply | served, Modbus TCP |
//! | `stuck I0.1=1` | the input image bit held at a level | in-process and served |
//! | `noisy I0.1 freq=5kHz` | the input image bit flipping at random, freq= slots per second | in-process and served |
//! | `power-loss for=5s` | nothing for the window (no reply, no scan, outputs off), then a restart with only what a power cut keeps: the E2PROM backup area, the retained ranges and the running clock; under 20 ms a dip instead (K80S §5.2.2: the program pauses with outputs held, timers run on, no restart) | in-process and served |
//!
//! Request faults apply to requests that touch the range (any request without a range). In
//! the process (`sim:MODEL`) there is no transport, so `late`, `bad-crc` and `drop` act only
//! when the simulator is served; in-process a `no-reply` is a link error and an `exception`
//! the device refusing, as the wire driver reports them. `stuck` and `noisy` act on the input
//! image that clients and programs read, and on what the high-speed counters count: inside
//! the window the input's edges are the fault's (`super::edges`). Noise is one level per slot
//! (`freq=` slots a second from the window's start), pseudo-random from the fault's id and
//! the slot number (splitmix64): the same on every run, whoever reads when. A fault's window
//! ending, or `sim fault clear`, gives the input its own level back.
//!
//! A `late` reply holds the server for its delay (it serves one request at a time, as a PLC's
//! Modbus port does), so everything the same `sim serve` process serves waits too.
//!
//! Every time a fault acts it is logged as an event (`fault{ID}`) with its virtual time, so a
//! test can correlate what plcsh reported with what was injected.

use super::inputs::{pin_name, Pin};
use crate::core::literal::parse_option_duration_us;
use crate::k2::operand::{parse_expr, Area};
use crate::msg;
use std::time::Duration;

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum FaultKind {
    NoReply,
    Exception {
        code: u8,
    },
    Late {
        ms: u64,
    },
    BadCrc,
    Drop,
    Stuck {
        byte: u32,
        bit: u8,
        on: bool,
    },
    Noisy {
        byte: u32,
        bit: u8,
        hz: u64,
    },
    /// The PLC without power for the fault's window: no reply, no scan, outputs off; back
    /// with only what a power cut keeps ([`super::power`]).
    PowerLoss,
}

impl FaultKind {
    /// The input a stuck or noisy fault acts on.
    pub fn pin(&self) -> Option<Pin> {
        match *self {
            FaultKind::Stuck { byte, bit, .. } | FaultKind::Noisy { byte, bit, .. } => Some((byte, bit)),
            _ => None,
        }
    }

    /// The short name (`no-reply`), also the event's.
    pub fn name(&self) -> &'static str {
        match self {
            FaultKind::NoReply => "no-reply",
            FaultKind::Exception { .. } => "exception",
            FaultKind::Late { .. } => "late",
            FaultKind::BadCrc => "bad-crc",
            FaultKind::Drop => "drop",
            FaultKind::Stuck { .. } => "stuck",
            FaultKind::Noisy { .. } => "noisy",
            FaultKind::PowerLoss => "power-loss",
        }
    }

    /// A numeric code for the event log (event kinds are plain data).
    pub fn code(&self) -> u8 {
        match self {
            FaultKind::NoReply => 1,
            FaultKind::Exception { .. } => 2,
            FaultKind::Late { .. } => 3,
            FaultKind::BadCrc => 4,
            FaultKind::Drop => 5,
            FaultKind::Stuck { .. } => 6,
            FaultKind::Noisy { .. } => 7,
            FaultKind::PowerLoss => 8,
        }
    }

    pub fn name_of_code(code: u8) -> &'static str {
        [
            FaultKind::NoReply,
            FaultKind::Exception { code: 0 },
            FaultKind::Late { ms: 0 },
            FaultKind::BadCrc,
            FaultKind::Drop,
            FaultKind::Stuck { byte: 0, bit: 0, on: false },
            FaultKind::Noisy { byte: 0, bit: 0, hz: 0 },
            FaultKind::PowerLoss,
        ]
        .into_iter()
        .find(|k| k.code() == code)
        .map_or("fault", |k| k.name())
    }

    /// Acts on requests (not on the input image).
    pub fn is_request(&self) -> bool {
        !matches!(self, FaultKind::Stuck { .. } | FaultKind::Noisy { .. })
    }

    /// Acts without a transport (in-process).
    pub fn in_process(&self) -> bool {
        !matches!(self, FaultKind::Late { .. } | FaultKind::BadCrc | FaultKind::Drop)
    }

    fn describe(&self) -> String {
        match *self {
            FaultKind::Exception { code } => {
                format!("exception {code:02X} ({})", crate::k2::modbus_map::exception_name(code))
            }
            FaultKind::Late { ms } => format!("late {ms}ms"),
            FaultKind::Stuck { byte, bit, on } => format!("stuck {}={}", pin_name((byte, bit)), u8::from(on)),
            FaultKind::Noisy { byte, bit, hz } => format!("noisy {} freq={hz}Hz", pin_name((byte, bit))),
            k => k.name().to_string(),
        }
    }
}

#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Fault {
    pub id: u32,
    pub kind: FaultKind,
    pub range: Option<(Area, u32, u32)>,
    /// Window in virtual time (ns since the clock started).
    pub from_ns: u64,
    pub until_ns: Option<u64>,
    pub times: Option<u32>,
    pub hits: u32,
    /// `stuck`/`noisy`: the activation was logged.
    pub logged: bool,
    /// `stuck`/`noisy`: the input's level before the fault took it, put back when it ends.
    #[serde(default)]
    pub held: Option<bool>,
}

impl Fault {
    /// The level a stuck or noisy fault gives its input at `t` ns, when its window holds
    /// `t` (the window only: how the input looks does not depend on who read it).
    pub fn level_at(&self, t: u64) -> Option<bool> {
        if t < self.from_ns || self.until_ns.is_some_and(|u| t >= u) || self.times == Some(0) {
            return None;
        }
        match self.kind {
            FaultKind::Stuck { on, .. } => Some(on),
            FaultKind::Noisy { hz, .. } => Some(noise(self.id, self.slot(t, hz))),
            _ => None,
        }
    }

    /// The noise slot `t` ns falls in (`hz` slots a second from the window's start).
    fn slot(&self, t: u64, hz: u64) -> u64 {
        ((t.saturating_sub(self.from_ns)) as u128 * hz as u128 / 1_000_000_000) as u64
    }

    /// The instants in `(a, b]` ns where the level this fault gives may change: its
    /// window's ends and, for noise, each slot's start.
    pub fn changes(&self, a: u64, b: u64) -> Vec<u64> {
        let mut out: Vec<u64> =
            [Some(self.from_ns), self.until_ns].into_iter().flatten().filter(|t| *t > a && *t <= b).collect();
        if let FaultKind::Noisy { hz, .. } = self.kind {
            let lo = a.max(self.from_ns);
            let hi = self.until_ns.map_or(b, |u| u.min(b));
            if hz > 0 && lo < hi {
                let first = self.slot(lo, hz) + 1;
                let last = self.slot(hi, hz);
                for k in first..=last {
                    let t = self.from_ns + (k as u128 * 1_000_000_000).div_ceil(hz as u128) as u64;
                    if t > a && t <= b {
                        out.push(t);
                    }
                }
            }
        }
        out
    }

    fn active(&self, now: Duration) -> bool {
        let t = now.as_nanos() as u64;
        t >= self.from_ns && self.until_ns.is_none_or(|u| t < u) && self.times.is_none_or(|n| self.hits < n)
    }

    fn touches(&self, touched: &[(Area, u32, u32)]) -> bool {
        match self.range {
            None => true,
            Some((a, f, l)) => touched.iter().any(|&(ta, tf, tl)| ta == a && tf <= l && f <= tl),
        }
    }

    /// One line for `sim faults`.
    pub fn describe(&self) -> String {
        let mut s = format!("fault {}: {}", self.id, self.kind.describe());
        if let Some((a, f, l)) = self.range {
            s.push_str(&format!(" on {}B{f}..{}B{l}", a.name(), a.name()));
        }
        s.push_str(&format!(" from {:.6}s", self.from_ns as f64 / 1e9));
        if let Some(u) = self.until_ns {
            s.push_str(&format!(" until {:.6}s", u as f64 / 1e9));
        }
        if let Some(n) = self.times {
            s.push_str(&format!(", {n} time(s)"));
        }
        s.push_str(&format!("; acted {} time(s)", self.hits));
        s
    }
}

/// The faults set on one simulator.
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct Faults {
    pub list: Vec<Fault>,
    next: u32,
}

/// One parsed `sim fault …` line.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    pub kind: FaultKind,
    pub range: Option<(Area, u32, u32)>,
    /// Start: absolute (`at=`) or relative to now (`after=`).
    pub at: Option<Duration>,
    pub after: Option<Duration>,
    pub duration: Option<Duration>,
    pub times: Option<u32>,
}

fn dur(v: &str, key: &str) -> Result<Duration, String> {
    let us = parse_option_duration_us(v).map_err(|m| format!("{key}={v}: {m}"))?;
    u64::try_from(us).map(Duration::from_micros).map_err(|_| msg!("k2-fault-negative", key = key, value = v).into())
}

fn input_pin(text: &str) -> Result<Pin, String> {
    let t = text.to_ascii_uppercase();
    t.strip_prefix('I')
        .and_then(|b| b.split_once('.'))
        .and_then(|(b, bit)| Some((b.parse().ok()?, bit.parse().ok().filter(|x: &u8| *x < 8)?)))
        .ok_or_else(|| msg!("k2-fault-not-input", text = text).into())
}

/// The grammar, for messages.
pub const USAGE: &str = "sim fault no-reply|exception CODE|late DURATION|bad-crc|drop [on OPERANDS] | sim fault stuck I0.1=1|noisy I0.1 freq=5kHz | sim fault power-loss for=5s — then [at=TIME|after=DURATION] [for=DURATION] [times=N]; sim faults; sim fault clear [ID]";

/// Parses `no-reply on VW100..VW110 after=2s times=1` and the like. Linear in its input;
/// refuses with a message.
pub fn parse(text: &str) -> Result<Spec, String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let Some((&kind_word, mut rest)) = words.split_first() else {
        return Err(msg!("k2-fault-which", usage = USAGE).into());
    };
    // `needs`: the message when the word is missing.
    let mut take = |needs: &dyn Fn() -> String| -> Result<&str, String> {
        let (w, r) = rest.split_first().ok_or_else(needs)?;
        rest = r;
        Ok(w)
    };
    let kind = match kind_word.to_ascii_lowercase().as_str() {
        "no-reply" => FaultKind::NoReply,
        "bad-crc" => FaultKind::BadCrc,
        "drop" => FaultKind::Drop,
        "power-loss" => FaultKind::PowerLoss,
        "exception" => {
            let c = take(&|| msg!("k2-fault-needs-code", kind = kind_word).into())?;
            let code = c
                .trim_start_matches("16#")
                .parse::<u8>()
                .ok()
                .filter(|c| *c > 0)
                .ok_or_else(|| msg!("k2-fault-not-code", code = c).text)?;
            FaultKind::Exception { code }
        }
        // `delay` is the drive line's word for it: one vocabulary for faults.
        "late" | "delay" => {
            let d = dur(take(&|| msg!("k2-fault-needs-delay", kind = kind_word).into())?, "late")?;

            FaultKind::Late { ms: d.as_millis() as u64 }
        }
        "stuck" => {
            let w = take(&|| msg!("k2-fault-needs-input-level", kind = kind_word).into())?;
            let (p, v) = w.split_once('=').ok_or_else(|| msg!("k2-fault-stuck-shape", word = w).text)?;
            let (byte, bit) = input_pin(p)?;
            let on = match v {
                "1" | "on" | "true" => true,
                "0" | "off" | "false" => false,
                _ => return Err(msg!("k2-fault-not-level", value = v).into()),
            };
            FaultKind::Stuck { byte, bit, on }
        }
        "noisy" => {
            let (byte, bit) = input_pin(take(&|| msg!("k2-fault-needs-input", kind = kind_word).into())?)?;
            FaultKind::Noisy { byte, bit, hz: 0 }
        }
        other => return Err(msg!("k2-fault-not-kind", kind = other, usage = USAGE).into()),
    };
    let mut spec = Spec { kind, range: None, at: None, after: None, duration: None, times: None };
    let mut it = rest.iter();
    while let Some(&w) = it.next() {
        if w.eq_ignore_ascii_case("on") {
            let ops_text = it.next().ok_or_else(|| msg!("k2-fault-on-needs-operands").text)?;
            let ops = parse_expr(ops_text).map_err(|e| e.message.clone())?;
            let area = ops[0].area;
            if ops.iter().any(|o| o.area != area) {
                return Err(msg!("k2-fault-spans-areas", operands = *ops_text).into());
            }
            let first = ops.iter().map(|o| o.byte).min().unwrap_or(0);
            let last = ops.iter().map(|o| o.byte + o.width.bytes().max(1) - 1).max().unwrap_or(0);
            spec.range = Some((area, first, last));
            continue;
        }
        let (k, v) = w.split_once('=').ok_or_else(|| msg!("k2-fault-not-option", word = w, usage = USAGE).text)?;
        match k {
            "at" => spec.at = Some(dur(v, k)?),
            "after" => spec.after = Some(dur(v, k)?),
            "for" => spec.duration = Some(dur(v, k)?),
            // `count=` is the drive line's word for it.
            "times" | "count" => {
                spec.times =
                    Some(v.parse().ok().filter(|n| *n > 0).ok_or_else(|| msg!("k2-fault-times", value = v).text)?)
            }
            "freq" => match &mut spec.kind {
                FaultKind::Noisy { hz, .. } => {
                    let f = crate::core::literal::parse_freq_hz(v)?;
                    if !(1.0..=1e7).contains(&f) {
                        return Err(format!("freq={v}: 1 Hz … 10 MHz"));
                    }
                    *hz = f as u64;
                }
                _ => return Err(msg!("k2-fault-freq-noisy-only").into()),
            },
            _ => return Err(msg!("k2-fault-unknown-option", key = k, usage = USAGE).into()),
        }
    }
    if let FaultKind::Noisy { hz: 0, .. } = spec.kind {
        return Err(msg!("k2-fault-noisy-needs-freq").into());
    }
    if spec.at.is_some() && spec.after.is_some() {
        return Err(msg!("k2-fault-at-or-after").into());
    }
    if spec.kind == FaultKind::PowerLoss {
        if spec.duration.is_none() {
            return Err(msg!("k2-fault-power-loss-needs-for").into());
        }
        if spec.range.is_some() || spec.times.is_some() {
            return Err(msg!("k2-fault-power-loss-options").into());
        }
    }
    if spec.range.is_some() && !spec.kind.is_request() {
        return Err(msg!("k2-fault-on-request-only", kind = spec.kind.name()).into());
    }

    Ok(spec)
}

/// A pseudo-random bit for slot `n` of fault `id` (splitmix64): deterministic noise.
fn noise(id: u32, n: u64) -> bool {
    let mut z = n.wrapping_add(u64::from(id) << 40).wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z ^ (z >> 31)) & 1 == 1
}

impl Faults {
    /// Sets a fault from `spec` at virtual time `now`; returns its id.
    pub fn add(&mut self, spec: &Spec, now: Duration) -> u32 {
        self.next += 1;
        let from = spec.at.unwrap_or(now + spec.after.unwrap_or_default());
        self.list.push(Fault {
            id: self.next,
            kind: spec.kind,
            range: spec.range,
            from_ns: from.as_nanos() as u64,
            until_ns: spec.duration.map(|d| (from + d).as_nanos() as u64),
            times: spec.times,
            hits: 0,
            logged: false,
            held: None,
        });
        self.next
    }

    /// The power-loss windows `(off, on)` set, in virtual time.
    pub fn power_windows(&self) -> impl Iterator<Item = (u32, Duration, Duration)> + '_ {
        self.list
            .iter()
            .filter(|f| f.kind == FaultKind::PowerLoss)
            .filter_map(|f| Some((f.id, Duration::from_nanos(f.from_ns), Duration::from_nanos(f.until_ns?))))
    }

    /// True when a power loss is set (checked before every step; usually an empty list).
    #[inline]
    pub fn has_power_loss(&self) -> bool {
        !self.list.is_empty() && self.list.iter().any(|f| f.kind == FaultKind::PowerLoss)
    }

    /// Removes fault `id`, or all; returns how many went, and the inputs the removed
    /// faults were holding with their levels from before (to be given back, as the end of
    /// a fault's window gives them back).
    pub fn clear(&mut self, id: Option<u32>) -> (usize, Vec<(Pin, bool)>) {
        let before = self.list.len();
        let mut held = Vec::new();
        self.list.retain(|f| {
            let keep = id.is_some_and(|i| f.id != i);
            if !keep {
                if let (Some(p), Some(level)) = (f.kind.pin(), f.held.filter(|_| f.logged)) {
                    held.push((p, level));
                }
            }
            keep
        });
        (before - self.list.len(), held)
    }

    /// The input faults (stuck, noisy) acting on `pin` at some time in `(a, b]` ns.
    pub fn on_pin(&self, pin: Pin, a: u64, b: u64) -> impl Iterator<Item = &Fault> {
        self.list.iter().filter(move |f| {
            f.kind.pin() == Some(pin) && f.from_ns < b && f.until_ns.is_none_or(|u| u > a) && f.times != Some(0)
        })
    }

    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The request fault acting on a request that touches `touched` at `now` (the first
    /// active one set), its hit counted. `served`: a transport is there.
    pub fn on_request(
        &mut self,
        now: Duration,
        touched: &[(Area, u32, u32)],
        served: bool,
    ) -> Option<(u32, FaultKind)> {
        let f = self
            .list
            .iter_mut()
            .find(|f| f.kind.is_request() && (served || f.kind.in_process()) && f.active(now) && f.touches(touched))?;
        f.hits += 1;
        Some((f.id, f.kind))
    }

    /// Applies stuck and noisy inputs to the input image at `now` (and gives an input back
    /// its level from before when its fault's window ends); returns the faults that took
    /// effect, with the time they did (to be logged once).
    /// An input a simulated signal drives (`driven`) is not given a level back: the signal's
    /// own level is already there.
    pub fn apply_inputs(
        &mut self,
        i: &mut [u8],
        now: Duration,
        driven: &dyn Fn(Pin) -> bool,
    ) -> Vec<(Duration, u32, FaultKind)> {
        fn put(i: &mut [u8], byte: u32, bit: u8, on: bool) {
            if let Some(b) = i.get_mut(byte as usize) {
                if on {
                    *b |= 1 << bit;
                } else {
                    *b &= !(1 << bit);
                }
            }
        }
        let mut started = Vec::new();
        for f in &mut self.list {
            let (byte, bit, level) = match f.kind {
                FaultKind::Stuck { byte, bit, on } => (byte, bit, on),
                FaultKind::Noisy { byte, bit, hz } => (byte, bit, noise(f.id, f.slot(now.as_nanos() as u64, hz))),
                _ => continue,
            };
            if !f.active(now) {
                if !f.logged && f.from_ns <= now.as_nanos() as u64 && f.times != Some(0) {
                    // Its whole window passed between two steps: it acted (the counters saw
                    // it, `super::edges`) and is logged at its start, whoever read when.
                    f.logged = true;
                    f.hits = 1;
                    started.push((Duration::from_nanos(f.from_ns), f.id, f.kind));
                    continue;
                }
                if let Some(before) = f.held.take().filter(|_| f.logged) {
                    if !driven((byte, bit)) {
                        put(i, byte, bit, before);
                    }
                }
                continue;
            }
            if !f.logged {
                f.logged = true;
                f.hits = 1;
                f.held = i.get(byte as usize).map(|b| b >> bit & 1 != 0);
                started.push((Duration::from_nanos(f.from_ns).min(now), f.id, f.kind));
            }
            put(i, byte, bit, level);
        }
        started
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    #[test]
    fn the_drive_lines_words_mean_the_same() {
        assert_eq!(parse("delay 300ms count=2").unwrap(), parse("late 300ms times=2").unwrap());
    }

    #[test]
    fn specs_parse_with_ranges_and_schedules() {
        let s = parse("exception 2 on VW100..VW110 after=2s for=1s times=3").unwrap();
        assert_eq!(s.kind, FaultKind::Exception { code: 2 });
        assert_eq!(s.range, Some((Area::V, 100, 111)));
        assert_eq!((s.after, s.duration, s.times), (Some(ms(2000)), Some(ms(1000)), Some(3)));
        assert_eq!(parse("late 300ms").unwrap().kind, FaultKind::Late { ms: 300 });
        assert_eq!(parse("stuck I0.1=1 at=5s").unwrap().kind, FaultKind::Stuck { byte: 0, bit: 1, on: true });
        assert_eq!(parse("noisy I1.0 freq=5kHz").unwrap().kind, FaultKind::Noisy { byte: 1, bit: 0, hz: 5000 });
        for bad in [
            "",
            "melt",
            "exception",
            "exception 0",
            "late",
            "stuck I0.9=1",
            "stuck Q0.1=1",
            "noisy I0.1",
            "no-reply on",
            "no-reply at=1s after=1s",
            "no-reply times=0",
            "stuck I0.1=1 on VW0",
            "drop when=now",
        ] {
            assert!(parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn request_faults_act_in_their_window_range_and_count() {
        let mut f = Faults::default();
        f.add(&parse("no-reply on VW100 after=1s times=2").unwrap(), ms(0));
        f.add(&parse("drop").unwrap(), ms(0));
        let vw100 = [(Area::V, 100, 101)];
        assert_eq!(f.on_request(ms(500), &vw100, false), None, "not yet; drop needs a transport");
        assert_eq!(f.on_request(ms(1500), &[(Area::V, 0, 1)], false), None, "other range");
        assert_eq!(f.on_request(ms(1500), &vw100, false), Some((1, FaultKind::NoReply)));
        assert_eq!(f.on_request(ms(1600), &[(Area::V, 90, 120)], false), Some((1, FaultKind::NoReply)));
        assert_eq!(f.on_request(ms(1700), &vw100, false), None, "times=2 used up");
        assert_eq!(f.on_request(ms(1700), &vw100, true), Some((2, FaultKind::Drop)), "served: drop acts");
        assert_eq!(f.clear(Some(2)).0, 1);
        assert_eq!(f.clear(None).0, 1);
    }

    #[test]
    fn stuck_and_noisy_inputs_hold_the_image_and_log_once() {
        let mut f = Faults::default();
        f.add(&parse("stuck I0.1=1 for=1s").unwrap(), ms(0));
        f.add(&parse("noisy I0.2 freq=1kHz").unwrap(), ms(0));
        let mut i = [0u8; 2];
        let started = f.apply_inputs(&mut i, ms(10), &|_| false);
        assert_eq!(started.len(), 2);
        assert_eq!(i[0] & 2, 2, "stuck on");
        assert!(f.apply_inputs(&mut i, ms(20), &|_| false).is_empty(), "logged once");
        // Noise: both levels appear over 100 slots, and the same time gives the same level.
        let levels: Vec<bool> = (0..100)
            .map(|k| {
                let mut i = [0u8; 2];
                f.apply_inputs(&mut i, ms(100 + k), &|_| false);
                i[0] & 4 != 0
            })
            .collect();
        assert!(levels.iter().any(|l| *l) && levels.iter().any(|l| !*l));
        let mut a = [0u8; 2];
        let mut b = [0u8; 2];
        f.apply_inputs(&mut a, ms(123), &|_| false);
        f.apply_inputs(&mut b, ms(123), &|_| false);
        assert_eq!(a, b);
        let mut i = [0u8; 2];
        f.apply_inputs(&mut i, ms(1500), &|_| false);
        assert_eq!(i[0] & 2, 0, "the stuck window ended: the level from before is back");
        assert_eq!(started[0].0, ms(0), "stamped when it took effect");
    }
}
