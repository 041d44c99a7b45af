//! `plcsh agent check`: a self-test of the helper program in a real K2, safe to run on a
//! machine that is set up: each step says whether it passed, what it proves and what to do when
//! it failed. It writes only the helper's mailbox request words and, for the refusal step, the
//! SM bytes of one idle pulse channel, which it puts back as they were (docs/agent.md,
//! "agent check").
//!
//! Steps, in order (a step that cannot run because an earlier one failed fails as "not run"):
//! 1. signature 16#4B41 at the mailbox base; 2. the protocol version; 3. the heartbeat's rate
//!    (scans a second, so the scan time); 4. SMB0 through the helper: SM0.0 is always 1 and
//!    SM0.1 (first scan) is 0 once the first scan is over (manual §2.2.7 SM table, k2.md §8);
//! 5. READ_RTC twice, a second apart: a valid date and a clock that runs; 6. the refusal path:
//!    manual §3.4.2, PTO: «Если указанное число импульсов меньше 2, то Kinco K2 установит
//!    соответствующий бит ошибки и запретит выход» — on a pulse channel whose control byte has
//!    the enable bit SMx.7 clear (the program does not use it), the check loads control byte
//!    16#84 (enable, PTO, single segment, update the pulse count only) and pulse count 0, runs
//!    PLS through the helper, and requires status bit 4 (§3.4.2.2: cycle time or pulse count
//!    invalid) to come back, the position counter and the idle bit to stay as they were; then
//!    it writes back the status byte, the control byte and the count as they were.

use super::client::{AgentClient, Registers};
use super::protocol::{self as p, Command, Status};
use crate::core::{Error, ErrorKind};
use crate::k2::catalog::Model;
use crate::k2::instr::RtcTime;
use crate::k2::sm_map::PTO_REGS;
use serde::Serialize;
use std::time::Duration;

/// Wall time as the check sees it (the machine's, or a simulator's in tests).
pub trait Time {
    /// Time since some fixed instant.
    fn now(&mut self) -> Duration;
    fn sleep(&mut self, d: Duration);
}

/// The machine's clock.
pub struct WallTime(pub std::time::Instant);

impl Time for WallTime {
    fn now(&mut self) -> Duration {
        self.0.elapsed()
    }
    fn sleep(&mut self, d: Duration) {
        std::thread::sleep(d)
    }
}

/// How a step ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Outcome {
    Passed,
    Failed,
    /// The step does not apply to this model (a relay-output model has no pulse channel).
    NotApplicable,
}

/// One step of the check.
#[derive(Clone, Debug, Serialize)]
pub struct Step {
    pub name: &'static str,
    pub outcome: Outcome,
    /// What a pass proves.
    pub proves: String,
    /// What was seen.
    pub seen: String,
    /// What to do (when it failed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub todo: Option<String>,
}

/// The whole check.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub base: String,
    pub model: &'static str,
    pub steps: Vec<Step>,
    /// Scan time from the heartbeat, when measured.
    pub scan_ms: Option<f64>,
    /// SM bytes the refusal step wrote (and wrote back).
    pub sm_written: Vec<String>,
}

impl Report {
    /// True when every step passed or does not apply.
    pub fn passed(&self) -> bool {
        self.steps.iter().all(|s| s.outcome != Outcome::Failed)
    }
}

/// The steps' names (the JSON `name`, the same in every language).
const NAMES: [&str; 6] = ["signature", "protocol", "heartbeat", "system bits", "clock", "refusal"];

/// What step `i` proves when it passes, in the current language.
fn proves(i: usize) -> String {
    match i {
        0 => crate::msg!("agent-check-proves-signature"),
        1 => crate::msg!("agent-check-proves-protocol"),
        2 => crate::msg!("agent-check-proves-heartbeat"),
        3 => crate::msg!("agent-check-proves-system-bits"),
        4 => crate::msg!("agent-check-proves-clock"),
        _ => crate::msg!("agent-check-proves-refusal"),
    }
    .to_string()
}

fn step(i: usize, ok: bool, seen: String, todo: Option<String>) -> Step {
    Step {
        name: NAMES[i],
        outcome: if ok { Outcome::Passed } else { Outcome::Failed },
        proves: proves(i),
        seen,
        todo: if ok { None } else { todo },
    }
}

