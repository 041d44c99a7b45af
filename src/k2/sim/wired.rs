//! The K2 simulator as the host of virtual wiring ([`crate::wiring`]): it resolves its own
//! terminals (`Q0.0` a pulse output or a plain output, `I0.3` an input, `I0.1,I0.0` an A/B
//! pair), pushes its pulse outputs to the drives they are wired to the moment they start or
//! stop, and advances piecewise so each wired input is one formula per piece: a quadrature
//! wave at a whole frequency from the drive's encoder, a steady level from a drive output
//! or an axis switch, its own outputs after a delay.

use super::inputs::{ns, Pin, Source, Wave};
use super::pto::pos;
use super::K2Sim;
use crate::core::signal::PulseTrain;
use crate::core::{Error, Result};
use crate::k2::operand::{Area, K2Operand};
use crate::wiring::{self, Decl, Harness, Kind, MakePeer, Peer, Role, Wire, WireState};
use std::time::Duration;

/// Most counts one piece catches up at its start (a longer gap is a lost plan, not noise).
const MAX_CATCH_UP: u64 = 100_000;

fn secs(t_ns: u64) -> f64 {
    t_ns as f64 / 1e9
}

fn ns_at(t: f64) -> u64 {
    if !t.is_finite() || t >= 1.8e10 {
        u64::MAX
    } else {
        (t.max(0.0) * 1e9).ceil() as u64
    }
}

fn parse_bit(text: &str, area: Area) -> Option<Pin> {
    let t = text.trim();
    let body = t.strip_prefix(area.name()).or_else(|| t.strip_prefix(&area.name().to_ascii_lowercase()))?;
    let (b, bit) = body.split_once('.')?;
    let (b, bit): (u32, u8) = (b.parse().ok()?, bit.parse().ok()?);
    (bit < 8).then_some((b, bit))
}

impl K2Sim {
    fn check_bit(&self, area: Area, p: Pin) -> Result<()> {
        self.space().check(&K2Operand::bit(area, p.0, p.1))
    }

    /// What a K2 terminal speaks: `Q0.0` (a PTO output: pulses with the channel's direction
    /// output; otherwise a plain output), `Q0.0,Q0.3` (pulses with this direction output),
    /// `I0.3` (an input), `I0.1,I0.0` (A and B of a counter).
    pub fn wire_terminal(&self, term: &str) -> Result<Role> {
        let parts: Vec<&str> = term.split(',').map(str::trim).collect();
        let bad = || {
            Error::usage(format!("{}: `{term}` is not a PLC terminal", self.model().name))
                .hint("PLC terminals: Q0.0 (output), Q0.0,Q0.2 (pulses + direction), I0.3 (input), I0.1,I0.0 (A,B)")
        };
        let out = |t: &str| parse_bit(t, Area::Q);
        let inp = |t: &str| parse_bit(t, Area::I);
        match parts.as_slice() {
            [q] if out(q).is_some() => {
                let p = out(q).unwrap();
                self.check_bit(Area::Q, p)?;
                Ok(match self.pto.iter().find(|c| c.pins().0 == p) {
                    Some(c) => Role::PulseOut { channel: c.regs.channel, out: p, dir: c.pins().1 },
                    None => Role::DigitalOut(p),
                })
            }
            [q, d] if out(q).is_some() && out(d).is_some() => {
                let (p, dir) = (out(q).unwrap(), out(d).unwrap());
                self.check_bit(Area::Q, dir)?;
                let c = self.pto.iter().find(|c| c.pins().0 == p).ok_or_else(|| {
                    Error::usage(format!("{} has no pulse output on Q{}.{}", self.model().name, p.0, p.1))
                        .hint("a pulse + direction pair starts with a PTO output (Q0.0 PTO0, Q0.1 PTO1 …)")
                })?;
                Ok(Role::PulseOut { channel: c.regs.channel, out: p, dir })
            }
            [i] if inp(i).is_some() => {
                let p = inp(i).unwrap();
                self.check_input(p)?;
                Ok(Role::DigitalIn(p))
            }
            [a, b] if inp(a).is_some() && inp(b).is_some() => {
                let (a, b) = (inp(a).unwrap(), inp(b).unwrap());
                self.check_input(a)?;
                self.check_input(b)?;
                if a == b {
                    return Err(Error::usage(format!("A and B are both I{}.{}", a.0, a.1)));
                }
                Ok(Role::QuadIn { a, b })
            }
            _ => Err(bad()),
        }
    }

