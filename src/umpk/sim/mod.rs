//! The simulated UMPK: the PLC side of the terminal protocol (manual §4.1), Intel HEX
//! programming into a simulated flash (§4.2), the modes of §3.2 / Table 2, the real-time
//! monitor (§4.1.11) and the 10 ms cycle (§1), through the same codec the driver uses.
//!
//! Bytes go in with [`Umpk::receive`] and come out of an output queue paced at 57600 baud
//! in virtual time ([`Umpk::take_due`]; in-process, [`Umpk::take_all`]). The pacing is what
//! makes the manual's error 255 observable: a command whose first byte arrives while the
//! previous reply is still being sent is an output-buffer overflow — the code 255 goes
//! into the error history and that command's reply is lost (our reading of §4.1: "can
//! lead to error 255").
//!
//! Modes (§3.2, Table 2): after power-up or reset, Work if a program is loaded, else Wait;
//! `?09F7` enters Programming; reset leaves it, to Work only if programming completed
//! (or the old program was never erased). Outputs are forced off outside Work (§3.4).
//! Availability (Table 6): in Programming mode only reset, echo on/off and controller info
//! are answered; other terminal commands get `U` (the manual lists no reply for them there;
//! in Programming mode the PLC knows programming records, not those commands — our choice).
//! HEX records outside Programming mode get `X`.
//!
//! Programming (§4.2): `:00000002FE` erases and enables; program info 1–22 bytes; data
//! records of at most one 64-byte page, each inside one page, in increasing address order
//! inside the model's memory (`A` otherwise, `L` when longer); `:00000001FF` ends and, if
//! nothing failed, makes the program runnable. Any refusal aborts the sequence: records
//! then get `X` until a new start record. A flash failure (`W`) can be injected for a page.
//!
//! What runs: the stored binary is kept, verified and reported (program info, Work mode),
//! but not executed — the UMPK's language is not published. A [`logic::Runner`] (an IL
//! program, a test's closure) is executed each cycle; see [`logic`].
//!
//! Other choices: the reset takes 0.6 s (§4.1.1), during which received bytes are lost,
//! then `R` CR LF is sent with echo on; the error history survives a reset; stray
//! characters outside a command get `C`, CR/LF/space between commands are ignored, and a
//! `?` or `:` inside an unfinished command abandons it with `C`.

pub mod control;
pub mod logic;
pub mod program;
pub mod reference;
pub mod serve;
pub mod snapshot;
pub mod state;

use super::codec::{
    packet, parse_command, text_packet, Command, Info, Monitor, Parsed, Status, StatusLayout, Timing, Version, BYTE_NS,
    INFO_LEN,
};
use super::hex::{kind, Record};
use super::model::{Model, PAGE};
use crate::core::Clock;
use crate::msg;
use logic::{Image, Logic, Runner, Scan, CYCLE_MS};
use std::collections::VecDeque;
use std::time::Duration;

/// How long a reset keeps the controller silent (§4.1.1: "~0.6 s").
pub const RESET_TIME: Duration = Duration::from_millis(600);
/// The firmware's own share of a cycle in 0.271 µs counts (the simulator's figure: 271 µs).
pub const FIRMWARE_COUNTS: u16 = 1000;
/// Output kept for a reader that does not read (an OS tty buffer's size); monitor packets
/// beyond it are dropped.
pub const OUTPUT_LIMIT: usize = 4096;
/// The firmware version the simulator reports.
pub const VERSION: Version = Version::new(1, 2, 'B');
pub const MICROCODE: u8 = 0x01;

/// The controller's mode (§3.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Work,
    Wait,
    Programming,
    /// Restarting after a reset until the given time.
    Resetting(Duration),
}

impl Mode {
    pub fn name(self) -> &'static str {
        match self {
            Mode::Work => "Work",
            Mode::Wait => "Wait",
            Mode::Programming => "Programming",
            Mode::Resetting(_) => "restarting",
        }
    }
}

/// What the flash holds.
pub enum Program {
    None,
    /// A binary written by Intel HEX programming: stored and reported, not executed.
    Binary,
    /// A program the simulator executes.
    Logic(Box<dyn Runner>),
}