fn failed(i: usize, e: &Error, default_todo: crate::core::msg::Msg) -> Step {
    let todo = e.hint.clone().unwrap_or_else(|| default_todo.to_string());
    step(i, false, e.message.clone(), Some(todo))
}

/// Runs the check on the helper at `client.base` of a PLC of `model`.
pub fn run(client: &mut AgentClient, regs: &mut dyn Registers, model: &'static Model, time: &mut dyn Time) -> Report {
    let mut r = Report {
        base: format!("VB{}", client.base),
        model: model.name,
        steps: Vec::new(),
        scan_ms: None,
        sm_written: Vec::new(),
    };
    steps(client, regs, model, time, &mut r);
    // Steps that did not run because an earlier one failed.
    let done = r.steps.len();
    for (i, name) in NAMES.iter().enumerate().skip(done) {
        r.steps.push(Step {
            name,
            outcome: Outcome::Failed,
            proves: proves(i),
            seen: crate::msg!("agent-check-not-run").to_string(),
            todo: Some(crate::msg!("agent-check-not-run-todo").to_string()),
        });
    }
    r
}

fn read_status(client: &AgentClient, regs: &mut dyn Registers) -> crate::core::Result<Status> {
    Ok(Status::parse(&regs.read_v(client.base, p::STATUS_WORDS)?))
}

fn steps(
    client: &mut AgentClient,
    regs: &mut dyn Registers,
    model: &'static Model,
    time: &mut dyn Time,
    r: &mut Report,
) {
    let base = client.base;
    let install = crate::msg!("agent-check-install", base = base).to_string();
    // 1. Signature.
    let s = match read_status(client, regs) {
        Ok(s) => s,
        Err(e) => {
            r.steps.push(failed(0, &e, crate::msg!("agent-check-link-probe")));
            return;
        }
    };
    let ok = s.signature == p::SIGNATURE;
    r.steps.push(step(
        0,
        ok,
        crate::msg!(
            "agent-check-signature-seen",
            base = base,
            got = format!("{:04X}", s.signature),
            want = format!("{:04X}", p::SIGNATURE)
        )
        .to_string(),
        Some(install.clone()),
    ));
    if !ok {
        return;
    }
    // 2. Protocol version.
    let ok = s.version == p::VERSION;
    r.steps.push(step(
        1,
        ok,
        crate::msg!("agent-check-version-seen", got = s.version, want = p::VERSION).to_string(),
        Some(crate::msg!("agent-check-version-todo").to_string()),
    ));
    if !ok {
        return;
    }
    // 3. Heartbeat over at least half a second.
    let (t0, hb0) = (time.now(), s.heartbeat);
    time.sleep(Duration::from_millis(500));
    let s1 = match read_status(client, regs) {
        Ok(s) => s,
        Err(e) => {
            r.steps.push(failed(2, &e, crate::msg!("agent-check-link")));
            return;
        }
    };
    let dt = time.now().saturating_sub(t0);
    let scans = s1.heartbeat.wrapping_sub(hb0);
    if scans == 0 {
        r.steps.push(step(
            2,
            false,
            crate::msg!("agent-check-heartbeat-stopped", hb = hb0, ms = dt.as_millis() as u64).to_string(),
            Some(crate::msg!("agent-check-heartbeat-todo").to_string()),
        ));
        return;
    }
    let scan_ms = dt.as_secs_f64() * 1000.0 / scans as f64;
    r.scan_ms = Some(scan_ms);
    r.steps.push(step(
        2,
        true,
        crate::msg!(
            "agent-check-heartbeat-seen",
            scans = scans,
            ms = dt.as_millis() as u64,
            rate = format!("{:.0}", scans as f64 / dt.as_secs_f64().max(1e-9)),
            scan = format!("{scan_ms:.2}")
        )
        .to_string(),
        None,
    ));
    // 4. SMB0.
    match client.run(regs, &Command::SmRead { start: 0, len: 1 }, &mut |d| time.sleep(d)) {
        Ok(b) if b.len() == 1 => {
            let (sm00, sm01) = (b[0] & 1 != 0, b[0] & 2 != 0);
            let ok = sm00 && !sm01;
            let mut todo = String::new();
            if !sm00 {
                todo.push_str(&crate::msg!("agent-check-sm00-todo"));
            } else if sm01 {
                todo.push_str(&crate::msg!("agent-check-sm01-todo"));
            }
            r.steps.push(step(
                3,
                ok,
                format!("SMB0 = 16#{:02X}: SM0.0 = {}, SM0.1 = {}", b[0], sm00 as u8, sm01 as u8),
                Some(todo),
            ));
            if !ok {
                return;
            }
        }
        Ok(b) => {
            r.steps.push(step(
                3,
                false,
                crate::msg!("agent-check-reply-length", n = b.len()).to_string(),
                Some(crate::msg!("agent-check-load-current-il").to_string()),
            ));
            return;
        }
        Err(e) => {
            r.steps.push(failed(3, &e, crate::msg!("agent-check-mailbox-todo")));
            return;
        }
    }
    // 5. The clock: a valid date, and running.
    let read_rtc =
        |client: &mut AgentClient, regs: &mut dyn Registers, time: &mut dyn Time| -> crate::core::Result<RtcTime> {
            let b = client.run(regs, &Command::ReadRtc, &mut |d| time.sleep(d))?;
            let buf: [u8; 8] = b
                .get(..8)
                .and_then(|s| s.try_into().ok())
                .ok_or_else(|| Error::link(crate::msg!("agent-check-rtc-short")))?;
            RtcTime::from_bcd8(&buf).map_err(|m| {
                Error::new(ErrorKind::Refused, crate::msg!("agent-check-rtc-invalid", reading = m.to_string()))
                    .hint(crate::msg!("agent-check-rtc-invalid-hint"))
            })
        };
    let first = read_rtc(client, regs, time);
    let t1 = time.now();
    time.sleep(Duration::from_millis(1100));
    let second = first.as_ref().ok().map(|_| read_rtc(client, regs, time));
    let dt = time.now().saturating_sub(t1).as_secs_f64();
    match (first, second) {
        (Ok(a), Some(Ok(b))) => {
            let moved = b.to_secs() - a.to_secs();
            let ok = moved >= 1 && (moved as f64) <= dt + 2.0;
            r.steps.push(step(
                4,
                ok,
                crate::msg!(
                    "agent-check-clock-seen",
                    first = a.to_string(),
                    second = b.to_string(),
                    dt = format!("{dt:.1}"),
                    moved = moved
                )
                .to_string(),
                Some(crate::msg!("agent-check-clock-todo").to_string()),
            ));
            if !ok {
                return;
            }
        }
        (Err(e), _) | (_, Some(Err(e))) => {
            r.steps.push(failed(4, &e, crate::msg!("agent-check-load-current-il")));
            return;
        }
        (Ok(_), None) => unreachable!("a second read follows a good first"),
    }
    // 6. The refusal path on an idle pulse channel.
    refusal(client, regs, model, &mut sleep_fn(time), r);
}