    /// Adds a wire this simulator hosts. `peer` is the other device (name and how to reach
    /// it) when the wire leaves the PLC. Returns a description.
    pub fn add_wire(&mut self, decl: Decl, from: Role, to: Role, peer: Option<(&str, MakePeer)>) -> Result<String> {
        let kind = wiring::connect(&decl, from, to)?;
        let needs_peer = !matches!(kind, Kind::Loop { .. } | Kind::PulseLoop { .. });
        if needs_peer != peer.is_some() {
            return Err(Error::usage(format!("{decl}: both ends are on one device or neither is the PLC"))
                .hint("wire a PLC terminal to a drive terminal, or a PLC output to a PLC input"));
        }
        self.advance();
        let mut h = self.wiring.take().unwrap_or_default();
        let peer = peer.map(|(name, make)| h.peer_index(name, make));
        if let (Kind::Pulses { .. }, Some(i)) = (kind, peer) {
            if let Err(m) = h.peers[i].1.check_pulse_input() {
                self.wiring = Some(h);
                return Err(Error::state(format!("{decl}: {m}")));
            }
        }
        // A terminal takes one signal: a new wire into it replaces the old one.
        let into = |k: &Kind| -> Vec<Pin> {
            match *k {
                Kind::Encoder { a, b, .. } => vec![a, b],
                Kind::Output { pin, .. } | Kind::Switch { pin, .. } => vec![pin],
                Kind::Loop { to, .. } | Kind::PulseLoop { to, .. } => vec![to],
                Kind::Pulses { .. } => vec![],
            }
        };
        let pins = into(&kind);
        let mut replaced = Vec::new();
        h.wires.retain(|w| {
            let clash = into(&w.kind).iter().any(|p| pins.contains(p))
                || (matches!(kind, Kind::Pulses { .. }) && w.peer == peer && matches!(w.kind, Kind::Pulses { .. }));
            if clash {
                replaced.push(w.decl.to_string());
            }
            !clash
        });
        if let (Kind::Switch { switch, .. }, Some(i)) = (kind, peer) {
            h.peers[i].1.set_switch(switch, true);
        }
        let w = Wire { decl, kind, peer, state: WireState::default() };
        let mut msg = format!("wired {}", Harness::describe(&w));
        if !replaced.is_empty() {
            msg.push_str(&format!("; replaces {}", replaced.join(", ")));
        }
        h.wires.push(w);
        self.wiring = Some(h);
        self.wired_outputs();
        // Start the new wire's signal from now.
        let now = self.last;
        self.advance_wired(now);
        Ok(msg)
    }