/// The state of a programming sequence (§4.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Programming {
    /// A start record was accepted and nothing failed since.
    enabled: bool,
    /// Next allowed data address.
    next: usize,
}

/// A square wave on an input.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Wave {
    pub input: u8,
    /// Period in cycles (≥ 2).
    pub period: u64,
    /// The cycle it starts in (on for the first half period).
    pub start: u64,
}

/// One simulated UMPK.
pub struct Umpk {
    pub model: &'static Model,
    pub layout: StatusLayout,
    pub clock: Clock,
    mode: Mode,
    echo: bool,
    echo_off_by_command: bool,
    monitor: bool,
    /// Newest first.
    errors: [u8; 8],
    pub flash: Vec<u8>,
    info: [u8; INFO_LEN],
    program: Program,
    prog: Programming,
    pub image: Image,
    pub logic: Logic,
    /// Inputs set by hand (`umpk sim input I3=1`).
    pub forced_inputs: u32,
    pub waves: Vec<Wave>,
    /// Flash page whose write fails (`W`), for tests and labs; set through
    /// [`Umpk::fail_flash_page`], which keeps it inside the program memory.
    flash_fail: Option<usize>,
    /// Injected faults: a silent line, stuck inputs ([`control`]).
    pub faults: crate::core::sim_faults::Faults,
    /// Where the flash, program info and error history are kept ([`state`]).
    pub state_path: Option<std::path::PathBuf>,
    rx: Vec<u8>,
    /// Pending output: byte, virtual time its transmission completes, part of a reply.
    out: VecDeque<(u8, Duration, bool)>,
    line_free: Duration,
    /// The reply of the command being received is lost (error 255).
    lose_reply: bool,
    /// Cycles processed (cycle k covers [k·10 ms, (k+1)·10 ms)).
    cycle: u64,
    program_cycles: u64,
    /// Longest program time seen, in 0.271 µs counts.
    max_program_counts: u16,
    /// Bytes received, commands completed (for tests).
    pub received: u64,
    pub commands: u64,
    /// Binaries programmed to the end (an end record accepted), for the note a server prints.
    pub binaries: u64,
}

impl Umpk {
    /// Makes flash writes to one 64-byte page fail with `W` (§4.2), or none. A page past the
    /// model's program memory (Table 1 row 10) is refused naming the range, rather than kept
    /// as a page no write can reach — or, for a page number near `usize::MAX`, an address
    /// that overflows when shown.
    pub fn fail_flash_page(&mut self, page: Option<usize>) -> crate::core::Result<()> {
        let pages = self.model.program_bytes / PAGE;
        if let Some(p) = page.filter(|&p| p >= pages) {
            return Err(crate::core::Error::usage(msg!(
                "umpk-sim-page-past-end",
                page = p,
                model = self.model.name,
                last = pages - 1,
                bytes = self.model.program_bytes,
                size = PAGE
            ))
            .hint(msg!("umpk-sim-hint-page", last = pages - 1)));
        }
        self.flash_fail = page;
        Ok(())
    }

    /// A controller that has been on for a while: Wait mode (nothing programmed), echo on.
    /// (Its power-up `R` went out before anyone listened; a reset sends one.)
    pub fn new(model: &'static Model, clock: Clock) -> Umpk {
        let now = clock.now();
        let mut u = Umpk {
            model,
            layout: StatusLayout::default(),
            mode: Mode::Wait,
            echo: true,
            echo_off_by_command: false,
            monitor: false,
            errors: [0; 8],
            flash: vec![0xFF; model.program_bytes],
            info: [b' '; INFO_LEN],
            program: Program::None,
            prog: Programming::default(),
            image: Image::default(),
            logic: Logic::new(model.timers, model.counters),
            forced_inputs: 0,
            waves: Vec::new(),
            flash_fail: None,
            faults: crate::core::sim_faults::Faults::default(),
            state_path: None,
            rx: Vec::new(),
            out: VecDeque::new(),
            line_free: now,
            lose_reply: false,
            cycle: now.as_millis() as u64 / CYCLE_MS,
            program_cycles: 0,
            max_program_counts: 0,
            received: 0,
            commands: 0,
            binaries: 0,
            clock,
        };
        u.line_free = now;
        u
    }

