//! The in-process K2 simulator: a memory image of any catalogued model, behaving as the
//! manual says, driven by the session's virtual clock.
//!
//! Everything time-dependent is computed from elapsed virtual time when the simulator is
//! touched ([`K2Sim::advance_to`]), never by ticking: the system bits (SM0.0 always on, SM0.1
//! first scan, SM0.5 1-second clock, SM0.6 scan toggle), the pulse outputs ([`pto`]), the
//! high-speed counters ([`hsc`]) fed by simulated input signals ([`inputs`]), the event
//! log ([`events`]) and the real-time clock ([`rtc`]). The backup area and retained ranges
//! persist through [`state`]. The Modbus server (`plcsh sim serve`) serves this same type.

pub mod agent;
pub mod agent_probe;
pub mod control;
pub mod edges;
pub mod events;
pub mod fault;
pub mod hsc;
pub mod inputs;
pub mod program;
pub mod pto;
pub mod rtc;
pub mod snapshot;
pub mod state;
pub mod wired;

pub mod modbus_net;
pub mod modbus_server;
pub mod power;
pub mod rtu_frame;

use crate::core::{Clock, Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::k2::catalog::{self, Model};
use crate::k2::instr::{self, Event, EventKind, EventMatch, RtcTime};
use crate::k2::memory::Memory;
use crate::k2::operand::{Area, K2Operand, Width};
use crate::k2::sm_map::{HSC_REGS, PTO_REGS};
use crate::k2::space::K2Space;
use crate::msg;
use events::EventLog;
use hsc::HscChannel;
use inputs::{Inputs, Pin, Source};
use pto::PtoChannel;
use rtc::Rtc;
use state::{Backup, Retain};
use std::path::PathBuf;
use std::time::Duration;

/// Scan time the simulator assumes (the manual gives no figure; 1 ms is typical of a
/// small K2 program). SM0.1 is on for the first scan, SM0.6 toggles every scan.
pub const SCAN_TIME: Duration = Duration::from_millis(1);

/// Most pulse and counter channels a model has (4 PTO + 4 HSC).
const MAX_CHANNELS: usize = 8;

/// A simulated K2.
pub struct K2Sim {
    info: DeviceInfo,
    space: K2Space,
    pub mem: Memory,
    pub clock: Clock,
    /// Virtual time the simulator was powered up, and in ns.
    start: Duration,
    start_ns: u64,
    /// Virtual time of the last `advance`.
    pub last: Duration,
    /// Pulse output channels the model has (none on relay models).
    pub pto: Vec<PtoChannel>,
    /// High-speed counters the model has.
    pub hsc: Vec<HscChannel>,
    /// Simulated signals on the inputs.
    pub inputs: Inputs,
    pub events: EventLog,
    pub rtc: Rtc,
    pub backup: Backup,
    /// Injected faults ([`fault`]).
    pub faults: fault::Faults,
    /// Wires to other simulated devices (`sim wire`); this simulator hosts them ([`wired`]).
    pub wiring: Option<Box<crate::core::wiring::Harness>>,
    /// The CPU running programs (user program, helper), once one was loaded.
    pub plc: Option<Box<program::Plc>>,
    /// The helper program's mailbox base when it runs (`--agent`), for snapshots.
    pub agent_base: Option<u32>,
    /// Scratch space of `advance_to` (events raised in a step, where each channel's end),
    /// kept so a step allocates nothing.
    raised: Vec<(Duration, EventKind)>,
    run_ends: Vec<usize>,
    /// Numbered events waiting for their interrupt routines (program::irq).
    irq_queue: Vec<(Duration, u32)>,
    /// A program's STOP instruction ran: the CPU goes to STOP at the end of the scan.
    pub(crate) stop_requested: bool,
}

impl K2Sim {
    pub fn new(model: &'static Model, clock: Clock) -> K2Sim {
        let start = clock.now();
        let mut mem = Memory::new(model);
        let pto = model.pto.iter().map(|p| PtoChannel::new(PTO_REGS[p.channel as usize], *p, &mut mem)).collect();
        let hsc = model.hsc.iter().map(|h| HscChannel::new(HSC_REGS[h.channel as usize], *h)).collect();
        let mut sim = K2Sim {
            info: DeviceInfo { family: "k2", model: model.name.to_string(), link: "sim".into(), simulated: true },
            space: K2Space::new(model),
            mem,
            clock,
            start,
            start_ns: inputs::ns(start),
            last: start,
            pto,
            hsc,
            inputs: Inputs::default(),
            events: EventLog::default(),
            rtc: Rtc::new(instr::host_local_now(), start),
            backup: Backup { since: start, ..Backup::default() },
            faults: fault::Faults::default(),
            wiring: None,
            plc: None,
            agent_base: None,
            raised: Vec::new(),
            run_ends: Vec::new(),
            irq_queue: Vec::new(),
            stop_requested: false,
        };
        sim.refresh_system_bits(start);
        sim
    }

    pub fn model(&self) -> &'static Model {
        self.space.model
    }

    pub fn space(&self) -> &K2Space {
        &self.space
    }

    /// Time since power-up.
    pub fn uptime(&self) -> Duration {
        self.last - self.start
    }

    /// Brings the simulation up to the clock's current time.
    #[inline]
    pub fn advance(&mut self) {
        let now = self.clock.now().max(self.last);
        self.advance_to(now);
    }

    /// Brings the simulation up to virtual time `now`: pulses, counts, events, input
    /// levels and system bits, all computed from the elapsed time in one step — and, when
    /// a program runs, every scan due before `now` at its own start time ([`program`]).
    #[inline]
    pub fn advance_to(&mut self, now: Duration) {
        if self.faults.has_power_loss() {
            return self.advance_through_power_loss(now);
        }
        self.advance_powered(now);
    }

    /// [`Self::advance_to`] while the PLC has power.
    #[inline]
    pub(crate) fn advance_powered(&mut self, now: Duration) {
        if self.wiring.is_some() {
            return self.advance_wired(now);
        }
        self.advance_plain(now);
    }

    /// [`Self::advance_to`] without the wiring: the scans due (when a program runs) and the
    /// hardware, one formula per signal over the interval.
    #[inline]
    pub(crate) fn advance_plain(&mut self, now: Duration) {
        if self.plc.is_some() {
            self.run_scans(now);
            self.advance_with_interrupts(now);
        } else {
            self.advance_hw(now);
        }
    }

    /// The hardware part of [`Self::advance_to`]: no program runs.
    fn advance_hw(&mut self, now: Duration) {
        let last = self.last;
        let now = now.max(last);
        // Events go to a buffer kept between steps, one run per channel, merged by time.
        self.raised.clear();
        let mut skipped = 0u64;
        // Both ends of the interval in ns, worked out once for every channel.
        let (from, to) = ((last, inputs::ns(last)), (now, inputs::ns(now)));
        // Where each channel's events end in `raised`, kept on the stack: the run list is
        // built only in the rare step that raised something.
        let mut lens = [0usize; MAX_CHANNELS];
        let mut k = 0;
        for p in &mut self.pto {
            p.advance(&mut self.mem, to, &mut self.raised);
            lens[k] = self.raised.len();
            k += 1;
        }
        for h in &mut self.hsc {
            if !self.faults.is_empty() && edges::faulted(&self.faults, &h.pins(), from.1, to.1) {
                h.advance_edges(&mut self.mem, &self.inputs, &self.faults, (from.1, to.1), &mut self.raised);
            } else {
                h.advance(&mut self.mem, &self.inputs, from, to, &mut self.raised, &mut skipped);
            }
            // A direction change shown since the last step (by HSC, a written input, or the
            // signals counted in this one), raised at the step's start.
            let at = h.dir_at.take();
            if let Some(up) = h.dir_event.take() {
                self.raised.push((at.unwrap_or(last), EventKind::HscDirection { channel: h.regs.channel, up }));
            }
            lens[k] = self.raised.len();
            k += 1;
        }
        self.refresh_input_levels(to.1);
        let mut faults = 0;
        if !self.faults.is_empty() {
            let inputs = &self.inputs;
            let driven = |p: Pin| inputs.drives(p).is_some();
            for (at, id, kind) in self.faults.apply_inputs(&mut self.mem.i, now, &driven) {
                self.raised.push((at.max(last), EventKind::Fault { id, fault: kind.code() }));
                faults += 1;
            }
        }
        if skipped > 0 {
            self.events.skip(skipped);
        }
        if !self.raised.is_empty() {
            self.run_events(&lens[..k], faults);
        }
        self.last = now;
        self.refresh_system_bits_ns(to.1);
    }

    /// Logs the events a step raised (one time-ordered run per channel, then one per fault)
    /// and queues their interrupt routines.
    #[cold]
    fn run_events(&mut self, lens: &[usize], faults: usize) {
        let raised = std::mem::take(&mut self.raised);
        let mut ends = std::mem::take(&mut self.run_ends);
        ends.clear();
        // Channels that raised nothing add no run.
        for &n in lens {
            if ends.last().copied().unwrap_or(0) < n {
                ends.push(n);
            }
        }
        let channels_end = ends.last().copied().unwrap_or(0);
        ends.extend((1..=faults).map(|f| channels_end + f));
        self.events.extend_runs(&raised, &ends);
        if self.plc.is_some() {
            self.queue_hw_events(&raised);
        }
        (self.raised, self.run_ends) = (raised, ends);
    }

    /// Writes the sources' current levels into the input image.
    fn refresh_input_levels(&mut self, t: u64) {
        fn put(i: &mut [u8], p: Pin, on: bool) {
            if let Some(b) = i.get_mut(p.0 as usize) {
                if on {
                    *b |= 1 << p.1
                } else {
                    *b &= !(1 << p.1)
                }
            }
        }
        for &(p, rise, fall) in self.inputs.edges() {
            put(&mut self.mem.i, p, rise.rises_ns(t) > fall.rises_ns(t));
        }
        if self.inputs.has_shaped() {
            for s in self.inputs.sources() {
                for (p, on) in s.shaped_levels(t).into_iter().flatten() {
                    put(&mut self.mem.i, p, on);
                }
            }
        }
    }

    fn refresh_system_bits(&mut self, now: Duration) {
        self.refresh_system_bits_ns(inputs::ns(now));
    }

    /// [`Self::refresh_system_bits`] at `now_ns`.
    fn refresh_system_bits_ns(&mut self, now_ns: u64) {
        // 64-bit arithmetic in ns (a u128 division is a library call; 64 bits of ns is 584
        // years of uptime); the scan time is a whole number of ms, so scans follow from ms.
        const SCAN_MS: u64 = SCAN_TIME.as_millis() as u64;
        const _: () = assert!(SCAN_TIME.as_nanos() == SCAN_MS as u128 * 1_000_000);
        // The clock bits run on the program's time (PAUSE and DEBUG freeze it: program::Plc::thaw).
        let prog_ns = self.plc.as_ref().map_or(now_ns, |p| p.program_ns(now_ns));
        let ms = prog_ns.saturating_sub(self.start_ns) / 1_000_000;
        let scans = ms / SCAN_MS;
        let mut b = 0u8;
        b |= 1; // SM0.0 always on (§8)
        let program = self.plc.as_ref().is_some_and(|p| p.has_program());
        if program {
            // The scan cycle sets SM0.1 and SM0.6 (program::one_scan).
            b |= self.mem.sm[0] & (1 << 1 | 1 << 6);
        } else if scans == 0 {
            b |= 1 << 1; // SM0.1 first scan (§8)
        }
        if (ms / 30_000).is_multiple_of(2) {
            b |= 1 << 4; // SM0.4 1-minute clock (S7-200 convention)
        }
        if (ms / 500).is_multiple_of(2) {
            b |= 1 << 5; // SM0.5 1-second clock: 0.5 s on, 0.5 s off
        }
        if !program && scans % 2 == 1 {
            b |= 1 << 6; // SM0.6 toggles every scan
        }
        self.mem.sm[0] = b;
    }

    /// Reads one operand's raw pattern at the current time.
    pub fn read_raw(&mut self, op: &K2Operand) -> u32 {
        self.mem.read(op)
    }

    /// Refuses writes the PLC would not accept.
    fn check_writable(&self, op: &K2Operand) -> Result<()> {
        if let Some(e) = sm_read_only(self.model(), op) {
            return Err(e);
        }
        let (lo, hi) = (op.byte, op.byte + op.width.bytes());
        if op.area == Area::I {
            for s in self.inputs.sources() {
                for p in s.pins() {
                    let bit_hit = match op.width {
                        Width::Bit(b) => p == (op.byte, b),
                        Width::Group { n, bit } => {
                            let abs = p.0 * 8 + p.1 as u32;
                            let first = op.byte * 8 + bit as u32;
                            abs >= first && abs < first + 4 * n as u32
                        }
                        _ => p.0 >= lo && p.0 < hi,
                    };
                    if bit_hit {
                        return Err(Error::new(
                            ErrorKind::State,
                            msg!("k2-input-driven", pin = inputs::pin_name(p), source = s.describe()),
                        )
                        .operand(op.canonical())
                        .hint(match s {
                            Source::Train { .. } | Source::Encoder { .. } => {
                                msg!("k2-input-driven-by-wire-hint", pin = inputs::pin_name(p))
                            }
                            _ => msg!("k2-input-driven-hint", pin = inputs::pin_name(p)),
                        }));
                    }
                }
            }
        }
        Ok(())
    }

    /// Bookkeeping after the user wrote `op`: counter edges, E2PROM wear, SMD38 holds.
    fn after_write(&mut self, op: &K2Operand, raised: &mut Vec<(Duration, EventKind)>) {
        let (lo, hi) = (op.byte, op.byte + op.width.bytes());
        match op.area {
            Area::V => {
                for (byte, writes) in self.backup.count(lo, hi - lo) {
                    raised.push((self.last, EventKind::EepromWear { byte, writes }));
                }
            }
            Area::SM => {
                for h in &mut self.hsc {
                    if lo < h.regs.cv + 4 && h.regs.cv < hi {
                        h.user_cv = true;
                    }
                }
                for p in &self.pto {
                    p.apply_position_bits(&mut self.mem);
                }
            }
            _ => {}
        }
    }

    // ---- channels -------------------------------------------------------------------

    fn pto_index(&self, ch: u8) -> Result<usize> {
        let m = self.model();
        check_pulse_channel(m)?;
        self.pto.iter().position(|p| p.regs.channel == ch).ok_or_else(|| no_pulse_channel(m, ch))
    }

    fn hsc_index(&self, ch: u8) -> Result<usize> {
        let m = self.model();
        self.hsc.iter().position(|h| h.regs.channel == ch).ok_or_else(|| no_counter(m, ch))
    }

    // ---- simulation controls ----------------------------------------------------------

    /// Checks that `pin` is an input of this model.
    pub fn check_input(&self, pin: Pin) -> Result<()> {
        let op = K2Operand::bit(Area::I, pin.0, pin.1);
        self.space.check(&op)
    }

    /// Adds (or replaces) a signal source; returns a description with any counter that
    /// counts it and frequency warnings.
    pub fn add_source(&mut self, s: Source) -> Result<String> {
        for p in s.pins() {
            self.check_input(p)?;
        }
        self.advance();
        let now = self.last;
        let s = match s {
            Source::Freq { pin, wave } => {
                Source::Freq { pin, wave: inputs::Wave { origin_ns: inputs::ns(now), ..wave } }
            }
            Source::Quad { lead, lag, wave } => {
                Source::Quad { lead, lag, wave: inputs::Wave { origin_ns: inputs::ns(now), ..wave } }
            }
            other => other,
        };
        self.inputs.add(s);
        self.refresh_input_levels(inputs::ns(now));
        let mut msg = s.describe();
        for h in &self.hsc {
            let Some(m) = h.mode else { continue };
            let pins: Vec<Pin> = [Some(m.count), m.second].into_iter().flatten().collect();
            if !s.pins().iter().any(|p| pins.contains(p)) {
                continue;
            }
            let quad = m.kind == crate::k2::sm_map::HscKind::Quadrature;
            let max = if quad { h.spec.max_hz_ab } else { h.spec.max_hz_single } as u64;
            msg.push_str("; ");
            msg.push_str(&msg!("k2-input-counted-by", n = h.regs.channel, mode = m.mode));
            if s.hz() > max {
                msg.push_str("; ");
                msg.push_str(&msg!(
                    "k2-input-above-hsc-limit",
                    n = h.regs.channel,
                    max = max,
                    model = self.model().name
                ));
            }
        }
        Ok(msg)
    }

    /// Stops the source driving `pin`; the input keeps its last level.
    pub fn remove_source(&mut self, pin: Pin) -> Result<Source> {
        self.check_input(pin)?;
        self.advance();
        self.inputs.remove(pin).ok_or_else(|| {
            Error::usage(msg!("k2-input-no-source", pin = inputs::pin_name(pin))).hint(msg!("k2-input-no-source-hint"))
        })
    }

    /// The earliest future time at which a channel will raise an event from what runs now.
    pub fn next_event_due(&self) -> Option<Duration> {
        let p = self.pto.iter().filter_map(|p| p.next_due());
        let h = self.hsc.iter().filter_map(|h| h.next_due(&self.inputs, &self.mem, self.last));
        // A wired input changes its formula at the end of its piece: look again then.
        p.chain(h).chain(self.wiring_due()).chain(self.fault_due()).min()
    }

    /// Where stuck and noisy inputs change what a running counter counts: their windows'
    /// ends, and inside a window on a counted input every millisecond (the counter then
    /// counts edge by edge, which the formulas above do not foresee).
    fn fault_due(&self) -> Option<Duration> {
        if self.faults.is_empty() {
            return None;
        }
        let last = inputs::ns(self.last);
        let counted = |p: Pin| self.hsc.iter().any(|h| h.running && h.pins().contains(&p));
        let mut due = None::<u64>;
        for f in &self.faults.list {
            if !f.kind.pin().is_some_and(counted) {
                continue;
            }
            let next = if f.level_at(last).is_some() {
                Some(last + 1_000_000)
            } else {
                [Some(f.from_ns), f.until_ns].into_iter().flatten().filter(|t| *t > last).min()
            };
            due = [due, next].into_iter().flatten().min();
        }
        due.map(Duration::from_nanos)
    }

    /// Battery-retained ranges (`VB0..VB99`, `MB0[10]`, `C0..C15`): V or M byte ranges
    /// and counters, as the hardware configuration offers them ("V, C", manual §2.2.8),
    /// at most the model's retention size in all (§2.1.2 "retention range"; a counter's
    /// current value takes 2 bytes).
    pub fn set_retain(&mut self, text: &str) -> Result<()> {
        let mut ranges = Vec::new();
        if !text.trim().eq_ignore_ascii_case("none") {
            for part in text.split([',', ' ']).filter(|p| !p.is_empty()) {
                let ops = self.space.parse_k2(part)?;
                let area = ops[0].area;
                if !matches!(area, Area::V | Area::M | Area::C) {
                    return Err(Error::usage(msg!("k2-retain-area", part = part)).hint(msg!("k2-retain-area-hint")));
                }
                let first = ops.iter().map(|o| o.byte).min().unwrap_or(0);
                let end =
                    ops.iter().map(|o| o.byte + if area == Area::C { 1 } else { o.width.bytes() }).max().unwrap_or(0);
                ranges.push(Retain { area, first, len: end - first });
            }
        }
        let bytes: u32 = ranges.iter().map(|r| if r.area == Area::C { 2 * r.len } else { r.len }).sum();
        let room = self.model().retentive_bytes;
        if bytes > room {
            return Err(Error::usage(msg!(
                "k2-retain-too-much",
                bytes = bytes,
                model = self.model().name,
                room = room
            ))
            .hint(msg!("k2-retain-too-much-hint")));
        }
        self.backup.retain = ranges;
        // The configuration is kept like the data it protects.
        self.save_state()
    }

    /// Reads the state file (if it has an entry for this model) and restores the backup
    /// area, retained ranges, E2PROM counts and the clock; from then on the simulator
    /// saves there.
    pub fn attach_state(&mut self, path: PathBuf) -> Result<()> {
        let lock = state::lock(&path)?;
        if let Some(st) = state::load(&path, self.model().name)? {
            self.backup.set_last(st.backup_last.clamp(catalog::EEPROM_LAST_DEFAULT, catalog::EEPROM_LAST_MAX))?;
            if let Some(bytes) = state::unhex(&st.backup) {
                let lo = catalog::EEPROM_FIRST as usize;
                let n = bytes.len().min(self.mem.v.len().saturating_sub(lo));
                self.mem.v[lo..lo + n].copy_from_slice(&bytes[..n]);
            }
            for (i, w) in st.eeprom_writes.iter().enumerate().take(self.backup.writes.len()) {
                self.backup.writes[i] = *w;
            }
            self.backup.retain.clear();
            for r in &st.retain {
                let Some(bytes) = state::unhex(&r.data) else { continue };
                if r.area == "C" {
                    let lo = r.first as usize;
                    let values: Vec<i16> = bytes.chunks_exact(2).map(|c| i16::from_be_bytes([c[0], c[1]])).collect();
                    if lo + values.len() <= self.mem.c.len() {
                        self.mem.c[lo..lo + values.len()].copy_from_slice(&values);
                        let len = values.len() as u32;
                        self.backup.retain.push(Retain { area: Area::C, first: r.first, len });
                    }
                    continue;
                }
                let area = if r.area == "M" { Area::M } else { Area::V };
                let buf = self.mem.area_mut(area);
                let lo = r.first as usize;
                if lo + bytes.len() <= buf.len() {
                    buf[lo..lo + bytes.len()].copy_from_slice(&bytes);
                    self.backup.retain.push(Retain { area, first: r.first, len: bytes.len() as u32 });
                }
            }
            if let Some(rtc) = st.rtc {
                let away = unix_now() - rtc.host_unix;
                self.rtc = Rtc::new(RtcTime::from_secs(rtc.civil_secs + away.max(0)), self.last);
            }
        }
        self.backup.path = Some(path);
        self.backup.lock = Some(lock);
        Ok(())
    }

    /// Makes a store to `area` bytes `lo..hi` durable before it is acknowledged: one that
    /// touches the E2PROM backup area or a retained range rewrites the state file (fsync'd,
    /// `state`'s module doc). Other stores cost nothing.
    pub fn commit_store(&mut self, area: Area, lo: u32, hi: u32) -> Result<()> {
        if self.backup.path.is_none() || !self.keeps(area, lo, hi) {
            return Ok(());
        }
        self.save_state()
    }

    /// Does a power cut keep bytes `lo..hi` of `area` (backup area or a retained range)?
    fn keeps(&self, area: Area, lo: u32, hi: u32) -> bool {
        let backup = area == Area::V && lo <= self.backup.last && catalog::EEPROM_FIRST < hi;
        backup || self.backup.retain.iter().any(|r| r.area == area && lo < r.first + r.len && r.first < hi)
    }

    /// Writes the state file now (also done when the simulator is dropped).
    pub fn save_state(&mut self) -> Result<()> {
        let Some(path) = self.backup.path.clone() else { return Ok(()) };
        self.advance();
        let lo = catalog::EEPROM_FIRST as usize;
        let hi = (self.backup.last as usize + 1).min(self.mem.v.len());
        let retain = self
            .backup
            .retain
            .iter()
            .map(|r| {
                let range = r.first as usize..(r.first + r.len) as usize;
                let data = if r.area == Area::C {
                    let bytes: Vec<u8> = self.mem.c[range].iter().flat_map(|v| v.to_be_bytes()).collect();
                    state::hex(&bytes)
                } else {
                    state::hex(&self.mem.area(r.area)[range])
                };
                state::RetainSaved { area: r.area.name().to_string(), first: r.first, data }
            })
            .collect();
        let st = state::ModelState {
            backup_last: self.backup.last,
            backup: state::hex(self.mem.v.get(lo..hi).unwrap_or(&[])),
            eeprom_writes: self.backup.writes.clone(),
            retain,
            rtc: Some(state::RtcSaved { civil_secs: self.rtc.read(self.last).to_secs(), host_unix: unix_now() }),
        };
        state::save(&path, self.model().name, st)
    }
}