    /// Removes the wires whose declaration mentions `which` (a terminal such as `plc:I0.0`
    /// or `servo:pulse`), or every wire for `all`. Returns what was removed.
    pub fn unwire(&mut self, which: &str) -> Result<Vec<String>> {
        self.advance();
        let Some(mut h) = self.wiring.take() else {
            return Err(Error::usage("nothing is wired").hint("sim wire FROM -> TO adds a wire"));
        };
        let all = which.trim().eq_ignore_ascii_case("all");
        let w = which.trim().to_ascii_lowercase();
        let hit = |d: &Decl| {
            all || d.to_string().to_ascii_lowercase() == w
                || [&d.from, &d.to].iter().any(|e| {
                    let e = e.to_string().to_ascii_lowercase();
                    e == w || e.split(',').any(|p| p == w) || e.starts_with(&format!("{w}@"))
                })
        };
        let (gone, kept): (Vec<Wire>, Vec<Wire>) = h.wires.drain(..).partition(|x| hit(&x.decl));
        h.wires = kept;
        if gone.is_empty() {
            let list: Vec<String> = h.wires.iter().map(|w| w.decl.to_string()).collect();
            self.wiring = Some(h);
            return Err(Error::usage(format!("no wire touches `{which}`")).hint(if list.is_empty() {
                "nothing is wired".to_string()
            } else {
                format!("wires: {}", list.join("; "))
            }));
        }
        let t = secs(ns(self.last));
        for g in &gone {
            match g.kind {
                Kind::Encoder { a, .. } => {
                    self.inputs.remove(a);
                }
                Kind::PulseLoop { to, .. } => {
                    self.inputs.remove(to);
                }
                Kind::Pulses { .. } => {
                    if let Some(i) = g.peer {
                        // The drive keeps the pulses already out and gets no more.
                        h.peers[i].1.pulses(wiring::cut(&g.state.train, t), t);
                    }
                }
                Kind::Switch { switch, .. } => {
                    if let Some(i) = g.peer {
                        h.peers[i].1.set_switch(switch, false);
                    }
                }
                _ => {}
            }
        }
        if !h.wires.is_empty() {
            self.wiring = Some(h);
        }
        Ok(gone.iter().map(|w| w.decl.to_string()).collect())
    }

    /// The wires this simulator hosts, described.
    pub fn wires(&self) -> Vec<String> {
        self.wiring.as_ref().map(|h| h.wires.iter().map(Harness::describe).collect()).unwrap_or_default()
    }

    /// When the next wired piece begins (a wired input may then change how it moves).
    pub(crate) fn wiring_due(&self) -> Option<Duration> {
        let h = self.wiring.as_ref()?;
        let last = ns(self.last);
        h.wires
            .iter()
            .flat_map(|w| [Some(w.state.until_ns), w.state.pending.front().map(|p| p.0)])
            .flatten()
            .filter(|t| *t > last && *t != u64::MAX)
            .min()
            .map(Duration::from_nanos)
    }

    /// Sets an input bit from a wire, counting its edge as a written input would be.
    fn drive_input(&mut self, p: Pin, on: bool) {
        let Some(b) = self.mem.i.get(p.0 as usize).copied() else { return };
        let now_on = b >> p.1 & 1 != 0;
        if now_on == on {
            return;
        }
        let old = self.mem.i.clone();
        if on {
            self.mem.i[p.0 as usize] |= 1 << p.1;
        } else {
            self.mem.i[p.0 as usize] &= !(1 << p.1);
        }
        let mut raised = Vec::new();
        let now = self.last;
        for h in &mut self.hsc {
            h.input_edges(&mut self.mem, &old, now, &mut raised);
        }
        if !raised.is_empty() {
            self.events.extend(raised);
        }
    }

    /// One 4× quadrature step on A/B (A leads counting up), as a decoder sees it.
    fn quad_step(&mut self, a: Pin, b: Pin, up: bool) {
        let level = |s: &K2Sim, p: Pin| s.mem.i.get(p.0 as usize).is_some_and(|x| x >> p.1 & 1 != 0);
        let (la, lb) = (level(self, a), level(self, b));
        let toggle_a = (la == lb) == up;
        if toggle_a {
            self.drive_input(a, !la);
        } else {
            self.drive_input(b, !lb);
        }
    }

    /// The pulse train a channel puts out now, as the signal model describes it.
    fn pto_train(&self, channel: u8, dir: Pin) -> Option<(u64, u64, PulseTrain)> {
        let c = self.pto.iter().find(|c| c.regs.channel == channel)?;
        let run = c.train()?;
        let dir_on = self.mem.q.get(dir.0 as usize).is_some_and(|b| b >> dir.1 & 1 != 0);
        let disabled = self.mem.sm_bit(c.regs.pos_control, pos::DIR_DISABLE) && dir == c.pins().1;
        // The K2's own convention (§3.4.3.1): direction output 0 = forward.
        let sign = if dir_on && !disabled { -1 } else { 1 };
        let mut train = PulseTrain::new();
        let mut t = run.start.as_secs_f64();
        for s in &run.segs {
            let freq = 1e9 / s.cycle_ns as f64;
            let _ = train.push(t, freq, s.count, sign);
            t += s.cycle_ns as f64 * s.count as f64 / 1e9;
        }
        Some((ns(run.start), run.total, train))
    }