    pub fn mode(&self) -> Mode {
        self.mode
    }
    pub fn echo(&self) -> bool {
        self.echo
    }
    pub fn monitor_on(&self) -> bool {
        self.monitor
    }
    pub fn errors(&self) -> [u8; 8] {
        self.errors
    }
    pub fn program_info(&self) -> [u8; INFO_LEN] {
        self.info
    }
    /// What the flash holds, in words.
    pub fn program_kind(&self) -> String {
        match &self.program {
            Program::None => msg!("umpk-sim-program-kind", kind = "none").text,
            Program::Binary => msg!("umpk-sim-program-kind", kind = "binary").text,
            Program::Logic(r) => msg!("umpk-sim-program-logic", program = r.name()).text,
        }
    }

    /// Loads a program the simulator executes, as if it had been programmed: Work mode
    /// (unless the controller is in Programming mode), program info from its name.
    pub fn load_logic(&mut self, runner: Box<dyn Runner>) {
        let mut info = [b' '; INFO_LEN];
        for (d, s) in info.iter_mut().zip(runner.name().bytes().filter(u8::is_ascii)) {
            *d = s;
        }
        self.info = info;
        self.program = Program::Logic(runner);
        self.logic.clear();
        self.image.markers = 0;
        if matches!(self.mode, Mode::Work | Mode::Wait) {
            self.mode = Mode::Work;
        }
        self.program_cycles = 0;
    }

    /// Sets input `i` by hand (until changed); the image shows it at once, the program
    /// sees it from the next cycle.
    pub fn set_input(&mut self, i: u8, on: bool) {
        self.waves.retain(|w| w.input != i);
        self.forced_inputs = self.forced_inputs & !(1 << i) | (on as u32) << i;
        self.refresh_inputs();
    }

    /// The input word of the current cycle: switches, square waves, then stuck inputs.
    fn input_word(&self, at: Duration) -> u32 {
        let mut inputs = self.forced_inputs;
        for w in &self.waves {
            if self.cycle.saturating_sub(w.start) % w.period < w.period / 2 {
                inputs |= 1 << w.input;
            }
        }
        let inputs = self.faults.stuck(at).fold(inputs, |w, (i, on)| w & !(1 << i) | (on as u32) << i);
        inputs & ((1u64 << self.model.inputs) - 1) as u32
    }

    /// Shows a change of switches or stuck inputs in the image at once (the program sees it
    /// from the next cycle).
    pub fn refresh_inputs(&mut self) {
        let now = self.clock.now();
        self.image.inputs = self.input_word(now);
    }

    /// Puts a square wave of `period` cycles on input `i`, starting with the next cycle.
    pub fn set_wave(&mut self, i: u8, period: u64) {
        self.waves.retain(|w| w.input != i);
        self.forced_inputs &= !(1 << i);
        self.waves.push(Wave { input: i, period: period.max(2), start: self.cycle + 1 });
    }

    /// Adds `code` to the error history (newest first).
    pub fn push_error(&mut self, code: u8) {
        self.errors.copy_within(0..7, 1);
        self.errors[0] = code;
        self.persist();
    }

    /// Keeps the flash, program info and error history in `path` from now on, starting from
    /// what it holds (a controller powered up with its program).
    pub fn open_state(&mut self, path: &std::path::Path) -> crate::core::Result<()> {
        state::load(self, path)?;
        self.state_path = Some(path.to_path_buf());
        Ok(())
    }

    /// Writes the durable state, if kept; false if that failed (reported on stderr).
    fn persist(&self) -> bool {
        match &self.state_path {
            None => true,
            Some(p) => match state::save(self, p) {
                Ok(()) => true,
                Err(e) => {
                    eprintln!("simulated UMPK: {e}");
                    false
                }
            },
        }
    }

