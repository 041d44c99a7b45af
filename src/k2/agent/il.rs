//! Generates the PLC-side helper program (`lib/k2_agent.il`) from the protocol constants and
//! the counter-mode table, for any mailbox base address: `plcsh agent il --base VB3400`.
//! Generating it keeps the program and the protocol from drifting apart — its refusals
//! are emitted from the same table as [`super::protocol::Command::decode`]'s
//! ([`super::protocol::checks`]) — and spares users hand-editing addresses. The simulator
//! runs this very text (`plcsh sim serve --agent`), and `crate::k2::sim::agent_probe`
//! checks it against the protocol scan by scan.

use super::protocol::{self as p, Command};
use crate::k2::catalog::Model;
use crate::k2::sm_map::{HSC_MODES, HSC_REGS, PTO_REGS};
use std::fmt::Write;

pub use super::protocol::{OFF_SCRATCH, TOTAL_SIZE};

/// The commands (first, last code) whose instruction must see its enable low between two
/// runs: PLS and PSTOP act on a rising edge (K2 manual §3.4.2; PSTOP's EXEC), and HDEF, HSC
/// and SET_RTC, on which the manual is silent, are treated the same way. A request that
/// repeats the last one executed among these waits one scan. READ_RTC is left out: it
/// changes nothing, and a K2 that ran it on the edge only would leave the reply empty (its
/// length is set by the instruction's ENO), which plcsh reports — never a wrong clock.
pub const REPEAT_WAITS: (u16, u16) = (3, 7);

struct Gen {
    model: &'static Model,
    base: u32,
    out: String,
    network: u32,
}

/// An INT literal in the typed form (`INT#3`): the manual writes its constants typed
/// (`DI#100`, `B#16#85`, §3.4.3.1, §3.4.2.3).
fn int(n: impl std::fmt::Display) -> String {
    format!("INT#{n}")
}

/// A WORD literal (`W#16#0103`).
fn word(n: u16) -> String {
    format!("W#16#{n:04X}")
}

impl Gen {
    fn w(&self, off: u32) -> String {
        format!("%VW{}", self.base + off)
    }
    fn b(&self, off: u32) -> String {
        format!("%VB{}", self.base + off)
    }
    /// The one-scan "execute" flag: a request waits and the previous scan executed none.
    /// The request is acknowledged in this scan.
    fn flag(&self) -> String {
        format!("%V{}.0", self.base + OFF_SCRATCH + 12)
    }
    /// "The request is valid": on with the execute flag, off once a check refuses it. It is
    /// the enable of every instruction the helper runs.
    fn valid(&self) -> String {
        format!("%V{}.4", self.base + OFF_SCRATCH + 12)
    }
    /// "The last request executed was one of [`REPEAT_WAITS`] and passed the checks";
    /// [`Self::last`] says which. Changed only when a request executes.
    fn rested(&self) -> String {
        format!("%V{}.5", self.base + OFF_SCRATCH + 12)
    }
    /// "A waiting request repeats that instruction command and waits this scan out": every
    /// instruction's enable is low in this scan, so the repeated one sees a rising edge in
    /// the next. On in one scan per such request (the next scan sees it on and runs it).
    fn hold(&self) -> String {
        format!("%V{}.6", self.base + OFF_SCRATCH + 12)
    }
    /// The last request executed (the low byte of its command code).
    fn last(&self) -> String {
        self.b(OFF_SCRATCH + 13)
    }
    /// The low byte of the request's command word (V is big-endian).
    fn command_low(&self) -> String {
        self.b(p::Field::Command.offset() + 1)
    }
    /// Set when the command's instruction reported success (its ENO).
    fn ok(&self) -> String {
        format!("%V{}.1", self.base + OFF_SCRATCH + 12)
    }
    /// PSTOP's EXEC input, computed per channel.
    fn exec(&self) -> String {
        format!("%V{}.2", self.base + OFF_SCRATCH + 12)
    }
    /// PSTOP's DONE output.
    fn done(&self) -> String {
        format!("%V{}.3", self.base + OFF_SCRATCH + 12)
    }
    /// PSTOP's ERRID output.
    fn errid(&self) -> String {
        self.w(OFF_SCRATCH + 14)
    }
    fn result(&self) -> String {
        self.w(OFF_SCRATCH)
    }
    fn count(&self) -> String {
        self.w(OFF_SCRATCH + 2)
    }
    /// "PLS finds channel `n` disabled and idle" (computed before PLS runs, in the scan
    /// that executes a PLS request; read in the same scan).
    fn idle(&self, n: u8) -> String {
        format!("%V{}.{n}", self.base + OFF_SCRATCH + 5)
    }
    /// Jumps to `label` unless this scan executes a valid request with command `code`: the
    /// networks between read status bits and set results, and hold no instruction.
    fn skip_unless(&mut self, code: u16, label: &str) {
        let cmd = self.w(p::Field::Command.offset());
        self.line("LDW<>", &format!("{cmd}, {}", int(code)), "");
        self.line("ON", &self.valid(), "");
        self.line("JMPC", label, "no instruction in between");
    }
    /// "The request writes SM block `k`" ([`p::sm_blocks`]).
    fn block(&self, k: usize) -> String {
        format!("%V{}.{k}", self.base + OFF_SCRATCH + 4)
    }
    fn net(&mut self, comment: &str) {
        self.network += 1;
        let _ = writeln!(self.out, "\n(* Network {}: {comment} *)", self.network);
    }
    fn line(&mut self, op: &str, args: &str, comment: &str) {
        let code = if args.is_empty() { op.to_string() } else { format!("{op:<7} {args}") };
        if comment.is_empty() {
            let _ = writeln!(self.out, "{code}");
        } else {
            let _ = writeln!(self.out, "{code:<40}(* {comment} *)");
        }
    }
    fn label(&mut self, l: &str) {
        let _ = writeln!(self.out, "{l}:");
    }
    /// `LD valid; AND command == code` — the enable of every command network.
    fn when(&mut self, code: u16) {
        let f = self.valid();
        let cmd = self.w(p::OFF_REQUEST + 4);
        self.line("LD", &f, "");
        self.line("AW=", &format!("{cmd}, {}", int(code)), "");
    }
    fn when_arg(&mut self, code: u16, arg1: u32, arg2: Option<u32>) {
        self.when(code);
        let a1 = self.w(p::OFF_REQUEST + 6);
        self.line("AW=", &format!("{a1}, {}", int(arg1)), "");
        if let Some(a2) = arg2 {
            let a = self.w(p::OFF_REQUEST + 8);
            self.line("AW=", &format!("{a}, {}", int(a2)), "");
        }
    }
    /// `LD` of "the request's command is one of `commands`" (signed compares are exact here:
    /// the codes are small, and a code of 32768 or more, negative as an INT, is in no range).
    fn gate(&mut self, commands: (u16, u16), comment: &str) {
        let cmd = self.w(p::Field::Command.offset());
        match commands {
            (a, b) if a == b => self.line("LDW=", &format!("{cmd}, {}", int(a)), comment),
            (a, b) => {
                self.line("LDW>=", &format!("{cmd}, {}", int(a)), comment);
                self.line("AW<=", &format!("{cmd}, {}", int(b)), "");
            }
        }
    }