fn unix_now() -> i64 {
    std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap_or_default().as_secs() as i64
}

impl Drop for K2Sim {
    fn drop(&mut self) {
        if let Err(e) = self.save_state() {
            eprintln!("plcsh: {}", msg!("k2-state-not-saved", error = e.to_string()));
        }
    }
}

impl K2Sim {
    /// An in-process request fault acting on these operands ([`fault`]): a `no-reply` is the
    /// link error the wire driver reports, an `exception` the PLC refusing. Logged as an event.
    fn injected_fault(&mut self, keys: impl Iterator<Item = u64>) -> Result<()> {
        if self.faults.is_empty() {
            return Ok(());
        }
        let touched: Vec<(Area, u32, u32)> = keys
            .map(|k| {
                let o = K2Operand::from_key(k);
                (o.area, o.byte, o.byte + o.width.bytes().max(1) - 1)
            })
            .collect();
        let now = self.last;
        let Some((id, kind)) = self.faults.on_request(now, &touched, false) else { return Ok(()) };
        self.events.extend(vec![(now, EventKind::Fault { id, fault: kind.code() })]);
        Err(match kind {
            fault::FaultKind::Exception { code } => Error::new(
                ErrorKind::Refused,
                msg!(
                    "k2-fault-exception",
                    code = format!("{code:02X}"),
                    name = crate::k2::modbus_map::exception_name(code),
                    id = id
                ),
            ),
            fault::FaultKind::PowerLoss => {
                Error::link(msg!("k2-fault-no-power", id = id)).hint(msg!("k2-fault-no-power-hint"))
            }
            _ => {
                Error::link(msg!("k2-fault-no-reply", id = id, name = kind.name())).hint(msg!("k2-fault-no-reply-hint"))
            }
        })
    }
}