fn sleep_fn(time: &mut dyn Time) -> impl FnMut(Duration) + '_ {
    move |d| time.sleep(d)
}

/// Step 6: PLS with pulse count 0 on a channel the program does not enable.
fn refusal(
    client: &mut AgentClient,
    regs: &mut dyn Registers,
    model: &'static Model,
    sleep: &mut dyn FnMut(Duration),
    r: &mut Report,
) {
    const I: usize = 5;
    if model.pto.is_empty() {
        r.steps.push(Step {
            name: NAMES[I],
            outcome: Outcome::NotApplicable,
            proves: proves(I),
            seen: crate::msg!("agent-check-relay-model", model = model.name).to_string(),
            todo: None,
        });
        return;
    }
    // Each channel's status … count bytes (SMB66 … SMB75 for channel 0), read in one command.
    let mut chosen = None;
    let mut busy = Vec::new();
    for spec in model.pto {
        let Some(regs_c) = PTO_REGS.iter().find(|x| x.channel == spec.channel) else { continue };
        let (lo, len) = (regs_c.status, regs_c.count + 4 - regs_c.status);
        let bytes = match client.run(regs, &Command::SmRead { start: lo as u16, len: len as u16 }, sleep) {
            Ok(b) if b.len() == len as usize => b,
            Ok(_) => continue,
            Err(e) => {
                r.steps.push(failed(I, &e, crate::msg!("agent-check-again")));
                return;
            }
        };
        let control = bytes[(regs_c.control - lo) as usize];
        if control & 0x80 != 0 {
            busy.push(format!("SMB{} = 16#{control:02X}", regs_c.control));
            continue;
        }
        chosen = Some((*regs_c, bytes));
        break;
    }
    let Some((c, before)) = chosen else {
        r.steps.push(step(
            I,
            false,
            crate::msg!("agent-check-all-enabled", bytes = busy.join(", ")).to_string(),
            Some(crate::msg!("agent-check-all-enabled-todo").to_string()),
        ));
        return;
    };
    let lo = c.status;
    let at = |reg: u32| (reg - lo) as usize;
    let cv_before = client.run(regs, &Command::SmRead { start: c.pos_cv as u16, len: 4 }, sleep);
    // Control byte 16#84: enable, PTO, 1 µs base, single segment, update the pulse count only.
    let write = |client: &mut AgentClient,
                 regs: &mut dyn Registers,
                 start: u32,
                 data: Vec<u8>,
                 sleep: &mut dyn FnMut(Duration)| {
        client.run(regs, &Command::SmWrite { start: start as u16, data }, sleep)
    };
    let mut written = vec![format!("SMB{}", c.control), format!("SMD{}", c.count)];
    let setup = write(client, regs, c.control, vec![0x84], sleep)
        .and_then(|_| write(client, regs, c.count, vec![0, 0, 0, 0], sleep));
    let pls = setup.as_ref().ok().map(|_| client.run(regs, &Command::Pls(c.channel), sleep));
    let after = client.run(regs, &Command::SmRead { start: lo as u16, len: (c.count + 4 - lo) as u16 }, sleep);
    let cv_after = client.run(regs, &Command::SmRead { start: c.pos_cv as u16, len: 4 }, sleep);
    // Put back the status byte (if it changed), the control byte and the count as they were.
    let status_now = after.as_ref().ok().and_then(|a| a.get(at(c.status)).copied());
    let mut restore = write(client, regs, c.control, vec![before[at(c.control)]], sleep)
        .and_then(|_| write(client, regs, c.count, before[at(c.count)..at(c.count) + 4].to_vec(), sleep));
    if status_now != Some(before[at(c.status)]) {
        written.insert(0, format!("SMB{}", c.status));
        restore = restore.and_then(|_| write(client, regs, c.status, vec![before[at(c.status)]], sleep));
    }
    r.sm_written = written.clone();
    let name = format!("PLS {} (control SMB{} = 16#84, count SMD{} = 0)", c.channel, c.control, c.count);
    if let Err(e) = &setup {
        r.steps.push(failed(I, e, crate::msg!("agent-check-again")));
        return;
    }
    if let Err(e) = &restore {
        r.steps.push(step(
            I,
            false,
            crate::msg!("agent-check-restore-failed", name = name.as_str(), error = e.message.as_str()).to_string(),
            Some(
                crate::msg!(
                    "agent-check-restore-todo",
                    control = c.control,
                    value = format!("{:02X}", before[at(c.control)]),
                    count = c.count,
                    pulses = u32::from_be_bytes(before[at(c.count)..at(c.count) + 4].try_into().expect("4 bytes"))
                        .to_string()
                )
                .to_string(),
            ),
        ));
        return;
    }
    let (after, cv_before, cv_after) = match (after, cv_before, cv_after) {
        (Ok(a), Ok(b), Ok(c)) if a.len() == before.len() => (a, b, c),
        (Err(e), ..) | (_, Err(e), _) | (.., Err(e)) => {
            r.steps.push(failed(I, &e, crate::msg!("agent-check-again")));
            return;
        }
        _ => {
            r.steps.push(step(
                I,
                false,
                crate::msg!("agent-check-wrong-length").to_string(),
                Some(crate::msg!("agent-check-load-current").to_string()),
            ));
            return;
        }
    };
    let status = after[at(c.status)];
    let bit4 = status & 0x10 != 0;
    let idle_kept = (status ^ before[at(c.status)]) & 0x80 == 0;
    let still = cv_before == cv_after;
    let (helper, reported_done) = match pls.expect("the setup succeeded") {
        Ok(_) => (crate::msg!("agent-check-reported-done").to_string(), true),
        Err(e) if e.kind == ErrorKind::Refused => {
            (crate::msg!("agent-check-reported", message = e.message.as_str()).to_string(), false)
        }
        Err(e) => {
            r.steps.push(failed(I, &e, crate::msg!("agent-check-again")));
            return;
        }
    };
    let ok = bit4 && idle_kept && still && !reported_done;
    let seen = crate::msg!(
        "agent-check-refusal-seen",
        name = name.as_str(),
        status = c.status,
        before = format!("{:02X}", before[at(c.status)]),
        after = format!("{status:02X}"),
        bit4 = if bit4 { "set" } else { "clear" },
        cv = c.pos_cv,
        moved = if still { "unchanged" } else { "changed" },
        helper = helper.as_str(),
        written = written.join(", ")
    )
    .to_string();
    let todo = if !bit4 {
        crate::msg!("agent-check-no-bit4-todo").to_string()
    } else if reported_done {
        crate::msg!("agent-check-cr-todo").to_string()
    } else {
        crate::msg!("agent-check-moved-todo", channel = c.channel).to_string()
    };
    r.steps.push(step(I, ok, seen, Some(todo)));
}