    /// The refusals of [`p::checks`], in order: each one that matches a still-valid request
    /// sets the result and clears "valid", so the first match wins and nothing runs; no
    /// jump skips the instruction networks (their enables must see every scan).
    /// The PLC compares words only as signed INTs (S7-200 convention; no unsigned compare),
    /// so "word < lo" with lo ≥ 0 also catches words of 32768 or more, and ARG1 + ARG2 is
    /// computed only after earlier rows bounded both, so the sum cannot overflow an INT.
    fn checks(&mut self) {
        let (result, count, valid) = (self.result(), self.count(), self.valid());
        let rows = p::checks(self.model);
        let mut summed: Option<(u16, u16)> = None;
        for (i, c) in rows.iter().enumerate() {
            let why = format!("{} -> result {}, cause {}", c.why, c.result.code(), i + 1);
            if matches!(c.test, p::Test::EndAbove(_) | p::Test::Overlaps(..) | p::Test::Span(..)) {
                let cmds = c.commands.expect("a sum check names its commands");
                match summed {
                    Some((a, b)) => assert!(a <= cmds.0 && cmds.1 <= b, "check {i}: the sum was computed for {a}…{b}"),
                    None => {
                        let bound = |f: p::Field| {
                            rows[..i]
                                .iter()
                                .filter(|r| r.commands.is_none_or(|(a, b)| a <= cmds.0 && cmds.1 <= b))
                                .filter_map(|r| match r.test {
                                    p::Test::Outside(g, _, hi) if g == f => Some(hi as u32),
                                    _ => None,
                                })
                                .min()
                                .unwrap_or_else(|| panic!("check {i}: {} is not bounded before the sum", f.name()))
                        };
                        let max = bound(p::Field::Arg1) + bound(p::Field::Arg2);
                        assert!(max <= p::INT_MAX as u32, "check {i}: ARG1 + ARG2 can reach {max}, past an INT");
                        let (a1, a2) = (self.w(p::Field::Arg1.offset()), self.w(p::Field::Arg2.offset()));
                        self.gate(cmds, &format!("both bounded: ARG1 + ARG2 <= {max}, no INT overflow"));
                        self.line("A", &valid, "only once the rows above passed");
                        self.line("MOVE", &format!("{a1}, {count}"), "");
                        self.line("ADD", &format!("{a2}, {count}"), "");
                        summed = Some(cmds);
                    }
                }
            }
            let w = |g: &Self, f: p::Field| g.w(f.offset());
            match c.test {
                p::Test::Is(f, v) => {
                    assert!(v <= p::INT_MAX, "check {i}: {v} is not an INT literal");
                    match c.commands {
                        Some(cmds) => self.gate(cmds, &why),
                        None => self.line("LD", "%SM0.0", &why),
                    }
                    self.line("AW=", &format!("{}, {}", w(self, f), int(v)), "");
                }
                p::Test::Outside(f, lo, hi) => {
                    assert!(lo <= hi && hi <= p::INT_MAX, "check {i}: {lo}..{hi} is not within 0..32767");
                    let x = w(self, f);
                    if let Some(cmds) = c.commands {
                        self.gate(cmds, &why);
                        self.line("LDW<", &format!("{x}, {}", int(lo)), "also 32768..65535: negative as an INT");
                        self.line("OW>", &format!("{x}, {}", int(hi)), "");
                        self.line("ALD", "", "");
                    } else {
                        self.line("LDW<", &format!("{x}, {}", int(lo)), &why);
                        self.line("OW>", &format!("{x}, {}", int(hi)), "32768..65535 are negative: caught above");
                    }
                }
                p::Test::EndAbove(l) => {
                    self.gate(c.commands.expect("checked above"), &why);
                    self.line("AW>", &format!("{count}, {}", int(l)), "");
                }
                p::Test::Overlaps(lo, hi) => {
                    self.gate(c.commands.expect("checked above"), &why);
                    self.line("AW<", &format!("{}, {}", w(self, p::Field::Arg1), int(hi)), "");
                    self.line("AW>", &format!("{count}, {}", int(lo)), "");
                }
                p::Test::Always => {
                    self.gate(c.commands.expect("an Always row names its commands"), &why);
                }
                p::Test::Span(lo, hi, end) => {
                    self.gate(c.commands.expect("checked above"), &why);
                    let a1 = w(self, p::Field::Arg1);
                    self.line("AW>=", &format!("{a1}, {}", int(lo)), "");
                    self.line("AW<=", &format!("{a1}, {}", int(hi)), "");
                    self.line("AW>", &format!("{count}, {}", int(end)), "");
                }
            }
            self.line("A", &valid, "");
            self.line("MOVE", &format!("{}, {result}", word(p::result_word(c.result, i as u8 + 1))), "");
            self.line("R", &format!("{valid}, 1"), "refused: nothing runs");
        }
    }
}

