//! The helper mailbox and the simulator without it are two routes to the same K2: random
//! sequences of the commands plcsh sends through the helper — SM writes and reads, PLS and
//! PSTOP repeated on every pulse channel, PTO and PWM, HDEF and HSC, refused writes, setting
//! and reading the clock — run once through `plcsh sim serve --agent` (Modbus TCP → mailbox →
//! `lib/k2_agent.il` in the served K2's scan engine) and once in process on `sim:K205-16DT`
//! (the shell writes SM and runs instructions directly), and after every command the device
//! state must be the same: the SM bytes the commands touch, the current positions (SMD212 …),
//! the emergency-stop latches (SM201.7 …), the counters' registers and the outputs.
//!
//! The served simulator follows the wall clock and the in-process one is stepped, so every
//! command is followed by a wait until its pulse train is done (a train's pulse count does
//! not depend on when it is looked at) and only states that do not move with time are
//! compared: an output that is running PWM (its status byte says so) is left out, and the
//! clock is compared to ten seconds (it is set to a whole ten seconds and read right after).
//!
//! Each case is one served process and one `plcsh run` per route: a generated Lua script runs
//! the steps and prints one JSON line per step. Cases come from a seeded generator
//! (`core::test_rng`); a failure names the seed, the step and every line up to it.

mod common;
use common::*;

use plcsh::k2::sm_map::{HSC_MODES, HSC_REGS, PTO_REGS};
use serde_json::{json, Value as Json};
use std::path::PathBuf;

/// The seeded generator the property tests share (`core::test_rng`).
#[path = "../src/core/test_rng.rs"]
#[allow(dead_code)]
mod test_rng;
use test_rng::Rng;

const MODEL: &str = "K205-16DT";

fn model() -> &'static plcsh::k2::catalog::Model {
    plcsh::k2::catalog::lookup(MODEL).unwrap()
}

/// The pulse channels of the model (K205-16DT: PTO0, PTO1, PTO2 on Q0.0, Q0.1, Q0.4).
fn pto_channels() -> Vec<(&'static plcsh::k2::sm_map::PtoRegs, &'static str)> {
    model().pto.iter().map(|c| (PTO_REGS.iter().find(|r| r.channel == c.channel).unwrap(), c.output)).collect()
}

/// The counters of the model.
fn hsc_channels() -> Vec<&'static plcsh::k2::sm_map::HscRegs> {
    model().hsc.iter().map(|h| HSC_REGS.iter().find(|r| r.channel == h.channel).unwrap()).collect()
}

/// One step: a command line, and the operand to wait for (a pulse channel's "PTO idle" bit)
/// before the state is looked at.
#[derive(Clone, Debug)]
struct Step {
    line: String,
    wait: Option<String>,
}

fn step(line: String) -> Step {
    Step { line, wait: None }
}