    /// Pushes what the PLC's outputs do now down the wires leaving it: a pulse train that
    /// started or stopped goes to the drive at once; an output level change is queued for
    /// its delay.
    pub(crate) fn wired_outputs(&mut self) {
        let Some(mut h) = self.wiring.take() else { return };
        let now = self.last;
        let t = secs(ns(now));
        for i in 0..h.wires.len() {
            let w = &mut h.wires[i];
            match w.kind {
                Kind::Pulses { channel, dir } => {
                    let cur = self.pto_train(channel, dir);
                    let sig = cur.as_ref().map(|c| (c.0, c.1));
                    if sig != w.state.pushed {
                        let train = match cur {
                            Some((_, _, train)) => train,
                            None => wiring::cut(&w.state.train, t),
                        };
                        w.state.train = train.clone();
                        w.state.pushed = sig;
                        if let Some(p) = w.peer {
                            h.peers[p].1.pulses(train, t);
                        }
                    }
                }
                Kind::Loop { from, to, delay_ns } => {
                    let on = self.mem.q.get(from.0 as usize).is_some_and(|b| b >> from.1 & 1 != 0);
                    if w.state.last_level != Some(on) {
                        w.state.last_level = Some(on);
                        if delay_ns == 0 {
                            self.drive_input(to, on);
                        } else {
                            w.state.pending.push_back((ns(now) + delay_ns, on));
                            w.state.until_ns = 0;
                        }
                    }
                }
                Kind::PulseLoop { channel, to, delay_ns } => {
                    w.state.until_ns = 0;
                    // Between trains the output is a plain output: its level goes through too.
                    let from = self.pto.iter().find(|c| c.regs.channel == channel).map(|c| c.pins().0);
                    if let Some(from) = from {
                        let on = self.mem.q.get(from.0 as usize).is_some_and(|b| b >> from.1 & 1 != 0);
                        if w.state.last_level != Some(on) {
                            w.state.last_level = Some(on);
                            if delay_ns == 0 && self.inputs.drives(to).is_none() {
                                self.drive_input(to, on);
                            } else {
                                w.state.pending.push_back((ns(now) + delay_ns, on));
                            }
                        }
                    }
                }
                _ => {}
            }
        }
        self.wiring = Some(h);
    }

    /// Advances to `now` piece by piece (see the module doc).
    pub(crate) fn advance_wired(&mut self, now: Duration) {
        let Some(mut h) = self.wiring.take() else { return self.advance_plain(now) };
        let now_ns = ns(now.max(self.last));
        loop {
            // Each piece starts by setting every wire's signal (and delivering what is due
            // then), the last one at `now` itself: so what comes next is known (waits ask).
            let t_ns = ns(self.last);
            let mut end = now_ns;
            for w in &mut h.wires {
                let peer = w.peer.map(|i| &mut h.peers[i].1);
                end = end.min(self.prepare(w, peer, t_ns));
            }
            if t_ns >= now_ns {
                self.advance_plain(self.last);
                break;
            }
            let mut end = end.max(t_ns + 1).min(now_ns);
            // With a program running, a piece also ends at the next scan's start: a pulse
            // output that scan starts (PLS in the program or the helper) reaches the wire at
            // the scan's own time, not at the end of the step.
            let scanning = self.plc.as_ref().is_some_and(|p| p.has_program());
            if let Some(p) = self.plc.as_ref().filter(|_| scanning) {
                end = end.min(ns(p.next_scan).max(t_ns + 1));
            }
            self.advance_plain(Duration::from_nanos(end));
            for w in &mut h.wires {
                finish(w, t_ns, end);
            }
            if scanning {
                self.wiring = Some(h);
                self.wired_outputs();
                h = self.wiring.take().expect("put back just above");
            }
        }
        self.wiring = Some(h);
        // A helper program's scan may have started or stopped a pulse output.
        self.wired_outputs();
    }