impl K2Sim {
    /// Removes injected fault `id`, or all, at the current time; returns how many went. An
    /// input a removed fault was holding gets its own level back, as when the fault's
    /// window ends: the level a signal drives it to, or the one it had before.
    pub fn clear_faults(&mut self, id: Option<u32>) -> usize {
        self.advance();
        let (n, held) = self.faults.clear(id);
        let t = inputs::ns(self.last);
        for (p, before) in held {
            let level = match self.inputs.drives(p) {
                Some(_) => {
                    self.refresh_input_levels(t);
                    continue;
                }
                None => before,
            };
            self.drive_input(p, level);
        }
        n
    }
}

impl Device for K2Sim {
    fn info(&self) -> &DeviceInfo {
        &self.info
    }

    fn operands(&self) -> &dyn OperandSpace {
        &self.space
    }

    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        let mut out = Vec::with_capacity(ops.len());
        self.read_into(ops, &mut out)?;
        Ok(out)
    }

    fn read_into(&mut self, ops: &[Operand], out: &mut Vec<Value>) -> Result<()> {
        self.advance();
        self.injected_fault(ops.iter().map(|o| o.key))?;
        out.clear();
        out.extend(ops.iter().map(|o| o.dtype.decode(self.mem.read_key(o.key))));
        Ok(())
    }

    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        for (o, _) in items {
            self.check_writable(&K2Operand::from_key(o.key))?;
        }
        self.advance();
        self.injected_fault(items.iter().map(|(o, _)| o.key))?;
        let old_i = self.mem.i.clone();
        let mut raised = Vec::new();
        let mut durable = false;
        for (o, v) in items {
            let k = K2Operand::from_key(o.key);
            let raw = o.dtype.encode(v);
            self.mem.write(&k, raw);
            self.after_write(&k, &mut raised);
            durable |= self.backup.path.is_some() && self.keeps(k.area, k.byte, k.byte + k.width.bytes().max(1));
        }
        if durable {
            // Acknowledged means kept: the state file holds the store before write returns.
            self.save_state()?;
        }
        if self.mem.i != old_i {
            let now = self.last;
            for h in &mut self.hsc {
                h.input_edges(&mut self.mem, &old_i, now, &mut raised);
            }
        }
        if !raised.is_empty() {
            self.events.extend(raised);
        }
        if self.plc.is_some() && self.mem.i != old_i {
            self.input_edge_interrupts(&old_i);
        }
        self.wired_outputs();
        Ok(())
    }

    /// The K2 operations and simulation controls (`k2::ops`, `k2::simulator`): the simulator
    /// itself permits everything.
    fn family(&mut self, _changes: &[crate::core::device::Change]) -> Result<Option<&mut dyn std::any::Any>> {
        Ok(Some(self))
    }

    /// `state=FILE` (persist there), `backup_last=4095` (E2PROM area end),
    /// `retain=VB0..VB99,MB0[8]` (battery-retained ranges, or `none`).
    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        match key {
            "state" => self.attach_state(PathBuf::from(value)),
            "backup_last" => {
                let n: u32 = value.trim().trim_start_matches(['V', 'B', 'v', 'b']).parse().map_err(|_| {
                    Error::usage(msg!("k2-option-backup-last", value = value)).hint("e.g. backup_last=4095")
                })?;
                self.backup.set_last(n)
            }
            "retain" => self.set_retain(value),
            "program" => {
                let text = crate::core::encoding::read_source(value).map_err(|e| {
                    Error::io(msg!("k2-option-program-unreadable", file = value, error = e.to_string()))
                })?;
                self.load_program(&text, value).map(|_| ())
            }
            _ => Err(Error::usage(msg!("k2-option-unknown", key = key))
                .hint("options: state=FILE, backup_last=3902…4095, retain=RANGES, program=FILE.il")),
        }
    }
}

