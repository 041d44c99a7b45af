//! Generates the PLC-side helper program (`lib/k2_agent.il`) from the protocol constants and
//! the counter-mode table, for any mailbox base address: `plcsh agent il --base VB3400`.
//! Generating it keeps the program and the protocol from drifting apart — its refusals
//! are emitted from the same table as [`super::protocol::Command::decode`]'s
//! ([`super::protocol::checks`]) — and spares users hand-editing addresses. The simulator
//! runs this very text (`plcsh sim serve --agent`), and `crate::k2::sim::agent_probe`
//! checks it against the protocol scan by scan.

use super::protocol::{self as p, Command};
use crate::k2::sm_map::{HSC_MODES, PTO_REGS};
use std::fmt::Write;

/// Scratch words the program uses, right after the client-visible block.
pub const OFF_SCRATCH: u32 = p::SIZE;
/// Bytes the program needs in all (mailbox + scratch).
pub const TOTAL_SIZE: u32 = p::SIZE + 16;

struct Gen {
    base: u32,
    out: String,
    network: u32,
}

impl Gen {
    fn w(&self, off: u32) -> String {
        format!("%VW{}", self.base + off)
    }
    fn b(&self, off: u32) -> String {
        format!("%VB{}", self.base + off)
    }
    fn d(&self, off: u32) -> String {
        format!("%VD{}", self.base + off)
    }
    /// The one-scan "execute" flag.
    fn flag(&self) -> String {
        format!("%V{}.0", self.base + OFF_SCRATCH + 12)
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
    fn src(&self) -> String {
        self.d(OFF_SCRATCH + 4)
    }
    fn dst(&self) -> String {
        self.d(OFF_SCRATCH + 8)
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
    /// `LD flag; AND command == code` — the guard of every command network.
    fn when(&mut self, code: u16) {
        let f = self.flag();
        let cmd = self.w(p::OFF_REQUEST + 4);
        self.line("LD", &f, "");
        self.line("AW=", &format!("{cmd}, {code}"), "");
    }
    fn when_arg(&mut self, code: u16, arg1: u32, arg2: Option<u32>) {
        self.when(code);
        let a1 = self.w(p::OFF_REQUEST + 6);
        self.line("AW=", &format!("{a1}, {arg1}"), "");
        if let Some(a2) = arg2 {
            let a = self.w(p::OFF_REQUEST + 8);
            self.line("AW=", &format!("{a}, {a2}"), "");
        }
    }
    /// `LD` of "the request's command is one of `commands`" (signed compares are exact here:
    /// the codes are small, and a code of 32768 or more, negative as an INT, is in no range).
    fn gate(&mut self, commands: (u16, u16), comment: &str) {
        let cmd = self.w(p::Field::Command.offset());
        match commands {
            (a, b) if a == b => self.line("LDW=", &format!("{cmd}, {a}"), comment),
            (a, b) => {
                self.line("LDW>=", &format!("{cmd}, {a}"), comment);
                self.line("AW<=", &format!("{cmd}, {b}"), "");
            }
        }
    }

    /// The refusals of [`p::checks`], in order: each sets the result and jumps to the ack.
    /// The PLC compares words only as signed INTs (S7-200 convention; no unsigned compare),
    /// so "word < lo" with lo ≥ 0 also catches words of 32768 or more, and ARG1 + ARG2 is
    /// computed only after earlier rows bounded both, so the sum cannot overflow an INT.
    fn checks(&mut self) {
        let (result, count) = (self.result(), self.count());
        let rows = p::checks();
        let mut summed: Option<(u16, u16)> = None;
        for (i, c) in rows.iter().enumerate() {
            let why = format!("{} -> result {}", c.why, c.result.code());
            if matches!(c.test, p::Test::EndAbove(_) | p::Test::Overlaps(..)) {
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
                    self.line("AW=", &format!("{}, {v}", w(self, f)), "");
                }
                p::Test::Outside(f, lo, hi) => {
                    assert!(lo <= hi && hi <= p::INT_MAX, "check {i}: {lo}..{hi} is not within 0..32767");
                    let x = w(self, f);
                    if let Some(cmds) = c.commands {
                        self.gate(cmds, &why);
                        self.line("LDW<", &format!("{x}, {lo}"), "also 32768..65535: negative as an INT");
                        self.line("OW>", &format!("{x}, {hi}"), "");
                        self.line("ALD", "", "");
                    } else {
                        self.line("LDW<", &format!("{x}, {lo}"), &why);
                        self.line("OW>", &format!("{x}, {hi}"), "32768..65535 are negative: caught above");
                    }
                }
                p::Test::EndAbove(l) => {
                    self.gate(c.commands.expect("checked above"), &why);
                    self.line("AW>", &format!("{count}, {l}"), "");
                }
                p::Test::Overlaps(lo, hi) => {
                    self.gate(c.commands.expect("checked above"), &why);
                    self.line("AW<", &format!("{}, {hi}", w(self, p::Field::Arg1)), "");
                    self.line("AW>", &format!("{count}, {lo}"), "");
                }
            }
            self.line("MOVE", &format!("{}, {result}", c.result.code()), "");
            self.line("JMPC", "ACK", "");
        }
    }

    /// A byte-copy loop through two pointers (S7-200-style `&`/`*` indirect addressing).
    fn copy_loop(&mut self, label: &str) {
        let (src, dst, count) = (self.src(), self.dst(), self.count());
        self.label(label);
        self.line("LD", "%SM0.0", "");
        self.line("MOVE", &format!("*{src}, *{dst}"), "one byte");
        self.line("ADD", &format!("1, {src}"), "");
        self.line("ADD", &format!("1, {dst}"), "");
        self.line("SUB", &format!("1, {count}"), "");
        self.line("LDW>", &format!("{count}, 0"), "");
        self.line("JMPC", label, "");
    }
}

/// The helper program for a mailbox at VB`base` (even, with TOTAL_SIZE bytes free).
pub fn program(base: u32) -> String {
    let mut g = Gen { base, out: String::new(), network: 0 };
    let end = base + TOTAL_SIZE - 1;
    let _ = write!(
        g.out,
        "(* ===================================================================================
   k2_agent.il - the plcsh helper program for Kinco K2 PLCs, mailbox protocol version {ver}.
   Generated by `plcsh agent il --base VB{base}` (edit the generator, src/k2/agent/il.rs).

   Once per scan it looks at a mailbox in VB{base}..VB{end} and, when plcsh has left a new
   request there, runs it: write or read SM bytes, PLS, HDEF, HSC, PSTOP, SET_RTC, READ_RTC.
   That gives plcsh the SM registers and instructions the K2 Modbus map does not reach
   (manual section 3.2). The protocol is described in docs/agent.md.

   Status: exercised only against plcsh's simulator, which executes this text in its IL
   engine (`plcsh sim serve --agent`); not yet run on a real K2. Mnemonics the K2 manual shows
   (LD, ST, R_TRIG, MOVE with typed operands, PLS) are used as shown there; comparisons
   (AW=, LDW<), ALD, ADD/SUB, jumps and the &/* indirect addressing are written as in
   KincoBuilder's S7-200-style IL. If KincoBuilder rejects a line, enter that network in
   LD with the logic its comment gives.

   Network 3 refuses malformed requests before anything runs (docs/agent.md, section Checks).
   Word compares are signed INT compares, so each `word < bound` test also catches the
   words 32768..65535, and ARG1 + ARG2 is added only after both are bounded: no request
   makes this program address memory outside SMB0..SMB549 or stop the CPU.

   Install in KincoBuilder:
     1. Add a subroutine PLCSH_AGENT, language IL; paste this file into it.
     2. In the main program add a network:  LD %SM0.0 / CAL PLCSH_AGENT  (every scan).
     3. Keep VB{base}..VB{end} free for the mailbox (below the E2PROM area VB3648).
     4. Download, RUN; connect with  tcp://PLC:502?agent=VB{base}  (or rtu:...&agent=VB{base}).
   =================================================================================== *)
",
        ver = p::VERSION
    );
    let (result, flag) = (g.result(), g.flag());
    g.net("announce the helper: signature, version, heartbeat (every scan)");
    g.line("LD", "%SM0.0", "");
    g.line("MOVE", &format!("W#16#{:04X}, {}", p::SIGNATURE, g.w(p::OFF_SIGNATURE)), "\"KA\"");
    g.line("MOVE", &format!("{}, {}", p::VERSION, g.w(p::OFF_VERSION)), "protocol version");
    g.line("ADD", &format!("1, {}", g.w(p::OFF_HEARTBEAT)), "heartbeat");

    g.net("a new request waits when the request sequence differs from ack 0");
    g.line("LDW<>", &format!("{}, {}", g.w(p::OFF_REQUEST), g.w(p::OFF_ACKS)), "");
    g.line("=", &flag, "execute this scan");
    g.line("LD", &flag, "");
    g.line("MOVE", &format!("0, {result}"), "result 0 = done");
    g.line("MOVE", &format!("0, {}", g.w(p::OFF_REPLY_LEN)), "no reply data yet");
    g.line("LDN", &flag, "");
    g.line("JMPC", "DONE", "nothing to do");

    let (a1, a2) = (g.w(p::OFF_REQUEST + 6), g.w(p::OFF_REQUEST + 8));
    g.net("refuse malformed requests: the checks of docs/agent.md, in order, over unsigned words");
    g.checks();

    g.net("command 1: copy ARG2 bytes of request data to SMB[ARG1]");
    g.when(Command::SmWrite { start: 0, data: vec![] }.code());
    g.line("JMPCN", "NOT_WRITE", "");
    g.line("MOVE", &format!("&VB{}, {}", base + p::OFF_REQ_DATA, g.src()), "source: request data");
    g.line("MOVE", &format!("&SMB0, {}", g.dst()), "target: SMB0 + ARG1");
    g.line("I_DI", &format!("{a1}, {}", g.src()), "ARG1 as a double word");
    g.line("ADD", &format!("{}, {}", g.src(), g.dst()), "");
    g.line("MOVE", &format!("&VB{}, {}", base + p::OFF_REQ_DATA, g.src()), "source: request data");
    g.line("MOVE", &format!("{a2}, {}", g.count()), "");
    g.copy_loop("WRITE_LOOP");
    g.line("JMP", "ACK", "");
    g.label("NOT_WRITE");

    g.net("command 2: copy ARG2 bytes from SMB[ARG1] to the reply");
    g.when(Command::SmRead { start: 0, len: 0 }.code());
    g.line("JMPCN", "NOT_READ", "");
    g.line("MOVE", &format!("&SMB0, {}", g.src()), "source: SMB0 + ARG1");
    g.line("I_DI", &format!("{a1}, {}", g.dst()), "ARG1 as a double word");
    g.line("ADD", &format!("{}, {}", g.dst(), g.src()), "");
    g.line("MOVE", &format!("&VB{}, {}", base + p::OFF_REPLY, g.dst()), "target: reply data");
    g.line("MOVE", &format!("{a2}, {}", g.count()), "");
    g.line("MOVE", &format!("{a2}, {}", g.w(p::OFF_REPLY_LEN)), "");
    g.copy_loop("READ_LOOP");
    g.line("JMP", "ACK", "");
    g.label("NOT_READ");

    let ok = g.ok();
    let code = |r: p::ResultCode| r.code();

    g.net("the instruction's ENO, set by the network that runs it");
    g.line("LD", &flag, "");
    g.line("R", &format!("{ok}, 1"), "set below by the instruction's ENO");

    g.net("command 3: PLS ARG1 (the one-scan execute flag is the rising edge PLS needs, section 3.4.2)");
    for r in PTO_REGS {
        g.when_arg(Command::Pls(0).code(), r.channel as u32, None);
        g.line("PLS", &r.channel.to_string(), "");
        g.line("S", &format!("{ok}, 1"), "ENO = 1: started");
    }
    g.when(Command::Pls(0).code());
    g.line("AN", &ok, "");
    g.line("MOVE", &format!("{}, {result}", code(p::ResultCode::InstructionFailed)), "PLS refused (status byte bit 4)");

    g.net("command 4: HDEF ARG1, ARG2 - one line per counter and mode of section 3.3.1");
    for &(hsc, mode, what) in HSC_MODES {
        g.when_arg(Command::Hdef { hsc: 0, mode: 0 }.code(), hsc as u32, Some(mode as u32));
        g.line("HDEF", &format!("{hsc}, {mode}"), what);
        g.line("S", &format!("{ok}, 1"), "");
    }
    g.when(Command::Hdef { hsc: 0, mode: 0 }.code());
    g.line("AN", &ok, "no line matched: not a mode of this counter");
    g.line("MOVE", &format!("{}, {result}", code(p::ResultCode::BadMode)), "");

    g.net("command 5: HSC ARG1");
    for n in 0..4u32 {
        g.when_arg(Command::Hsc(0).code(), n, None);
        g.line("HSC", &n.to_string(), "");
        g.line("S", &format!("{ok}, 1"), "");
    }
    g.when(Command::Hsc(0).code());
    g.line("AN", &ok, "");
    g.line("MOVE", &format!("{}, {result}", code(p::ResultCode::InstructionFailed)), "");

    g.net("command 6: PSTOP ARG1 - stop the channel and latch its emergency-stop bit (section 3.4.3.1)");
    let (exec, done, errid) = (g.exec(), g.done(), g.errid());
    for r in PTO_REGS {
        g.when_arg(Command::Pstop(0).code(), r.channel as u32, None);
        g.line("=", &exec, "EXEC: on in this request's scan only");
        g.line("LD", "%SM0.0", "");
        g.line("PSTOP", &format!("{}, {exec}, {done}, {errid}", r.channel), "AXIS, EXEC, DONE, ERRID");
    }

    g.net("commands 7 and 8: SET_RTC from the request data, READ_RTC into the reply");
    g.when(Command::SetRtc([0; 8]).code());
    g.line("SET_RTC", &g.b(p::OFF_REQ_DATA), "8 bytes BCD: yy mm dd hh mm ss 00 weekday");
    g.line("S", &format!("{ok}, 1"), "");
    g.when(Command::SetRtc([0; 8]).code());
    g.line("AN", &ok, "");
    g.line("MOVE", &format!("{}, {result}", code(p::ResultCode::BadClock)), "not a valid date and time");
    g.when(Command::ReadRtc.code());
    g.line("READ_RTC", &g.b(p::OFF_REPLY), "");
    g.line("MOVE", &format!("8, {}", g.w(p::OFF_REPLY_LEN)), "");

    g.net("acknowledge: shift acks 0-2 to 1-3, then ack 0 = (sequence, token, result), sequence last");
    g.label("ACK");
    g.line("LD", &flag, "");
    g.line("BLKMOVE", &format!("{}, {}, 6", g.b(p::OFF_ACKS + 12), g.b(p::OFF_ACKS + 18)), "ack 2 -> ack 3");
    g.line("BLKMOVE", &format!("{}, {}, 6", g.b(p::OFF_ACKS + 6), g.b(p::OFF_ACKS + 12)), "ack 1 -> ack 2");
    g.line("BLKMOVE", &format!("{}, {}, 6", g.b(p::OFF_ACKS), g.b(p::OFF_ACKS + 6)), "ack 0 -> ack 1");
    g.line("MOVE", &format!("{}, {}", g.w(p::OFF_REQUEST + 2), g.w(p::OFF_ACKS + 2)), "token");
    g.line("MOVE", &format!("{result}, {}", g.w(p::OFF_ACKS + 4)), "result");
    g.line("MOVE", &format!("{}, {}", g.w(p::OFF_REQUEST), g.w(p::OFF_ACKS)), "sequence: the ack is complete");
    g.label("DONE");
    g.out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_committed_program_is_current() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/lib/k2_agent.il");
        let want = program(p::DEFAULT_BASE);
        if std::env::var_os("PLCSH_BLESS").is_some() {
            std::fs::write(path, &want).unwrap();
        }
        let have = std::fs::read_to_string(path).unwrap_or_default();
        assert!(
            have == want,
            "lib/k2_agent.il is stale: run `cargo run -- agent il > lib/k2_agent.il` or PLCSH_BLESS=1 cargo test"
        );
    }

    #[test]
    fn every_counter_mode_and_address_is_relocated() {
        let il = program(2000);
        for &(hsc, mode, _) in HSC_MODES {
            assert!(il.contains(&format!("HDEF    {hsc}, {mode}")), "HDEF {hsc}, {mode}");
        }
        assert!(il.contains("%VW2000"), "signature at the base");
        assert!(!il.contains("%VW3400"), "no default address left");
        assert!(il.contains("PSTOP   3, "), "PSTOP of channel 3");
        assert!(!il.contains('…'), "no elisions");
    }

    #[test]
    fn every_check_refuses_before_any_command_runs() {
        let il = program(p::DEFAULT_BASE);
        let (checks, first_command) = (il.find("Network 3").unwrap(), il.find("Network 4").unwrap());
        let net = &il[checks..first_command];
        let rows = p::checks();
        assert_eq!(net.matches("JMPC    ACK").count(), rows.len(), "one refusal per row of the table");
        for c in &rows {
            assert!(net.contains(&format!("{} -> result {}", c.why, c.result.code())), "{}", c.why);
        }
        // Only INT literals: the PLC's word compares are signed.
        for line in il.lines().filter(|l| l.starts_with("LDW") || l.starts_with("AW") || l.starts_with("OW")) {
            let lit = line.rsplit(", ").next().unwrap().split_whitespace().next().unwrap();
            if let Ok(n) = lit.parse::<i64>() {
                assert!((0..=32767).contains(&n), "{line}");
            }
        }
    }

    #[test]
    fn the_scratch_area_stays_below_the_backup_area() {
        const { assert!(p::DEFAULT_BASE + TOTAL_SIZE <= crate::k2::catalog::EEPROM_FIRST) };
    }
}