/// Runs the check through a [`Registers`] link with the machine's clock.
pub fn run_wall(client: &mut AgentClient, regs: &mut dyn Registers, model: &'static Model) -> Report {
    run(client, regs, model, &mut WallTime(std::time::Instant::now()))
}

/// The report as text: one line a step, then what to do for each failed one.
pub fn text(r: &Report) -> String {
    let mut s = format!("{}\n", crate::msg!("agent-check-title", base = r.base.as_str(), model = r.model));
    for (i, st) in r.steps.iter().enumerate() {
        let mark = match st.outcome {
            Outcome::Passed => "pass",
            Outcome::Failed => "FAIL",
            Outcome::NotApplicable => "n/a ",
        };
        s.push_str(&format!("{}. {mark} {}: {}\n", i + 1, st.name, st.seen));
        s.push_str(&format!("   {}\n", crate::msg!("agent-check-proves", text = st.proves.as_str())));
        if let Some(t) = &st.todo {
            s.push_str(&format!("   {}\n", crate::msg!("agent-check-todo", text = t.as_str())));
        }
    }
    let verdict = if r.passed() { crate::msg!("agent-check-passed") } else { crate::msg!("agent-check-failed") };
    s.push_str(&format!("{verdict}\n"));
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::{Clock, Result};
    use crate::k2::catalog;
    use crate::k2::operand::{Area, K2Operand};
    use crate::k2::sim::{self, K2Sim, SCAN_TIME};

    /// V words of a simulator in stepped time: every sleep moves it by that long.
    struct SimRegs {
        sim: K2Sim,
        clock: Clock,
    }

    impl Registers for SimRegs {
        fn read_v(&mut self, vbyte: u32, count: u16) -> Result<Vec<u16>> {
            self.sim.advance();
            Ok((0..count as u32).map(|i| self.sim.mem.read(&K2Operand::word(Area::V, vbyte + 2 * i)) as u16).collect())
        }
        fn write_v(&mut self, vbyte: u32, words: &[u16]) -> Result<()> {
            self.sim.advance();
            for (i, w) in words.iter().enumerate() {
                self.sim.mem.write(&K2Operand::word(Area::V, vbyte + 2 * i as u32), *w as u32);
            }
            Ok(())
        }
    }

    struct Stepped(Clock);
    impl Time for Stepped {
        fn now(&mut self) -> Duration {
            self.0.now()
        }
        fn sleep(&mut self, d: Duration) {
            self.0.step(d.max(SCAN_TIME));
        }
    }

    fn check(model: &str, agent: bool) -> (Report, SimRegs) {
        let clock = Clock::stepped();
        let mut s = sim::open(model, clock.clone()).unwrap();
        if agent {
            s.enable_agent(p::DEFAULT_BASE).unwrap();
        }
        clock.step(SCAN_TIME * 3);
        s.advance();
        let mut regs = SimRegs { sim: s, clock: clock.clone() };
        let mut c = AgentClient::new(p::DEFAULT_BASE);
        let r = run(&mut c, &mut regs, catalog::find(model).unwrap(), &mut Stepped(clock));
        (r, regs)
    }

    #[test]
    fn a_helper_in_a_manual_following_plc_passes_every_step() {
        let (r, regs) = check("K205-16DT", true);
        assert!(r.passed(), "{}", text(&r));
        assert_eq!(r.steps.len(), 6);
        assert!((r.scan_ms.unwrap() - SCAN_TIME.as_secs_f64() * 1000.0).abs() < 0.5, "{:?}", r.scan_ms);
        assert_eq!(regs.sim.mem.sm_byte(67), 0, "the control byte is back");
        assert_eq!(regs.sim.mem.sm_byte(66) & 0x10, 0, "the status byte is back");
        let _ = regs.clock;
    }

    #[test]
    fn a_relay_model_has_no_refusal_step_to_run() {
        let (r, _) = check("K205-16DR", true);
        assert!(r.passed(), "{}", text(&r));
        assert_eq!(r.steps[5].outcome, Outcome::NotApplicable);
    }

    #[test]
    fn without_the_helper_the_first_step_fails_and_says_how_to_load_it() {
        let (r, _) = check("K205-16DT", false);
        assert!(!r.passed());
        assert_eq!(r.steps[0].outcome, Outcome::Failed);
        assert!(r.steps[0].todo.as_deref().unwrap().contains("plcsh agent il"), "{}", text(&r));
        assert!(r.steps[1..].iter().all(|s| s.seen.starts_with("not run")), "{}", text(&r));
    }

    /// A helper that takes PLS's CR as success on a K2 that leaves the CR as it was (manual
    /// §3.4.2, IL): its acknowledgement of a refused PLS says "done". The check fails, naming it.
    #[test]
    fn a_helper_that_reports_a_refused_pls_as_done_fails_the_check() {
        struct DoneForPls(SimRegs);
        impl Registers for DoneForPls {
            fn read_v(&mut self, vbyte: u32, count: u16) -> Result<Vec<u16>> {
                let mut w = self.0.read_v(vbyte, count)?;
                let pls = self.0.sim.mem.read(&K2Operand::word(Area::V, p::DEFAULT_BASE + p::OFF_REQUEST + 4)) == 3;
                let result = ((p::OFF_ACKS + 4) / 2) as usize;
                // A refusal (result 6, or 8 with its cause in the high byte) turned into "done".
                if vbyte == p::DEFAULT_BASE && pls && w.len() > result && matches!(w[result] & 0xFF, 6 | 8) {
                    w[result] = 0;
                }
                Ok(w)
            }
            fn write_v(&mut self, vbyte: u32, words: &[u16]) -> Result<()> {
                self.0.write_v(vbyte, words)
            }
        }
        let clock = Clock::stepped();
        let mut s = sim::open("K205-16DT", clock.clone()).unwrap();
        s.enable_agent(p::DEFAULT_BASE).unwrap();
        clock.step(SCAN_TIME * 3);
        s.advance();
        let mut regs = DoneForPls(SimRegs { sim: s, clock: clock.clone() });
        let r = run(
            &mut AgentClient::new(p::DEFAULT_BASE),
            &mut regs,
            catalog::find("K205-16DT").unwrap(),
            &mut Stepped(clock),
        );
        assert_eq!(r.steps[5].outcome, Outcome::Failed, "{}", text(&r));
        assert!(r.steps[5].seen.contains("bit 4 set") && r.steps[5].seen.contains("done"), "{}", text(&r));
        assert!(r.steps[5].todo.as_deref().unwrap().contains("CR"), "{}", text(&r));
        assert_eq!(regs.0.sim.mem.sm_byte(67), 0, "the bytes are written back all the same");
    }

    #[test]
    fn a_channel_the_program_enables_is_left_alone() {
        let clock = Clock::stepped();
        let mut s = sim::open("K205-16DT", clock.clone()).unwrap();
        s.enable_agent(p::DEFAULT_BASE).unwrap();
        for ch in [67, 77, 97] {
            s.mem.sm[ch] = 0x85;
        }
        clock.step(SCAN_TIME * 3);
        s.advance();
        let mut regs = SimRegs { sim: s, clock: clock.clone() };
        let r = run(
            &mut AgentClient::new(p::DEFAULT_BASE),
            &mut regs,
            catalog::find("K205-16DT").unwrap(),
            &mut Stepped(clock),
        );
        assert_eq!(r.steps[5].outcome, Outcome::Failed, "{}", text(&r));
        assert!(r.steps[5].seen.contains("SMB67 = 16#85"), "{}", text(&r));
        assert!(r.sm_written.is_empty(), "nothing was written");
    }
}