/// A write to an SM register the CPU owns: SMB0 (system bits) or a position channel's current
/// value SMD212 … (§3.4.3.1). In process and through the helper (`k2::driver`) alike.
pub fn sm_read_only(m: &Model, op: &K2Operand) -> Option<Error> {
    if op.area != Area::SM {
        return None;
    }
    if op.byte == 0 {
        let (msg, hint) = crate::k2::sm_map::smb0_read_only(&op.canonical());
        return Some(Error::new(ErrorKind::Refused, msg).operand(op.canonical()).hint(hint));
    }
    let (lo, hi) = (op.byte, op.byte + op.width.bytes());
    m.pto.iter().map(|p| PTO_REGS[p.channel as usize]).find(|r| lo < r.pos_cv + 4 && r.pos_cv < hi).map(|r| {
        let (msg, hint) = crate::k2::sm_map::pos_cv_read_only(&r, &op.canonical());
        Error::new(ErrorKind::Refused, msg).operand(op.canonical()).hint(hint)
    })
}

/// Refuses pulse channel `ch` on a model with relay outputs (no pulse outputs, §2.2.6).
/// In process and through the helper (`k2::driver`) alike.
pub fn check_pulse_channel(m: &Model) -> Result<()> {
    if m.relay {
        return Err(
            Error::unsupported(msg!("k2-sim-relay-model", model = m.name)).hint(msg!("k2-pto-relay-model-hint"))
        );
    }
    Ok(())
}

