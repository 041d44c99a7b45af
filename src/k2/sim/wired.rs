//! The K2 simulator as the host of virtual wiring ([`crate::core::wiring`]): it resolves its own
//! terminals (`Q0.0` a pulse output or a plain output, `I0.3` an input, `I0.1,I0.0` an A/B
//! pair), pushes its pulse outputs to the drives they are wired to the moment they start or
//! stop, and advances piecewise so each wired input is one formula per piece: the drive's
//! encoder following one constant-acceleration stretch of its motion, a steady level from a
//! drive output or an axis switch, its own outputs (pulse trains and levels) after a delay.

use super::inputs::{ns, Pin, Source, Track};
use super::pto::pos;
use super::K2Sim;
use crate::core::signal::PulseTrain;
use crate::core::wiring::{self, Decl, Harness, Kind, MakePeer, Peer, Role, Wire, WireState};
use crate::core::{Error, Result};
use crate::k2::operand::{Area, K2Operand};
use crate::msg;
use std::time::Duration;

/// A change of an encoder's position between two pieces larger than this (4× counts) is a
/// re-referenced position, not motion (the pieces of one motion meet to within float noise).
const JUMP: f64 = 1e-3;

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
            Error::usage(msg!("wire-not-plc-terminal", model = self.model().name, terminal = term))
                .hint(msg!("wire-plc-terminals-hint"))
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
                    Error::usage(msg!(
                        "wire-no-pulse-output",
                        model = self.model().name,
                        pin = format!("Q{}.{}", p.0, p.1)
                    ))
                    .hint(msg!("wire-no-pulse-output-hint"))
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
                    return Err(Error::usage(msg!("wire-a-b-same", pin = format!("I{}.{}", a.0, a.1))));
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
            return Err(Error::usage(msg!("wire-ends", wire = decl.to_string())).hint(msg!("wire-ends-hint")));
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
            return Err(Error::usage(msg!("wire-nothing")).hint(msg!("wire-nothing-short-hint")));
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
            return Err(Error::usage(msg!("wire-none-touches", which = which)).hint(if list.is_empty() {
                msg!("wire-nothing")
            } else {
                msg!("wire-list-hint", list = list.join("; "))
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
    pub(crate) fn drive_input(&mut self, p: Pin, on: bool) {
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
                    let c = self.pto.iter().find(|c| c.regs.channel == channel);
                    let run = c.and_then(|c| c.train());
                    let sig = run.map(|r| (ns(r.start), r.total));
                    if sig != w.state.pushed {
                        // What the output put out by now arrives whatever happens next; the
                        // rest of a train that stopped or was replaced never goes out.
                        cut_loop(&mut w.state, ns(now).saturating_add(delay_ns));
                        if let Some(r) = run {
                            let mut first = ns(r.start).saturating_add(delay_ns);
                            for s in &r.segs {
                                let seg = wiring::LoopSeg { first_ns: first, cycle_ns: s.cycle_ns, count: s.count };
                                w.state.segs.push_back(seg);
                                first = first.saturating_add(s.cycle_ns.saturating_mul(s.count));
                            }
                        }
                        w.state.pushed = sig;
                        w.state.until_ns = 0;
                    }
                    // Between trains the output is a plain output: its level goes through too
                    // (during a train the output's image follows the pulses, carried above).
                    let from = c.map(|c| c.pins().0).filter(|_| run.is_none());
                    if let Some(from) = from {
                        let on = self.mem.q.get(from.0 as usize).is_some_and(|b| b >> from.1 & 1 != 0);
                        if w.state.last_level != Some(on) {
                            w.state.last_level = Some(on);
                            if delay_ns == 0 && self.inputs.drives(to).is_none() {
                                self.drive_input(to, on);
                            } else {
                                w.state.pending.push_back((ns(now) + delay_ns, on));
                                w.state.until_ns = 0;
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
            // A CPU in STOP (a watchdog fault) scans no more: its pieces are the wires' own.
            let scanning = self.plc.as_ref().is_some_and(|p| p.mode == super::program::Mode::Run && p.has_program());
            if let Some(p) = self.plc.as_ref().filter(|_| scanning) {
                end = end.min(ns(p.next_scan).max(t_ns + 1));
            }
            self.advance_plain(Duration::from_nanos(end));
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
                if plan == st.plan && t_ns < st.until_ns && st.track.is_some() {
                    return st.until_ns;
                }
                let res = peer.resolution();
                let scale = lines.map_or(1.0, |l| 4.0 * l as f64 / res);
                let motion = peer.motion(t);
                let Some(piece) = motion.first().copied() else { return u64::MAX };
                // The stretch of motion from now: one constant acceleration, one way. It ends
                // with the motion's piece, where the velocity reaches zero inside it, and at
                // the drive's next own event (which may replace the plan).
                let v = piece.v0 + piece.a * (t - piece.t0).max(0.0);
                let mut until = piece.t0 + piece.dur;
                if piece.a != 0.0 && v != 0.0 {
                    let rest = t - v / piece.a;
                    if rest > t && rest < until {
                        until = rest;
                    }
                }
                if let Some(e) = peer.next_event(t) {
                    if e > t {
                        until = until.min(e);
                    }
                }
                let x = piece.at(t) * scale;
                if let Some(prev) = st.track {
                    // The position jumped (re-referenced): the shaft did not move.
                    let was = prev.x_unheld(t_ns);
                    if (x + st.offset - was).abs() > JUMP {
                        st.offset = was - x;
                    }
                }
                let x0 = x + st.offset;
                let track = Track { t0_ns: t_ns, dur: (until - t).max(0.0), x0, v: v * scale, a: piece.a * scale };
                st.plan = plan;
                st.until_ns = ns_at(until).max(t_ns + 1);
                st.track = Some(track);
                self.inputs.add(Source::Encoder { a, b, track });
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
            (Kind::PulseLoop { to, .. }, _) => {
                if t_ns < st.until_ns {
                    return st.until_ns;
                }
                // The stretch on the input is over once its last pulse has fallen.
                if st.playing.is_some_and(|p| t_ns >= p.low_from_ns()) {
                    st.playing = None;
                }
                // Level changes of the output between trains, due now (while a stretch plays
                // the pulses own the input).
                while st.pending.front().is_some_and(|(at, _)| *at <= t_ns) {
                    let (_, on) = st.pending.pop_front().unwrap();
                    if st.playing.is_none() {
                        self.drive_input(to, on);
                    }
                }
                // The next stretch goes on the input once the level changes before it are in.
                let before = |s: &wiring::LoopSeg, p: &std::collections::VecDeque<(u64, bool)>| {
                    p.front().is_none_or(|(at, _)| *at >= s.first_ns)
                };
                if st.playing.is_none() && st.segs.front().is_some_and(|s| before(s, &st.pending)) {
                    let next = st.segs.pop_front().expect("just seen");
                    // Put on the input before its first pulse rises (at the previous stretch's
                    // end, or when the train starts); a pulse rising right now (a train put
                    // out now, without delay) is an edge the counters see now.
                    if next.rises_ns(t_ns) > 0 {
                        self.drive_input(to, true);
                    }
                    st.playing = Some(next);
                }
                // The input carries the stretch playing (a stopped train's, cut short).
                let on = match self.inputs.drives(to) {
                    Some(Source::Train { train, .. }) => Some(*train),
                    _ => None,
                };
                match st.playing {
                    Some(p) if on != Some(p) => self.inputs.add(Source::Train { pin: to, train: p }),
                    None if on.is_some() => {
                        self.inputs.remove(to);
                    }
                    _ => {}
                }
                let mut next = st.pending.front().map_or(u64::MAX, |p| p.0);
                if let Some(p) = st.playing {
                    next = next.min(p.low_from_ns());
                }
                st.until_ns = next.max(t_ns + 1);
                st.until_ns
            }
            _ => u64::MAX,
        }
    }
}

/// Keeps, of the pulses a loop wire carries, those the output started by `cut_ns` (in the
/// wire's delayed time; a started pulse arrives whole); the rest never went out.
fn cut_loop(st: &mut WireState, cut_ns: u64) {
    let keep = |s: &wiring::LoopSeg| {
        let started = if cut_ns < s.first_ns { 0 } else { (cut_ns - s.first_ns) / s.cycle_ns.max(1) + 1 };
        wiring::LoopSeg { count: started.min(s.count), ..*s }
    };
    st.segs = st.segs.iter().map(keep).filter(|s| s.count > 0).collect();
    if let Some(p) = st.playing {
        let k = keep(&p);
        if k != p {
            st.playing = (k.count > 0).then_some(k);
            st.until_ns = 0;
        }
    }
}