/// A random sequence of helper commands, `n` steps long.
fn generate(rng: &mut Rng, n: usize) -> Vec<Step> {
    let ptos = pto_channels();
    let hscs = hsc_channels();
    let mut steps = Vec::new();
    while steps.len() < n {
        let (r, _) = rng.pick(&ptos);
        let ch = r.channel;
        let idle = format!("SM{}.7", r.status);
        let pls = |steps: &mut Vec<Step>| steps.push(Step { line: format!("pls {ch}"), wait: Some(idle.clone()) });
        match rng.below(13) {
            // A pulse train from scratch: `pto` writes SMB67 …, then PLS.
            0 | 1 => {
                let freq = rng.pick(&["2kHz", "5kHz", "10kHz", "20kHz"]);
                let count = rng.in_range(2, 300);
                steps.push(Step { line: format!("pto {ch} freq={freq} count={count}"), wait: Some(idle.clone()) });
            }
            // PLS again with what the SM registers hold, once or several times in a row.
            2 | 3 => {
                for _ in 0..rng.in_range(1, 3) {
                    pls(&mut steps);
                }
            }
            // The PTO registers in one SM write (one helper command), then often PLS.
            4 => {
                let ctl = rng.pick(&["16#85", "16#84", "16#81", "16#D3", "16#D2"]);
                let cycle = rng.in_range(50, 400);
                let width = rng.in_range(0, cycle);
                let count = rng.in_range(2, 300);
                steps.push(step(format!(
                    "set SMB{}={ctl}, SMW{}={cycle}, SMW{}={width}, SMD{}={count}",
                    r.control, r.cycle, r.width, r.count
                )));
                if rng.below(2) == 0 {
                    pls(&mut steps);
                }
            }
            // One register at a time.
            5 => {
                let line = match rng.below(4) {
                    0 => format!("set SMW{}={}", r.cycle, rng.in_range(50, 400)),
                    1 => format!("set SMD{}={}", r.count, rng.in_range(2, 300)),
                    2 => format!("set SMB{}={}", r.pos_control, rng.pick(&[0, 8])),
                    _ => format!("set SM{}.7=0", r.pos_control),
                };
                steps.push(step(line));
            }
            // PSTOP, once or twice; the latch is cleared by an SM write now and then.
            6 | 7 => {
                for _ in 0..rng.in_range(1, 2) {
                    steps.push(step(format!("pstop {ch}")));
                }
                if rng.below(2) == 0 {
                    steps.push(step(format!("set SM{}.7=0", r.pos_control)));
                }
            }
            // PWM (synchronous or asynchronous update).
            8 => {
                let cycle = rng.in_range(100, 2000);
                let width = rng.in_range(0, cycle);
                let sync = if rng.below(2) == 0 { " async" } else { "" };
                steps.push(step(format!("pwm {ch} cycle={cycle}us width={width}us{sync}")));
            }
            // A counter: its registers, HDEF (a mode of its table, or one it lacks), HSC.
            9 | 10 => {
                let h = rng.pick(&hscs);
                let modes: Vec<u8> = HSC_MODES.iter().filter(|m| m.0 == h.channel).map(|m| m.1).collect();
                if rng.below(2) == 0 {
                    steps.push(step(format!(
                        "set SMB{}={}, SMD{}={}, SMD{}={}",
                        h.control,
                        rng.below(256),
                        h.cv,
                        rng.in_range(-1000, 1000),
                        h.pv,
                        rng.in_range(-1000, 1000)
                    )));
                }
                let mode = if rng.below(5) == 0 { rng.in_range(0, 11) as u8 } else { rng.pick(&modes) };
                steps.push(step(format!("hdef {} {mode}", h.channel)));
                for _ in 0..rng.in_range(1, 2) {
                    steps.push(step(format!("hsc {}", h.channel)));
                }
            }
            // Writes the helper and the simulator both refuse (read-only current values).
            11 => {
                let (r2, _) = rng.pick(&ptos);
                steps.push(step(format!("set SMD{}={}", r2.pos_cv, rng.in_range(1, 1000))));
            }
            // The clock: set to a whole ten seconds, read right after.
            _ => {
                let t = format!(
                    "20{:02}-{:02}-{:02}T{:02}:{:02}:{}0",
                    rng.in_range(1, 99),
                    rng.in_range(1, 12),
                    rng.in_range(1, 28),
                    rng.in_range(0, 23),
                    rng.in_range(0, 59),
                    rng.in_range(0, 4)
                );
                steps.push(step(format!("rtc set {t}; rtc")));
            }
        }
    }
    steps.truncate(n);
    steps
}

/// What is compared after every step: the pulse channels' registers (status, control,
/// cycle, width, count, current position, position control byte), the counters' registers
/// (status, control, current value, preset), and the outputs Q0.0 … Q0.7 — but a pulse
/// output while its channel runs PWM (its status byte's "PWM idle" bit is 0).
fn observed() -> (Vec<String>, Vec<(String, String)>) {
    let mut ops = Vec::new();
    let mut pwm = Vec::new();
    for (r, q) in pto_channels() {
        ops.extend([
            format!("SMB{}", r.status),
            format!("SMB{}", r.control),
            format!("SMW{}", r.cycle),
            format!("SMW{}", r.width),
            format!("SMD{}", r.count),
            format!("SMD{}", r.pos_cv),
            format!("SMB{}", r.pos_control),
        ]);
        pwm.push((format!("SM{}.3", r.status), q.to_string()));
    }
    for h in hsc_channels() {
        ops.extend([
            format!("SMB{}", h.status),
            format!("SMB{}", h.control),
            format!("SMD{}", h.cv),
            format!("SMD{}", h.pv),
        ]);
    }
    for b in 0..8 {
        let q = format!("Q0.{b}");
        if !pwm.iter().any(|(_, p)| *p == q) {
            ops.push(q);
        }
    }
    (ops, pwm)
}