/// Pulse channel `ch` is not among the model's (§3.4 tables).
pub fn no_pulse_channel(m: &Model, ch: u8) -> Error {
    if let Err(e) = check_pulse_channel(m) {
        return e;
    }
    let list: Vec<String> = m.pto.iter().map(|p| format!("{} ({})", p.channel, p.output)).collect();
    let m2 = if ch == 3 {
        msg!("k2-sim-no-pulse-channel-q05", model = m.name, channel = ch)
    } else {
        msg!("k2-pto-no-channel", model = m.name, channel = ch)
    };
    Error::unsupported(m2).hint(msg!("k2-sim-pulse-channels-hint", model = m.name, list = list.join(", ")))
}

/// High-speed counter `ch` is not among the model's (§3.3.1 tables).
pub fn no_counter(m: &Model, ch: u8) -> Error {
    let list: Vec<String> = m.hsc.iter().map(|h| format!("HSC{}", h.channel)).collect();
    Error::unsupported(msg!("k2-hsc-no-counter", model = m.name, n = ch)).hint(msg!(
        "k2-hsc-no-counter-hint",
        model = m.name,
        list = list.join(", ")
    ))
}

/// What to try after PLS on channel `r` did nothing ([`pto::did_nothing`]): another channel
/// whose control byte (`others`: registers, outputs, control byte) has the enable bit set is
/// likely the one meant; otherwise set this one's. From the control bytes alone, so the
/// helper path, which reads them back, gives the same hint.
pub fn did_nothing_hint(
    r: &crate::k2::sm_map::PtoRegs,
    others: &[(crate::k2::sm_map::PtoRegs, crate::k2::catalog::PtoSpec, u8)],
) -> String {
    let enabled: Vec<String> = others
        .iter()
        .filter(|(_, _, c)| c & pto::ctl::ENABLE != 0)
        .map(|(o, spec, c)| {
            msg!(
                "k2-pls-other-channel-hint",
                control = o.control,
                value = format!("{c:02X}"),
                channel = o.channel,
                output = spec.output
            )
            .into()
        })
        .collect();
    if enabled.is_empty() {
        msg!("k2-pls-set-control-hint", control = r.control, cycle = r.cycle, count = r.count).into()
    } else {
        enabled.join("; ")
    }
}