    /// Sets up one wire's signal for the piece starting at `t_ns`; returns when the piece
    /// must end for this wire.
    fn prepare(&mut self, w: &mut Wire, peer: Option<&mut Box<dyn Peer>>, t_ns: u64) -> u64 {
        let t = secs(t_ns);
        let st = &mut w.state;
        match (w.kind, peer) {
            (Kind::Encoder { a, b, lines }, Some(peer)) => {
                let plan = peer.plan_id(t);
                if plan == st.plan && t_ns < st.until_ns {
                    return st.until_ns;
                }
                let res = peer.resolution();
                let scale = lines.map_or(1.0, |l| 4.0 * l as f64 / res);
                let motion = peer.motion(t);
                let Some(piece) = motion.first().copied() else { return u64::MAX };
                let x0 = wiring::snap(piece.at(t) * scale);
                if !st.anchored {
                    st.given = x0.floor() as i64;
                    st.anchored = true;
                }
                // Counts owed from the last piece (a plan replaced between polls, a start
                // within the first period) are given now, as A/B steps.
                let owed = x0.floor() as i64 - st.given;
                if owed != 0 {
                    self.inputs.remove(a);
                    self.inputs.remove(b);
                    for _ in 0..owed.unsigned_abs().min(MAX_CATCH_UP) {
                        self.quad_step(a, b, owed > 0);
                    }
                    st.given = x0.floor() as i64;
                }
                let piece_end = piece.t0 + piece.dur;
                let (te, rate) = if piece.a == 0.0 {
                    (piece_end, piece.v0 * scale)
                } else {
                    let te = (t + wiring::RAMP_PIECE).min(piece_end);
                    (te, (piece.at(te) - piece.at(t)) * scale / (te - t))
                };
                let exact = piece.a == 0.0 && wiring::max_piece(rate).is_infinite();
                let mut until = te.min(t + wiring::max_piece(rate));
                if let Some(e) = peer.next_event(t) {
                    if e > t {
                        until = until.min(e);
                    }
                }
                // A piece whose wave only approximates the motion (a ramp's mean rate, a rate
                // that is not a whole Hz) is worked out again whenever the PLC is brought
                // forward, so the count is exact at every poll (owed counts are given then).
                st.plan = if exact { plan } else { plan.wrapping_add(1) };
                st.until_ns = ns_at(until).max(t_ns + 1);
                st.wave = wiring::quad_wave(t_ns, x0, rate, st.given);
                if let Some((hz, o, _)) = st.wave {
                    // A late first edge (see `quad_wave`): resynchronise soon.
                    let period = 1_000_000_000u64.div_ceil(hz);
                    if o == 0 && t_ns < period {
                        st.until_ns = st.until_ns.min(2 * period);
                    }
                }
                match st.wave {
                    Some((hz, origin_ns, up)) => {
                        let (lead, lag) = if up { (a, b) } else { (b, a) };
                        self.inputs.add(Source::Quad { lead, lag, wave: Wave { hz, origin_ns } });
                    }
                    None => {
                        self.inputs.remove(a);
                        self.inputs.remove(b);
                    }
                }
                st.until_ns
            }
            (Kind::Output { what, pin }, Some(peer)) => {
                // The level is read at every piece: a drive's state machine (enabled, fault)
                // changes without its motion plan changing.
                let on = peer.output(what, t);
                self.drive_input(pin, on);
                let plan = peer.plan_id(t);
                if plan == st.plan && t_ns < st.until_ns {
                    return st.until_ns;
                }
                let settle = peer.motion(t).last().map(|p| p.t0).filter(|e| *e > t);
                let ev = peer.next_event(t).filter(|e| *e > t);
                let until = [settle, ev].into_iter().flatten().fold(f64::INFINITY, f64::min);
                st.plan = plan;
                st.until_ns = ns_at(until).max(t_ns + 1);
                st.until_ns
            }
            (Kind::Switch { switch, pin }, Some(peer)) => {
                let plan = peer.plan_id(t);
                if plan == st.plan && t_ns < st.until_ns {
                    return st.until_ns;
                }
                let motion = peer.motion(t);
                let p = motion.first().map_or(0.0, |m| m.at(t));
                self.drive_input(pin, switch.active(wiring::snap(p)));
                // The level flips where the position reaches the switch (to the nearest ns).
                let reach = wiring::first_reach(&motion, switch.position(), t + 1e-9);
                let ev = peer.next_event(t).filter(|e| *e > t);
                let reach_ns = reach.map_or(u64::MAX, |r| (r * 1e9).round() as u64);
                st.plan = plan;
                st.until_ns = reach_ns.min(ev.map_or(u64::MAX, ns_at)).max(t_ns + 1);
                st.until_ns
            }
            (Kind::Loop { to, .. }, _) => {
                while st.pending.front().is_some_and(|(at, _)| *at <= t_ns) {
                    let (_, on) = st.pending.pop_front().unwrap();
                    self.drive_input(to, on);
                }
                st.pending.front().map_or(u64::MAX, |(at, _)| *at)
            }
            (Kind::PulseLoop { channel, to, delay_ns }, _) => {
                if t_ns < st.until_ns {
                    return st.until_ns;
                }
                let run = self.pto.iter().find(|c| c.regs.channel == channel).and_then(|c| c.train()).cloned();
                let mut next = u64::MAX;
                let mut wave = None;
                if let Some(run) = run {
                    let mut s0 = ns(run.start) + delay_ns;
                    for s in &run.segs {
                        let len = s.cycle_ns.saturating_mul(s.count);
                        if t_ns < s0 {
                            next = s0;
                            break;
                        }
                        if t_ns < s0.saturating_add(len) {
                            // One edge per pulse, counted as the pulse completes (the k-th at
                            // s0 + k·cycle), as the channel's own position counter counts it.
                            let hz = (1e9 / s.cycle_ns as f64).round().max(1.0) as u64;
                            wave = Some((hz, s0, true));
                            next = s0.saturating_add(len);
                            break;
                        }
                        s0 = s0.saturating_add(len);
                    }
                }
                match wave {
                    Some((hz, origin_ns, _)) => {
                        self.inputs.add(Source::Freq { pin: to, wave: Wave { hz, origin_ns } });
                    }
                    None => {
                        if self.inputs.drives(to).is_some() {
                            self.inputs.remove(to);
                        }
                        while st.pending.front().is_some_and(|(at, _)| *at <= t_ns) {
                            let (_, on) = st.pending.pop_front().unwrap();
                            self.drive_input(to, on);
                        }
                        if let Some((at, _)) = st.pending.front() {
                            next = next.min(*at);
                        }
                    }
                }
                st.wave = wave;
                st.until_ns = next.max(t_ns + 1);
                st.until_ns
            }
            _ => u64::MAX,
        }
    }
}

/// After a piece: the counts the encoder wave gave the counter in (a, b].
fn finish(w: &mut Wire, a: u64, b: u64) {
    if let (Kind::Encoder { .. }, Some((hz, origin_ns, up))) = (w.kind, w.state.wave) {
        let lead = Wave { hz, origin_ns };
        let lag = lead.shifted(lead.half_ns() / 2);
        let edges = |t: u64| {
            lead.rises_ns(t)
                + lead.shifted(lead.half_ns()).rises_ns(t)
                + lag.rises_ns(t)
                + lag.shifted(lag.half_ns()).rises_ns(t)
        };
        let n = (edges(b) - edges(a)) as i64;
        w.state.given += if up { n } else { -n };
    }
}