    fn status(&self, blink: bool) -> u8 {
        self.layout.encode(&Status {
            work: self.mode == Mode::Work,
            errors: self.errors.iter().any(|&e| e != 0),
            monitor: self.monitor,
            echo_off: self.echo_off_by_command,
            programming: self.mode == Mode::Programming,
            blink,
        })
    }

    pub fn controller_info(&self) -> Info {
        Info {
            model: self.model.code,
            version: VERSION,
            inputs: self.model.inputs,
            outputs: self.model.outputs,
            status: self.status(false),
            microcode: MICROCODE,
        }
    }

    pub fn timing(&self) -> Timing {
        Timing { firmware: FIRMWARE_COUNTS, total: FIRMWARE_COUNTS.saturating_add(self.max_program_counts) }
    }

    fn enqueue(&mut self, bytes: &[u8], at: Duration, reply: bool) {
        let mut t = self.line_free.max(at);
        for &b in bytes {
            if !reply && self.out.len() >= OUTPUT_LIMIT {
                return;
            }
            t += Duration::from_nanos(BYTE_NS);
            self.out.push_back((b, t, reply));
        }
        self.line_free = t;
    }

    fn reply(&mut self, body: &[u8], now: Duration) {
        if std::mem::take(&mut self.lose_reply) {
            return;
        }
        let mut r = body.to_vec();
        if self.echo {
            r.extend_from_slice(b"\r\n");
        }
        self.enqueue(&r, now, true);
    }

    /// Runs the cycles up to `now` (and a reset's end).
    pub fn advance(&mut self, now: Duration) {
        let target = now.as_millis() as u64 / CYCLE_MS;
        // Nothing changes from cycle to cycle (no program running, no wave, no monitor, no
        // restart pending): only the last cycle matters, so a long step costs one cycle.
        let running = self.mode == Mode::Work && matches!(self.program, Program::Logic(_));
        let idle = self.waves.is_empty() && !self.monitor && !matches!(self.mode, Mode::Resetting(_)) && !running;
        if idle && target > self.cycle + 1 {
            self.cycle = target - 1;
        }
        while self.cycle < target {
            self.cycle += 1;
            let t = Duration::from_millis(self.cycle * CYCLE_MS);
            if let Mode::Resetting(until) = self.mode {
                if t >= until {
                    self.finish_reset(until);
                }
            }
            self.run_cycle(t);
        }
        if let Mode::Resetting(until) = self.mode {
            if now >= until {
                self.finish_reset(until);
            }
        }
    }

    fn finish_reset(&mut self, at: Duration) {
        self.mode = if matches!(self.program, Program::None) { Mode::Wait } else { Mode::Work };
        self.echo = true;
        self.echo_off_by_command = false;
        self.monitor = false;
        self.prog = Programming::default();
        self.logic.clear();
        self.image.markers = 0;
        self.program_cycles = 0;
        if let Program::Logic(r) = &mut self.program {
            r.restart();
        }
        self.enqueue(b"R\r\n", at, true);
    }

    fn run_cycle(&mut self, t: Duration) {
        self.image.inputs = self.input_word(t);
        let mut ran = false;
        if self.mode == Mode::Work {
            if let Program::Logic(r) = &mut self.program {
                let mut scan = Scan { io: &mut self.image, logic: &mut self.logic, cycle: self.program_cycles };
                r.scan(&mut scan);
                self.max_program_counts = self.max_program_counts.max(r.cost_counts());
                self.program_cycles += 1;
                ran = true;
            }
            // What the cycle reported: codes for the history, a program that stopped (it
            // stays loaded; Wait mode, outputs off, until a reset starts it again).
            for code in std::mem::take(&mut self.logic.raised) {
                self.push_error(code);
            }
            if std::mem::take(&mut self.logic.stopped) {
                self.mode = Mode::Wait;
            }
        }
        if !ran || self.mode != Mode::Work {
            self.image.outputs = 0;
        }
        self.image.outputs &= (1u32 << self.model.outputs) - 1;
        if self.monitor {
            let m = Monitor {
                status: self.status(self.cycle / 25 % 2 == 1),
                inputs: self.image.inputs,
                outputs: self.image.outputs,
                timers: self.image.timers,
                counters: self.image.counters,
                markers: self.image.markers,
            };
            self.enqueue(&m.encode(), t, false);
        }
    }