impl crate::k2::K2Ops for K2Sim {
    fn model(&self) -> &'static Model {
        self.space.model
    }

    fn pls(&mut self, channel: u8) -> Result<String> {
        let i = self.pto_index(channel)?;
        self.advance();
        let now = self.last;
        let r = self.pto[i].pls(&mut self.mem, now);
        self.wired_outputs();
        match r {
            Err(e) if e.kind == ErrorKind::State => {
                let others: Vec<_> = self
                    .pto
                    .iter()
                    .filter(|p| p.regs.channel != channel)
                    .map(|p| (p.regs, p.spec, self.mem.sm_byte(p.regs.control)))
                    .collect();
                Err(e.hint(did_nothing_hint(&self.pto[i].regs, &others)))
            }
            r => r,
        }
    }

    fn hdef(&mut self, counter: u8, mode: u8) -> Result<String> {
        let i = self.hsc_index(counter)?;
        self.advance();
        self.hsc[i].hdef(mode)
    }

    fn hsc(&mut self, counter: u8) -> Result<String> {
        let i = self.hsc_index(counter)?;
        self.advance();
        self.hsc[i].hsc(&mut self.mem)
    }

    fn pstop(&mut self, channel: u8) -> Result<String> {
        let i = self.pto_index(channel)?;
        self.advance();
        let p = &mut self.pto[i];
        let what = p.pstop(&mut self.mem);
        let r = p.regs;
        self.wired_outputs();
        Ok(msg!(
            "k2-pstop",
            channel = channel,
            what = if what.is_empty() { "none" } else { what },
            byte = r.pos_control
        )
        .into())
    }

    fn read_rtc(&mut self) -> Result<RtcTime> {
        self.advance();
        Ok(self.rtc.read(self.last))
    }

    fn set_rtc(&mut self, t: RtcTime) -> Result<()> {
        t.validate().map_err(Error::usage)?;
        self.advance();
        self.rtc.set(t, self.last);
        Ok(())
    }

    fn events(&mut self, clear: bool) -> Result<Vec<Event>> {
        self.advance();
        let l = self.events.list();
        if clear {
            self.events.clear();
        }
        Ok(l)
    }

    fn take_event(&mut self, m: &EventMatch) -> Result<Option<Event>> {
        self.advance();
        Ok(self.events.take(m))
    }

    fn backup_area(&self) -> (u32, u32) {
        (catalog::EEPROM_FIRST, self.backup.last)
    }

    fn as_sim(&mut self) -> Option<&mut K2Sim> {
        Some(self)
    }
}