/// The Lua script that runs `steps` on the current device and prints, per step, whether
/// each command succeeded, the clock it read (to ten seconds) and the observed state. Whether
/// a command was refused is compared here; how a refusal is worded, by tests/agent.rs
/// (`every_refusal_reads_the_same_through_the_helper_and_in_process`). The simulator
/// follows the manual here: its PLS leaves the CR as it was (K2 §3.4.2), so the helper
/// cannot pass by reading the CR.
fn script(steps: &[Step]) -> String {
    let (ops, pwm) = observed();
    let data = json!({
        "steps": steps.iter().map(|s| json!({"line": s.line, "wait": s.wait})).collect::<Vec<_>>(),
        "observe": ops.join(" "),
        "pwm": pwm.iter().map(|(idle, q)| json!([idle, q])).collect::<Vec<_>>(),
    });
    format!(
        r#"local data = plcsh.json.decode([==[{data}]==])
local function get(ops)
  local r = plcsh.exec("get " .. ops)
  local out = {{}}
  for _, v in ipairs(r.values) do out[#out + 1] = v.operand .. "=" .. tostring(v.value) end
  return out
end
for i, s in ipairs(data.steps) do
  local r = table.pack(pcall(plcsh.exec, s.line))
  local out = {{step = i, ok = r[1], clock = {{}}}}
  if r[1] then
    for k = 2, r.n do
      if r[k].rtc then out.clock[#out.clock + 1] = string.sub(r[k].rtc, 1, 18) end
    end
  end
  if s.wait then
    plcsh.wait_until(function() return plcsh.exec("get " .. s.wait).values[1].value end,
      {{timeout = 10000, every = 1, what = s.wait}})
  end
  out.state = get(data.observe)
  for _, p in ipairs(data.pwm) do
    local idle = plcsh.exec("get " .. p[1]).values[1].value
    out.state[#out.state + 1] = idle and get(p[2])[1] or (p[2] .. " runs PWM")
  end
  print(plcsh.json.encode(out))
end
"#
    )
}

/// A file of this test's own (process id and case), removed on drop.
struct TempFile(PathBuf);

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Runs the script with plcsh `args` and returns the step lines it printed.
fn run_route(what: &str, args: &[&str], script: &std::path::Path, n: usize) -> Vec<Json> {
    let mut all = vec!["--json"];
    all.extend_from_slice(args);
    all.extend(["run", script.to_str().unwrap()]);
    let o = run(&all, "");
    let lines = json_lines(&o);
    let steps: Vec<Json> = lines
        .iter()
        .filter(|l| l["cmd"] == "print")
        .map(|l| serde_json::from_str(l["message"].as_str().unwrap()).unwrap())
        .collect();
    assert!(
        o.status.success() && steps.len() == n,
        "{what}: {} of {n} steps ran\n{}\n{}",
        steps.len(),
        stdout(&o),
        stderr(&o)
    );
    steps
}

/// Runs `steps` through both routes, compares them step by step (`case` names the case in
/// a failure) and returns what the helper route printed.
fn compare(case: &str, steps: &[Step]) -> Vec<Json> {
    let n = steps.len();
    let name = format!("plcsh-agent-diff-{}-{}.lua", std::process::id(), case.replace(' ', "-"));
    let file = TempFile(std::env::temp_dir().join(name));
    std::fs::write(&file.0, script(steps)).unwrap();
    let served = serve(&["--tcp", "0", "--agent", "--model", MODEL]);
    let url = format!("tcp://{}?model={MODEL}&agent=VB3400", served.ready["tcp"].as_str().unwrap());
    let wire = run_route("through the helper", &["--device", &url], &file.0, n);
    drop(served);
    let local = run_route("in process", &["--time", "stepped", "--model", MODEL], &file.0, n);
    for (i, (w, l)) in wire.iter().zip(&local).enumerate() {
        if w != l {
            let lines: Vec<&str> = steps[..=i].iter().map(|s| s.line.as_str()).collect();
            let diff: Vec<String> = match (w["state"].as_array(), l["state"].as_array()) {
                (Some(a), Some(b)) => a
                    .iter()
                    .zip(b)
                    .filter(|(x, y)| x != y)
                    .map(|(x, y)| format!("helper {x}, in process {y}"))
                    .collect(),
                _ => Vec::new(),
            };
            panic!(
                "{case}, step {} `{}`: the routes differ\n  through the helper: {w}\n  in process:         {l}\n  differing: {diff:?}\n  steps: {}",
                i + 1,
                steps[i].line,
                lines.join("; ")
            );
        }
    }
    wire
}

/// Random sequences: after every command the device state through the helper is the
/// simulator's without it.
#[test]
fn helper_commands_leave_the_same_state_as_the_simulator_without_the_helper() {
    let start = std::time::Instant::now();
    let mut lines = Vec::new();
    for seed in (1..=6u64).map(|k| 0xA6E7_0000 + k) {
        let steps = generate(&mut Rng(seed), 50);
        compare(&format!("seed {seed:#x}"), &steps);
        lines.extend(steps.into_iter().map(|s| s.line));
    }
    // The generator reached what it is for: PLS repeated on every channel, PSTOP repeated,
    // PWM, HDEF, HSC, the clock, refusals.
    let has = |p: &str| lines.iter().filter(|l| l.starts_with(p)).count();
    for (ch, _) in pto_channels() {
        let pls = format!("pls {}", ch.channel);
        let twice = lines.windows(2).filter(|w| w[0] == pls && w[1] == pls).count();
        assert!(twice > 0, "PLS {} twice in a row was generated", ch.channel);
        let pstop = format!("pstop {}", ch.channel);
        assert!(lines.windows(2).any(|w| w[0] == pstop && w[1] == pstop), "PSTOP {} twice", ch.channel);
    }
    for p in ["pto ", "pwm ", "hdef ", "hsc ", "rtc set", "set SMB", "set SM2"] {
        assert!(has(p) > 0, "no `{p}` step generated");
    }
    eprintln!("{} steps in {:?}", lines.len(), start.elapsed());
}

/// The reported case, as one sequence: PTO on every channel twice, PSTOP twice with SM writes
/// between — the old helper counted the first train only and latched SM201.7 once.
#[test]
fn repeated_pls_and_pstop_on_every_channel_match_the_simulator() {
    let mut steps = Vec::new();
    for (r, _) in pto_channels() {
        let ch = r.channel;
        let idle = Some(format!("SM{}.7", r.status));
        for _ in 0..2 {
            steps.push(Step { line: format!("pto {ch} freq=2kHz count=100"), wait: idle.clone() });
        }
        steps.push(Step { line: format!("pls {ch}"), wait: idle.clone() });
        steps.push(Step { line: format!("pls {ch}"), wait: idle.clone() });
        steps.push(step(format!("pstop {ch}")));
        steps.push(step(format!("set SMW{}=200", r.cycle)));
        steps.push(step(format!("set SM{}.7=0", r.pos_control)));
        steps.push(step(format!("pstop {ch}")));
    }
    let wire = compare("the repeated instructions", &steps);
    // And the numbers: 4 × 100 pulses on every channel; the latch set after the last PSTOP.
    let state = wire.last().unwrap()["state"].as_array().unwrap().clone();
    for (r, _) in pto_channels() {
        assert!(state.contains(&json!(format!("SMD{}=400", r.pos_cv))), "SMD{}: {state:?}", r.pos_cv);
        let latch = format!("SMB{}=128", r.pos_control);
        assert!(state.contains(&json!(latch)), "{latch}: {state:?}");
    }
}

/// The refusals the helper used to report in its own words, and the HSC table fault it used to
/// report as a refusal, as one sequence: PLS on a value an earlier refused PLS left behind
/// (update bit clear, K2 §3.4.2.2), multi-segment profile tables that break §3.4.2.1's rules and
/// then one that is valid, and HSC with a faulty multi-PV table (§3.3.2: the status bit reports
/// it; the counter runs). Through the helper and in process, every step has the same outcome
/// (refused or done) and leaves the same state.
#[test]
fn kept_values_profile_tables_and_pv_table_faults_match_the_simulator() {
    let idle = Some("SM66.7".to_string());
    let lines = [
        "set SMB67=16#85, SMW68=1000, SMD72=1",
        "pls 0",
        "set SMB67=16#81, SMW68=500",
        "pls 0",
        "set SMB67=16#84, SMD72=1",
        "pls 0",
        "set SMW168=3000, SMB67=16#A0",
        "pls 0",
        "set VB3001=2, VW3002=100, VD3006=10, VW3010=1, VD3014=5, SMW168=3001",
        "pls 0",
        "set VW3010=200",
        "pls 0",
        "hdef 0 0",
        "set SMB141=16#11, SMW142=3000, SMB37=16#80",
        "hsc 0",
        "set VB3101=2, VD3102=100, VD3106=300, SMW142=3101",
        "hsc 0",
    ];
    let steps: Vec<Step> = lines
        .iter()
        .map(|l| Step { line: l.to_string(), wait: l.starts_with("pls").then(|| idle.clone()).flatten() })
        .collect();
    let wire = compare("kept values and tables", &steps);
    let ok: Vec<bool> = wire.iter().map(|s| s["ok"].as_bool().unwrap()).collect();
    // PLS refused three times, the valid profile runs (10 + 5 pulses); HSC runs both times.
    assert_eq!(
        ok,
        [true, false, true, false, true, false, true, false, true, false, true, true, true, true, true, true, true],
        "{wire:?}"
    );
    let state = wire.last().unwrap()["state"].as_array().unwrap().clone();
    assert!(state.contains(&json!("SMD212=15")), "the profile's 15 pulses: {state:?}");
}