    /// Bytes from the computer, arriving at the clock's current time.
    pub fn receive(&mut self, bytes: &[u8]) {
        let now = self.clock.now();
        self.advance(now);
        for &b in bytes {
            self.byte(b, now);
        }
    }

    fn byte(&mut self, b: u8, now: Duration) {
        self.received += 1;
        if matches!(self.mode, Mode::Resetting(_)) || self.faults.mute(now) {
            return;
        }
        let starts = b == b'?' || b == b':';
        if starts {
            self.monitor = false;
            // Only reply bytes still on their way count (due later than now).
            if self.out.iter().any(|o| o.2 && o.1 > now) {
                self.push_error(255);
                self.lose_reply = true;
            }
        }
        if self.echo {
            self.enqueue(&[b], now, false);
        }
        if self.rx.is_empty() {
            match b {
                b'?' | b':' => self.rx.push(b),
                b'\r' | b'\n' | b' ' => {}
                _ => self.reply(b"C", now),
            }
            return;
        }
        if starts {
            self.rx.clear();
            let lose = std::mem::take(&mut self.lose_reply);
            self.reply(b"C", now);
            self.lose_reply = lose;
            self.rx.push(b);
            return;
        }
        self.rx.push(b);
        if self.rx[0] == b'?' && self.rx.len() == 5 {
            let cmd: [u8; 5] = self.rx[..5].try_into().expect("five bytes");
            self.rx.clear();
            self.commands += 1;
            self.command(&cmd, now);
        } else if self.rx[0] == b':' && self.rx.len() >= 3 {
            match Record::text_len(&self.rx) {
                None => {
                    self.rx.clear();
                    self.abort_programming();
                    self.reply(b"C", now);
                }
                Some(n) if self.rx.len() == n => {
                    let text = std::mem::take(&mut self.rx);
                    self.commands += 1;
                    self.record(&text, now);
                }
                Some(_) => {}
            }
        }
    }

    fn command(&mut self, cmd: &[u8; 5], now: Duration) {
        let c = match parse_command(cmd) {
            Parsed::Command(c) => c,
            Parsed::Refused(l) => return self.reply(&[l], now),
        };
        if self.mode == Mode::Programming && !c.in_programming() {
            return self.reply(b"U", now);
        }
        match c {
            Command::Reset => {
                self.rx.clear();
                self.lose_reply = false;
                self.monitor = false;
                self.image.outputs = 0;
                self.mode = Mode::Resetting(now + RESET_TIME);
            }
            Command::EchoOn => {
                self.echo = true;
                self.echo_off_by_command = false;
                self.reply(b"R", now);
            }
            Command::EchoOff => {
                self.echo = false;
                self.echo_off_by_command = true;
                self.reply(b"R", now);
            }
            Command::Info => self.reply(&packet(&self.controller_info().data()), now),
            Command::ProgramInfo => {
                let info = if self.mode == Mode::Wait { [b' '; INFO_LEN] } else { self.info };
                self.reply(&text_packet(&info), now)
            }
            Command::Inputs => self.reply(&packet(&self.image.inputs.to_le_bytes()), now),
            Command::Outputs => self.reply(&packet(&self.image.outputs.to_le_bytes()), now),
            Command::Errors => self.reply(&packet(&self.errors), now),
            Command::ClearErrors => {
                self.errors = [0; 8];
                self.persist();
                self.reply(b"R", now)
            }
            Command::Programming => {
                self.mode = Mode::Programming;
                self.prog = Programming::default();
                self.image.outputs = 0;
                self.reply(b"R", now)
            }
            Command::MonitorStart => {
                self.reply(b"R", now);
                self.monitor = true;
            }
            Command::MonitorStop => self.reply(b"R", now),
            Command::Timing => self.reply(&packet(&self.timing().data()), now),
        }
    }

    fn abort_programming(&mut self) {
        self.prog.enabled = false;
    }

    fn refuse_record(&mut self, letter: u8, now: Duration) {
        self.abort_programming();
        self.reply(&[letter], now);
    }