/// Opens `sim:MODEL` (or `sim:` for the default model).
pub fn open(model: &str, clock: Clock) -> Result<K2Sim> {
    let name = if model.is_empty() { catalog::DEFAULT_MODEL } else { model };
    Ok(K2Sim::new(catalog::lookup(name)?, clock))
}

#[cfg(test)]
mod behaviour_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicBool;

    fn sim() -> (K2Sim, Clock) {
        let clock = Clock::stepped();
        (open("K205-16DT", clock.clone()).unwrap(), clock)
    }

    fn get(s: &mut K2Sim, text: &str) -> Value {
        let op = s.space().parse(text).unwrap()[0];
        s.read(&[op]).unwrap()[0]
    }

    #[test]
    fn read_into_reads_what_read_reads_into_the_same_buffer() {
        let (mut s, clock) = sim();
        let ops: Vec<Operand> =
            ["VW100", "SMB0", "SMD4", "Q0.0", "VD200"].iter().map(|t| s.space().parse(t).unwrap()[0]).collect();
        let v100 = s.space().parse("VW100").unwrap()[0];
        s.write(&[(v100, Value::Int(1234))]).unwrap();
        let mut buf = vec![Value::Int(99); 20];
        let capacity = buf.capacity();
        for _ in 0..3 {
            clock.step(std::time::Duration::from_millis(1500));
            s.read_into(&ops, &mut buf).unwrap();
            let want = s.read(&ops).unwrap();
            assert_eq!(buf, want, "the same values, and only them");
            assert_eq!(buf.capacity(), capacity, "the buffer is reused");
        }
        assert_eq!(buf[0], Value::Int(1234));
    }

    #[test]
    fn every_model_fits_the_step_buffer() {
        for m in catalog::MODELS {
            assert!(m.pto.len() + m.hsc.len() <= MAX_CHANNELS, "{}", m.name);
        }
    }

    #[test]
    fn system_bits_follow_virtual_time() {
        let (mut s, clock) = sim();
        assert_eq!(get(&mut s, "SM0.0"), Value::Bool(true));
        assert_eq!(get(&mut s, "SM0.1"), Value::Bool(true), "first scan");
        assert_eq!(get(&mut s, "SM0.5"), Value::Bool(true));
        clock.step(Duration::from_millis(1));
        assert_eq!(get(&mut s, "SM0.1"), Value::Bool(false), "after the first scan");
        assert_eq!(get(&mut s, "SM0.6"), Value::Bool(true));
        clock.sleep(Duration::from_millis(499), &AtomicBool::new(false));
        assert_eq!(get(&mut s, "SM0.5"), Value::Bool(false), "SM0.5 off after 0.5 s");
        clock.step(Duration::from_millis(500));
        assert_eq!(get(&mut s, "SM0.5"), Value::Bool(true), "SM0.5 on again after 1 s");
        assert_eq!(get(&mut s, "SM0.0"), Value::Bool(true));
    }

    #[test]
    fn smb0_is_read_only() {
        let (mut s, _) = sim();
        let op = s.space().parse("SM0.1").unwrap()[0];
        let e = s.write(&[(op, Value::Bool(false))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused);
    }

    #[test]
    fn a_refused_batch_writes_nothing() {
        let (mut s, _) = sim();
        let vw = s.space().parse("VW0").unwrap()[0];
        let sm = s.space().parse("SMB0").unwrap()[0];
        assert!(s.write(&[(vw, Value::Int(7)), (sm, Value::Int(0))]).is_err());
        assert_eq!(get(&mut s, "VW0"), Value::Int(0));
    }
}