/// Why `model` cannot hold the helper at VB`base`, if it cannot (its V area ends before
/// the mailbox does, §2.1.2 "memory area").
pub fn refuse(model: &Model, base: u32) -> Option<String> {
    let end = base + TOTAL_SIZE;
    (end > model.v_bytes).then(|| {
        format!(
            "{} has V bytes VB0…VB{}; the helper's mailbox at VB{base} needs VB{base}…VB{}",
            model.name,
            model.v_bytes - 1,
            end - 1
        )
    })
}

/// The helper program for `model` with its mailbox at VB`base` (even, with TOTAL_SIZE bytes
/// free): only the pulse outputs, counters and counter modes `model` has (manual §3.3.1,
/// §3.4), in the instruction forms of [`super::forms::FORMS`].
pub fn program(model: &'static Model, base: u32) -> String {
    let mut g = Gen { model, base, out: String::new(), network: 0 };
    let end = base + TOTAL_SIZE - 1;
    let list = |manual: bool| {
        let shapes: Vec<String> =
            super::forms::FORMS.iter().filter(|f| f.manual == manual).map(|f| f.shape()).collect();
        let mut lines = vec![String::new()];
        for sh in shapes {
            let last = lines.last_mut().expect("one line");
            if !last.is_empty() && last.len() + sh.len() > 80 {
                lines.push(String::new());
            }
            let last = lines.last_mut().expect("one line");
            if !last.is_empty() {
                last.push_str("; ");
            }
            last.push_str(&sh);
        }
        lines.join("\n     ")
    };
    let (manual, other) = (list(true), list(false));
    let chans = |n: usize, what: &str| match n {
        0 => format!("no {what}"),
        n => format!("{what} 0..{}", n - 1),
    };
    let _ = write!(
        g.out,
        "(* ===================================================================================
   k2_agent.il - the plcsh helper program for a Kinco {model}, mailbox protocol version {ver}.
   Generated by `plcsh agent il --model {model} --base VB{base}` (edit the generator,
   src/k2/agent/il.rs). It runs {pto} and {hsc}
   (manual sections 3.3.1, 3.4): load it only into a {model};
   `plcsh agent il --model MODEL` prints it for another model.

   Once per scan it looks at a mailbox in VB{base}..VB{end} and, when plcsh has left a new
   request there, runs it: write or read SM bytes, PLS, HDEF, HSC, PSTOP, SET_RTC, READ_RTC.
   That gives plcsh the SM registers and instructions the K2 Modbus map does not reach
   (manual section 3.2). The protocol is described in docs/agent.md.

   Status: exercised only against plcsh's simulator, which executes this text in its IL
   engine (`plcsh sim serve --agent`); not yet run on a real K2.
   Forms the K2 manual shows, used as shown there:
     {manual}
   Forms the manual does not show (S7-200/IEC IL as KincoBuilder writes it; each with its
   source and its LD equivalent in docs/agent.md, \"Instruction forms\"):
     {other}
   SM bytes are copied one by one at fixed addresses, only the bytes of the registers the
   manual gives this model (no pointer, no block move).
   If KincoBuilder rejects a line, enter that network in LD with the logic its comment gives.

   Refusals are read where the PLC reports them: after PLS the channel's status bit 4
   (section 3.4.2.2; PLS leaves the CR as it was, section 3.4.2), after PSTOP the
   emergency-stop bit (section 3.4.3.1), after HSC the counter's status bit 3 (section 3.3.2).
   Each result word carries its cause in the high byte (docs/agent.md, Results).

   Every command acts every time it is asked (docs/agent.md, section \"Every command acts
   every time\"): no jump skips an instruction, so PLS and PSTOP, which act on the rising
   edge of their enable (manual section 3.4.2), see it fall on every scan without a request;
   and a request that repeats the instruction command of the request executed before it waits
   one scan, so an instruction's enable is low for at least one scan between two executions.

   Network 3 refuses malformed requests before anything runs (docs/agent.md, section Checks).
   Word compares are signed INT compares, so each `word < bound` test also catches the
   words 32768..65535, and ARG1 + ARG2 is added only after both are bounded: no request
   makes this program address memory outside SMB0..SMB{sm_last} or stop the CPU.

   Install in KincoBuilder:
     1. Add a subroutine PLCSH_AGENT, language IL; paste this file into it.
     2. In the main program add a network:  LD %SM0.0 / CAL PLCSH_AGENT  (every scan).
     3. Keep VB{base}..VB{end} free for the mailbox (below the E2PROM area VB3648).
     4. Download, RUN; connect with  tcp://PLC:502?model={model}&agent=VB{base}
        (or rtu:...&model={model}&agent=VB{base}).
   =================================================================================== *)
",
        model = model.name,
        ver = p::VERSION,
        pto = chans(model.pto.len(), "pulse outputs"),
        hsc = chans(model.hsc.len(), "high-speed counters"),
        manual = manual,
        other = other,
        sm_last = p::sm_end() - 1,
    );
    let (result, flag) = (g.result(), g.flag());
    g.net("announce the helper: signature, version, heartbeat (every scan)");
    g.line("LD", "%SM0.0", "");
    g.line("MOVE", &format!("{}, {}", word(p::SIGNATURE), g.w(p::OFF_SIGNATURE)), "\"KA\"");
    g.line("MOVE", &format!("{}, {}", word(p::VERSION), g.w(p::OFF_VERSION)), "protocol version");
    g.line("ADD", &format!("{}, {}", int(1), g.w(p::OFF_HEARTBEAT)), "heartbeat");

    let (valid, rested, hold, last, cmd_low) = (g.valid(), g.rested(), g.hold(), g.last(), g.command_low());
    let waiting = format!("{}, {}", g.w(p::OFF_REQUEST), g.w(p::OFF_ACKS));
    g.net("a new request waits when the request sequence differs from ack 0; one that repeats the last instruction command waits a scan first");
    g.line("LDW<>", &waiting, "");
    g.line("A", &rested, "the last request executed was an instruction command");
    g.line("AB=", &format!("{cmd_low}, {last}"), "and this one names the same command");
    g.line("AN", &hold, "and has not waited yet");
    g.line("ST", &hold, "so it waits this scan, with every enable low");
    g.line("LDW<>", &waiting, "");
    g.line("AN", &hold, "");
    g.line("ST", &flag, "execute (and acknowledge) this scan");
    g.line("ST", &valid, "valid until a check below refuses it");
    g.line("LD", &flag, "");
    g.line("MOVE", &format!("{}, {result}", word(0)), "result 0 = done");
    g.line("MOVE", &format!("{}, {}", word(0), g.w(p::OFF_REPLY_LEN)), "no reply data yet");

    let a1 = g.w(p::OFF_REQUEST + 6);
    g.net("refuse malformed requests: the checks of docs/agent.md, in order, over unsigned words");
    g.line("LDN", &flag, "");
    g.line("JMPC", "CHECKED", "no request executes: nothing to check (no instruction is skipped)");
    g.checks();
    g.label("CHECKED");

    g.net(&format!(
        "remember the request this scan executes, and whether it runs an instruction that needs a rising edge (commands {}..{})",
        REPEAT_WAITS.0, REPEAT_WAITS.1
    ));
    g.line("LD", &flag, "");
    g.line("R", &format!("{rested}, 1"), "");
    g.line("MOVE", &format!("{cmd_low}, {last}"), "");
    g.gate(REPEAT_WAITS, "");
    g.line("A", &valid, "");
    g.line("S", &format!("{rested}, 1"), "read by network 2 when the next request waits");

    let rows = p::sm_rows(model);
    let read_only: Vec<u32> = PTO_REGS
        .iter()
        .filter(|r| model.pto(r.channel).is_some())
        .flat_map(|r| r.pos_cv..r.pos_cv + 4)
        .chain([0])
        .collect();
    let count = g.count();
    g.net("SM copies: skipped on scans that execute no valid request (the jump passes over no instruction)");
    g.line("LDN", &valid, "");
    g.line("JMPC", "SM_DONE", "");

    g.net("command 1: request data -> SM, byte by byte at fixed addresses: SMB(b) from data byte b - its block's first byte, for ARG1 <= b < ARG1 + ARG2; only the registers the manual gives this model");
    for (k, &(s0, e0)) in p::sm_blocks().iter().enumerate() {
        g.when(Command::SmWrite { start: 0, data: vec![] }.code());
        g.line("AW>=", &format!("{a1}, {}", int(s0)), "");
        g.line("AW<=", &format!("{a1}, {}", int(e0 - 1)), "");
        g.line("ST", &g.block(k), &format!("writes block SMB{s0}..SMB{}", e0 - 1));
        for b in rows.iter().copied().filter(|b| (s0..e0).contains(b) && !read_only.contains(b)) {
            g.line("LD", &g.block(k), "");
            g.line("AW<=", &format!("{a1}, {}", int(b)), "");
            g.line("AW>", &format!("{count}, {}", int(b)), "");
            g.line("MOVE", &format!("{}, %SMB{b}", g.b(p::OFF_REQ_DATA + b - s0)), "");
        }
    }

    g.net("command 2: SM -> reply, the whole block ARG1 lies in, byte by byte at fixed addresses: SMB(b) to reply byte b - the block's first byte");
    for &(s0, e0) in &p::sm_blocks() {
        g.when(Command::SmRead { start: 0, len: 0 }.code());
        g.line("AW>=", &format!("{a1}, {}", int(s0)), "");
        g.line("AW<=", &format!("{a1}, {}", int(e0 - 1)), &format!("block SMB{s0}..SMB{}", e0 - 1));
        for b in rows.iter().copied().filter(|b| (s0..e0).contains(b)) {
            g.line("MOVE", &format!("%SMB{b}, {}", g.b(p::OFF_REPLY + b - s0)), "");
        }
        g.line("MOVE", &format!("{}, {}", word(p::DATA_MAX as u16), g.w(p::OFF_REPLY_LEN)), "the whole block");
    }
    g.label("SM_DONE");

    let ok = g.ok();
    let status = |cause: p::StatusCause| word(p::result_word(p::ResultCode::StatusBit, cause as u8));
    let ptos: Vec<_> = PTO_REGS.iter().filter(|r| model.pto(r.channel).is_some()).collect();
    let hscs: Vec<_> = HSC_REGS.iter().filter(|r| model.hsc(r.channel).is_some()).collect();

    g.net("the instruction's ENO, set by the network that runs it (HDEF, HSC, SET_RTC)");
    g.line("LD", "%SM0.0", "");
    g.line("R", &format!("{ok}, 1"), "set below by the instruction's ENO");

    let a1 = g.w(p::Field::Arg1.offset());
    g.net("command 3, before PLS: is the channel disabled and idle, so that PLS will have nothing to do? (section 3.4.2.2: enable bit 7 of the control byte, idle bits 7 and 3 of the status byte)");
    g.skip_unless(Command::Pls(0).code(), "PLS_READY");
    for r in &ptos {
        g.line("LDW=", &format!("{a1}, {}", int(r.channel)), "");
        g.line("AN", &format!("%SM{}.7", r.control), "enable bit clear");
        g.line("A", &format!("%SM{}.7", r.status), "PTO idle");
        g.line("A", &format!("%SM{}.3", r.status), "PWM idle");
        g.line("ST", &g.idle(r.channel), "");
    }
    g.label("PLS_READY");

    g.net("command 3: PLS ARG1 - evaluated every scan: its enable is on in the request's scan only, a rising edge each time (section 3.4.2)");
    for r in &ptos {
        g.when_arg(Command::Pls(0).code(), r.channel as u32, None);
        g.line("R", &format!("%SM{}.4, 1", r.status), "a bit left by an earlier refusal is not this PLS's");
        g.line("PLS", &r.channel.to_string(), "leaves the CR as it was (section 3.4.2)");
    }

    g.net("command 3, after PLS: its verdict is the channel's status bit 4, cycle time or pulse count invalid (section 3.4.2.2), as PLS leaves the CR as it was");
    g.skip_unless(Command::Pls(0).code(), "PLS_DONE");
    for r in &ptos {
        g.line("LDW=", &format!("{a1}, {}", int(r.channel)), "");
        g.line("A", &format!("%SM{}.4", r.status), "");
        g.line("MOVE", &format!("{}, {result}", status(p::StatusCause::PtoInvalid)), "result 8, cause 1: status bit 4");
        g.line("LD", &g.idle(r.channel), "");
        g.line(
            "MOVE",
            &format!("{}, {result}", status(p::StatusCause::NothingToDo)),
            "result 8, cause 4: nothing to do",
        );
    }
    g.label("PLS_DONE");

    g.net("command 4: HDEF ARG1, ARG2 - one line per counter and mode of section 3.3.1 on this model; the manual names no status for HDEF: its ENO is read");
    for &(hsc, mode, what) in HSC_MODES.iter().filter(|m| model.hsc(m.0).is_some()) {
        g.when_arg(Command::Hdef { hsc: 0, mode: 0 }.code(), hsc as u32, Some(mode as u32));
        g.line("HDEF", &format!("{hsc}, {mode}"), &what(crate::core::msg::Lang::En));
        g.line("S", &format!("{ok}, 1"), "");
    }
    g.when(Command::Hdef { hsc: 0, mode: 0 }.code());
    g.line("AN", &ok, "no line matched: not a mode of this counter");
    g.line("MOVE", &format!("{}, {result}", word(p::ResultCode::BadMode.code())), "");

    g.net("command 5: HSC ARG1 - its ENO, then the counter's status bit 3, multi-PV table fault (section 3.3.2)");
    for r in &hscs {
        g.when_arg(Command::Hsc(0).code(), r.channel as u32, None);
        g.line("HSC", &r.channel.to_string(), "");
        g.line("S", &format!("{ok}, 1"), "");
    }
    g.when(Command::Hsc(0).code());
    g.line("AN", &ok, "");
    g.line("MOVE", &format!("{}, {result}", word(p::ResultCode::InstructionFailed.code())), "");
    g.skip_unless(Command::Hsc(0).code(), "HSC_DONE");
    for r in &hscs {
        g.line("LDW=", &format!("{a1}, {}", int(r.channel)), "");
        g.line("A", &format!("%SM{}.3", r.status), "fault in the multi-PV table (section 3.3.2)");
        g.line("MOVE", &format!("{}, {result}", status(p::StatusCause::PvTable)), "result 8, cause 3");
    }
    g.label("HSC_DONE");

    g.net("command 6: PSTOP ARG1 - stop the channel and latch its emergency-stop bit (section 3.4.3.1); runs every scan, acts on EXEC's rising edge; the latch is its verdict");
    let (exec, done, errid) = (g.exec(), g.done(), g.errid());
    for r in &ptos {
        g.when_arg(Command::Pstop(0).code(), r.channel as u32, None);
        g.line("ST", &exec, "EXEC: on in this request's scan only");
        g.line("LD", "%SM0.0", "");
        g.line("PSTOP", &format!("{}, {exec}, {done}, {errid}", r.channel), "AXIS, EXEC, DONE, ERRID");
    }
    g.skip_unless(Command::Pstop(0).code(), "PSTOP_DONE");
    for r in &ptos {
        g.line("LDW=", &format!("{a1}, {}", int(r.channel)), "");
        g.line("AN", &format!("%SM{}.7", r.pos_control), "PSTOP sets it (section 3.4.3.1)");
        g.line("MOVE", &format!("{}, {result}", status(p::StatusCause::NotLatched)), "result 8, cause 2");
    }
    g.label("PSTOP_DONE");

    g.net("commands 7 and 8: SET_RTC from the request data, READ_RTC into the reply; the manual names no status for them: SET_RTC's ENO is read");
    g.when(Command::SetRtc([0; 8]).code());
    g.line("SET_RTC", &g.b(p::OFF_REQ_DATA), "8 bytes BCD: yy mm dd hh mm ss 00 weekday");
    g.line("S", &format!("{ok}, 1"), "");
    g.when(Command::SetRtc([0; 8]).code());
    g.line("AN", &ok, "");
    g.line("MOVE", &format!("{}, {result}", word(p::ResultCode::BadClock.code())), "not a valid date and time");
    g.when(Command::ReadRtc.code());
    g.line("READ_RTC", &g.b(p::OFF_REPLY), "");
    g.line("MOVE", &format!("{}, {}", word(8), g.w(p::OFF_REPLY_LEN)), "");

    g.net("acknowledge: shift acks 0-2 to 1-3 word by word, then ack 0 = (sequence, token, result), sequence last");
    g.line("LDN", &flag, "");
    g.line("JMPC", "ACKED", "no request executed: nothing to acknowledge (no instruction in between)");
    g.line("LD", &flag, "");
    for k in (0..9u32).rev() {
        let what = format!("ack {} -> ack {}", k / 3, k / 3 + 1);
        g.line("MOVE", &format!("{}, {}", g.w(p::OFF_ACKS + 2 * k), g.w(p::OFF_ACKS + 6 + 2 * k)), &what);
    }
    g.line("MOVE", &format!("{}, {}", g.w(p::OFF_REQUEST + 2), g.w(p::OFF_ACKS + 2)), "token");
    g.line("MOVE", &format!("{result}, {}", g.w(p::OFF_ACKS + 4)), "result");
    g.line("MOVE", &format!("{}, {}", g.w(p::OFF_REQUEST), g.w(p::OFF_ACKS)), "sequence: the ack is complete");
    g.label("ACKED");
    g.out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn default_model() -> &'static Model {
        crate::k2::catalog::lookup(crate::k2::catalog::DEFAULT_MODEL).unwrap()
    }

    #[test]
    fn the_committed_program_is_current() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/lib/k2_agent.il");
        let want = program(default_model(), p::DEFAULT_BASE);
        if std::env::var_os("PLCSH_BLESS").is_some() {
            std::fs::write(path, &want).unwrap();
        }
        let have = std::fs::read_to_string(path).unwrap_or_default();
        assert!(
            have == want,
            "lib/k2_agent.il is stale: run `cargo run -- agent il > lib/k2_agent.il` (the default model) or PLCSH_BLESS=1 cargo test"
        );
    }

    #[test]
    fn every_counter_mode_and_address_is_relocated() {
        let k209m = crate::k2::catalog::lookup("K209M-56DT").unwrap();
        let il = program(k209m, 2000);
        for &(hsc, mode, _) in HSC_MODES.iter().filter(|m| k209m.hsc(m.0).is_some()) {
            assert!(il.contains(&format!("HDEF    {hsc}, {mode}")), "HDEF {hsc}, {mode}");
        }
        assert!(il.contains("%VW2000"), "signature at the base");
        assert!(!il.contains("%VW3400"), "no default address left");
        assert!(il.contains("PSTOP   3, "), "PSTOP of channel 3");
        assert!(!il.contains("HDEF    2, "), "the K209M has no HSC2 (section 3.3)");
        assert!(!il.contains('…'), "no elisions");
    }

    #[test]
    fn every_check_refuses_before_any_command_runs() {
        let il = program(default_model(), p::DEFAULT_BASE);
        let (checks, first_command) = (il.find("(* Network 3:").unwrap(), il.find("(* Network 4:").unwrap());
        let net = &il[checks..first_command];
        let rows = p::checks(default_model());
        let refusal = format!("R       %V{}.4, 1", p::DEFAULT_BASE + OFF_SCRATCH + 12);
        assert_eq!(net.matches(&refusal).count(), rows.len(), "one refusal per row of the table");
        for (i, c) in rows.iter().enumerate() {
            assert!(net.contains(&format!("{} -> result {}, cause {}", c.why, c.result.code(), i + 1)), "{}", c.why);
        }
        // Only INT literals: the PLC's word compares are signed.
        for line in il.lines().filter(|l| l.starts_with("LDW") || l.starts_with("AW") || l.starts_with("OW")) {
            let lit = line.rsplit(", ").next().unwrap().split_whitespace().next().unwrap().trim_start_matches("INT#");
            if let Ok(n) = lit.parse::<i64>() {
                assert!((0..=32767).contains(&n), "{line}");
            }
        }
    }

    /// The PLC instructions the helper runs (K2 manual §3.3, §3.4, §2.2.10).
    const INSTRUCTIONS: [&str; 6] = ["PLS", "HDEF", "HSC", "PSTOP", "SET_RTC", "READ_RTC"];

    /// No jump lands past an instruction: every instruction line is evaluated on every scan,
    /// so an edge-triggered one (PLS, PSTOP's EXEC) sees its enable fall between requests.
    #[test]
    fn no_jump_skips_an_instruction() {
        let il = program(default_model(), p::DEFAULT_BASE);
        let lines: Vec<&str> = il.lines().collect();
        let op = |l: &str| l.split_whitespace().next().unwrap_or("").to_string();
        let mut jumps = 0;
        for (i, l) in lines.iter().enumerate() {
            if !matches!(op(l).as_str(), "JMP" | "JMPC" | "JMPCN") {
                continue;
            }
            jumps += 1;
            let target = l.split_whitespace().nth(1).unwrap();
            let at = lines.iter().position(|x| *x == format!("{target}:")).unwrap_or_else(|| panic!("{l}: no label"));
            let (lo, hi) = if at > i { (i, at) } else { (at, i) };
            for skipped in &lines[lo..hi] {
                assert!(!INSTRUCTIONS.contains(&op(skipped).as_str()), "`{l}` jumps over `{skipped}`");
            }
        }
        assert!(jumps >= 2, "past the checks and past the SM copies, at least");
        for name in INSTRUCTIONS {
            assert!(lines.iter().any(|l| op(l) == name), "{name} is in the program");
        }
    }

    /// Every instruction's enable starts with the "valid" bit (on in a request's scan only)
    /// and the command's code.
    #[test]
    fn every_instruction_is_enabled_by_the_one_scan_valid_bit() {
        let base = p::DEFAULT_BASE;
        let text = program(default_model(), base);
        let il = &text[text.find("(* Network 1:").unwrap()..];
        let valid = Gen { model: default_model(), base, out: String::new(), network: 0 }.valid();
        let lines: Vec<&str> = il.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let name = l.split_whitespace().next().unwrap_or("");
            if !INSTRUCTIONS.contains(&name) {
                continue;
            }
            // The rung that enables it: back to its LD (PSTOP: the rung that computes EXEC).
            let mut k = i;
            let mut skip_sm0 = name == "PSTOP";
            loop {
                k -= 1;
                if lines[k].starts_with("LD ") {
                    if skip_sm0 && lines[k].contains("%SM0.0") {
                        skip_sm0 = false;
                        continue;
                    }
                    break;
                }
            }
            assert!(lines[k].contains(&valid), "{l}: enabled by `{}`, not by the valid bit", lines[k]);
            let cmd = format!("AW=     %VW{}, ", base + p::Field::Command.offset());
            assert!(lines[k + 1].starts_with(&cmd), "{l}: its enable names no command: `{}`", lines[k + 1]);
        }
    }

    use crate::k2::sim::agent_probe::AgentProbe;

    /// Request data holding `bytes` (the rest zero).
    fn data(bytes: &[u8]) -> [u8; p::DATA_MAX] {
        let mut d = [0; p::DATA_MAX];
        d[..bytes.len()].copy_from_slice(bytes);
        d
    }

    /// Sends one request through the probe (every scan checked against the protocol).
    fn ask(probe: &mut AgentProbe, code: u16, args: [u16; 2], bytes: &[u8]) -> p::ResultCode {
        // An SM write's bytes travel at their place in the SM block (docs/agent.md).
        let off = if code == 1 { (args[0] as u32 - p::block_of(args[0] as u32).0) as usize } else { 0 };
        let mut shifted = vec![0; off];
        shifted.extend_from_slice(bytes);
        probe.request(code, [args[0], args[1], 0], &data(&shifted)).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The channels the probe's model has (K205-16DT).
    fn channels(probe: &AgentProbe) -> Vec<&'static crate::k2::sm_map::PtoRegs> {
        PTO_REGS.iter().filter(|r| probe.sim.model().pto.iter().any(|c| c.channel == r.channel)).collect()
    }

    /// Scans until channel `r`'s PTO is idle (SM66.7 …), at most `limit` scans.
    fn until_idle(probe: &mut AgentProbe, r: &crate::k2::sm_map::PtoRegs, limit: u32) {
        for _ in 0..limit {
            if probe.sim.mem.sm_bit(r.status, 7) {
                return;
            }
            probe.scan();
        }
        panic!("PTO{} still busy after {limit} scans", r.channel);
    }

    /// PLS acts on its enable's rising edge (K2 manual §3.4.2): a second PLS of the same
    /// channel — after the first train ended, with or without an SM write in between —
    /// starts a second train. Returns SMD212 … of every channel after two trains of 100
    /// pulses each.
    fn pls_twice(probe: &mut AgentProbe, write_between: bool) -> Vec<u32> {
        let mut out = Vec::new();
        for r in channels(probe) {
            // SMB67 = 16#85, SMW68 = 100 (µs), SMD72 = 100 (§3.4.2.3) in one SM write.
            let cfg = [0x85, 0, 100, 0, 0, 0, 0, 0, 100];
            assert_eq!(ask(probe, 1, [r.control as u16, cfg.len() as u16], &cfg), p::ResultCode::Ok);
            assert_eq!(ask(probe, 3, [r.channel as u16, 0], &[]), p::ResultCode::Ok);
            until_idle(probe, r, 100);
            if write_between {
                assert_eq!(ask(probe, 1, [r.control as u16, 1], &[0x85]), p::ResultCode::Ok);
            }
            assert_eq!(ask(probe, 3, [r.channel as u16, 0], &[]), p::ResultCode::Ok);
            until_idle(probe, r, 100);
            out.push(probe.sim.mem.sm_dword(r.pos_cv));
        }
        out
    }

    #[test]
    fn pls_starts_a_train_every_time_it_is_asked() {
        let mut probe = AgentProbe::new();
        let chans = channels(&probe);
        assert!(chans.len() >= 2, "the model has pulse channels");
        assert_eq!(pls_twice(&mut probe, false), vec![200; chans.len()], "SMD212 … count both trains");
        assert_eq!(pls_twice(&mut probe, true), vec![400; chans.len()], "and with an SM write between");
        // Back to back: PLS right after PLS (the second waits one scan, enable low).
        for r in chans {
            let before = probe.sim.mem.sm_dword(r.pos_cv);
            assert_eq!(ask(&mut probe, 3, [r.channel as u16, 0], &[]), p::ResultCode::Ok);
            assert_eq!(ask(&mut probe, 3, [r.channel as u16, 0], &[]), p::ResultCode::Ok);
            until_idle(&mut probe, r, 100);
            let after = probe.sim.mem.sm_dword(r.pos_cv);
            // The second PLS restarts the running train (pulses already out stay counted):
            // more than one train's 100 pulses, at most two trains' worth.
            assert!(after - before > 100 && after - before <= 200, "PTO{}: {before} -> {after}", r.channel);
        }
    }

    #[test]
    fn pstop_latches_its_bit_every_time_it_is_asked() {
        let mut probe = AgentProbe::new();
        for r in channels(&probe) {
            for round in 0..3 {
                assert_eq!(ask(&mut probe, 6, [r.channel as u16, 0], &[]), p::ResultCode::Ok);
                assert!(
                    probe.sim.mem.sm_bit(r.pos_control, 7),
                    "PSTOP {} round {round}: SM{}.7",
                    r.channel,
                    r.pos_control
                );
                // The program clears it (§3.4.3.1): an SM write, then PSTOP again.
                assert_eq!(ask(&mut probe, 1, [r.pos_control as u16, 1], &[0]), p::ResultCode::Ok);
                assert!(!probe.sim.mem.sm_bit(r.pos_control, 7));
            }
        }
    }

    /// A request that repeats the instruction command of the request executed before it
    /// (right before, or scans before) waits one scan, so that instruction's enable is low
    /// in between; any other request runs in the scan that sees it.
    #[test]
    fn a_repeated_instruction_command_waits_one_scan() {
        let mut probe = AgentProbe::new();
        let write = |probe: &mut AgentProbe, seq: u16, cmd: &Command| {
            let base = (p::DEFAULT_BASE + p::OFF_REQUEST) as usize;
            for (k, w) in p::request_words(seq, 7, cmd).iter().enumerate() {
                probe.sim.mem.v[base + 2 * k..base + 2 * k + 2].copy_from_slice(&w.to_be_bytes());
            }
        };
        let ack0 = |probe: &AgentProbe| probe.status().acks[0].seq;
        // (request, idle scans before it is written, scans until its ack).
        let cases = [
            (Command::ReadRtc, 0, 1),
            (Command::ReadRtc, 0, 1),
            (Command::SetRtc([0x26, 0x13, 1, 0, 0, 0, 0, 1]), 0, 1),
            (Command::SetRtc([0x26, 0x11, 1, 0, 0, 0, 0, 1]), 0, 2),
            (Command::SmRead { start: 66, len: 1 }, 0, 1),
            (Command::Pls(0), 0, 1),
            (Command::Pls(1), 0, 2),
            (Command::Pls(1), 5, 2),
            (Command::Pstop(1), 0, 1),
            (Command::Pstop(1), 0, 2),
            (Command::Hsc(9), 0, 1),
            (Command::Hsc(0), 0, 1),
            (Command::Ping, 0, 1),
            (Command::Ping, 0, 1),
            (Command::SmWrite { start: 67, data: vec![0x85] }, 0, 1),
            (Command::SmWrite { start: 67, data: vec![0x85] }, 0, 1),
        ];
        for (seq, (cmd, idle, scans)) in (1..).zip(cases) {
            for _ in 0..idle {
                probe.scan();
            }
            write(&mut probe, seq, &cmd);
            for k in 1..scans {
                probe.scan();
                assert_eq!(ack0(&probe), seq - 1, "{cmd:?}: not acknowledged in scan {k}");
            }
            probe.scan();
            assert_eq!(ack0(&probe), seq, "{cmd:?}: acknowledged in scan {scans}");
        }
    }

    /// The probe fails a helper that jumps over its instruction networks on scans without
    /// a request (the program as it was before): the second PLS never sees its enable fall.
    #[test]
    fn the_probe_catches_a_helper_that_jumps_over_its_instructions() {
        let il = program(default_model(), p::DEFAULT_BASE);
        let g = Gen { model: default_model(), base: p::DEFAULT_BASE, out: String::new(), network: 0 };
        let flag = g.flag();
        // A jump over the command networks to the end on scans without a request.
        let jumping =
            il.replace("\n(* Network 5:", &format!("LDN     {flag}\nJMPC    DONE\n\n(* Network 5:")) + "DONE:\n";
        assert_ne!(jumping, il);
        let mut probe = AgentProbe::new();
        probe.sim.load_helper(&jumping, "jumping.il").unwrap();
        let n = channels(&probe).len();
        assert_eq!(pls_twice(&mut probe, false), vec![100; n], "the second PLS is acknowledged but runs no train");
    }

    /// A model whose V area cannot hold the mailbox is refused, naming its last V byte.
    #[test]
    fn a_model_without_the_v_bytes_is_refused() {
        let mut small = *default_model();
        small.v_bytes = 2048;
        let m = refuse(&small, p::DEFAULT_BASE).expect("refused");
        assert!(m.contains("VB0…VB2047") && m.contains("VB3400…VB3587"), "{m}");
        assert!(refuse(default_model(), p::DEFAULT_BASE).is_none());
    }

    #[test]
    fn the_scratch_area_stays_below_the_backup_area() {
        const { assert!(p::DEFAULT_BASE + TOTAL_SIZE <= crate::k2::catalog::EEPROM_FIRST) };
    }
}