    /// `R` once the change is kept; `W` (the flash write failed) if it could not be.
    fn ack_durable(&mut self, now: Duration) {
        if self.persist() {
            self.reply(b"R", now)
        } else {
            self.refuse_record(b'W', now)
        }
    }

    fn record(&mut self, text: &[u8], now: Duration) {
        let r = match Record::parse(text) {
            Ok(r) => r,
            Err((letter, _)) => return self.refuse_record(letter, now),
        };
        if !matches!(r.kind, kind::DATA | kind::END | kind::START | kind::INFO) {
            return self.refuse_record(b'U', now);
        }
        if self.mode != Mode::Programming {
            return self.reply(b"X", now);
        }
        if r.kind != kind::START && !self.prog.enabled {
            return self.reply(b"X", now);
        }
        match r.kind {
            kind::START => {
                if !r.data.is_empty() {
                    return self.refuse_record(b'L', now);
                }
                self.flash.fill(0xFF);
                self.info = [b' '; INFO_LEN];
                self.program = Program::None;
                self.prog = Programming { enabled: true, next: 0 };
                self.ack_durable(now)
            }
            kind::INFO => {
                if r.data.is_empty() || r.data.len() > INFO_LEN {
                    return self.refuse_record(b'L', now);
                }
                self.info = [b' '; INFO_LEN];
                self.info[..r.data.len()].copy_from_slice(&r.data);
                self.ack_durable(now)
            }
            kind::DATA => {
                if r.data.len() > PAGE {
                    return self.refuse_record(b'L', now);
                }
                let start = r.offset as usize;
                let end = start + r.data.len();
                let one_page = r.data.is_empty() || start / PAGE == (end - 1) / PAGE;
                if start < self.prog.next || end > self.model.program_bytes || !one_page {
                    return self.refuse_record(b'A', now);
                }
                if self.flash_fail == Some(start / PAGE) {
                    return self.refuse_record(b'W', now);
                }
                self.flash[start..end].copy_from_slice(&r.data);
                self.prog.next = end;
                self.ack_durable(now)
            }
            _ => {
                // End (§4.2.2): programming is no longer allowed; the program may run.
                self.prog.enabled = false;
                self.program = Program::Binary;
                self.binaries += 1;
                self.ack_durable(now)
            }
        }
    }

    /// Output whose transmission has completed by the clock's current time.
    pub fn take_due(&mut self) -> Vec<u8> {
        let now = self.clock.now();
        self.advance(now);
        let mut v = Vec::new();
        while let Some(&(b, t, _)) = self.out.front() {
            if t > now {
                break;
            }
            v.push(b);
            self.out.pop_front();
        }
        v
    }

    /// Everything queued (the in-process link does not wait out the baud rate).
    pub fn take_all(&mut self) -> Vec<u8> {
        let now = self.clock.now();
        self.advance(now);
        let v = self.out.iter().map(|o| o.0).collect();
        self.out.clear();
        self.line_free = now;
        v
    }

    /// When the next queued byte completes, or the next cycle starts (for the serve loop).
    pub fn next_event(&self) -> Duration {
        let next_cycle = Duration::from_millis((self.cycle + 1) * CYCLE_MS);
        self.out.front().map_or(next_cycle, |o| o.1.min(next_cycle))
    }
}

/// The monitor's status-word meaning in words, for `umpk info`.
pub fn describe_status(s: &Status) -> Vec<String> {
    [(s.work, "W"), (s.errors, "H"), (s.monitor, "R"), (s.echo_off, "E"), (s.programming, "P"), (s.blink, "T")]
        .into_iter()
        .filter(|(on, _)| *on)
        .map(|(_, flag)| msg!("umpk-status-flag", flag = flag).text)
        .collect()
}

/// What the simulator says when a binary is programmed into it (the shell after `umpk
/// program`, `sim serve` on its standard error), in the current language: it is kept, not run,
/// and what that looks like.
pub fn binary_not_executed() -> crate::core::msg::Msg {
    msg!("umpk-sim-binary-not-executed")
}

#[cfg(test)]
mod tests;
