//! `plcsh lab new NAME`: a working example lab to start from — a K2 and a servo drive wired
//! together (the drive's `enabled` output on the PLC's I0.2), an IL starter for the students,
//! the reference solution, and a Lua grader with one criterion per behaviour. `plcsh lab
//! check NAME` passes on it as written (a test keeps it so).

/// The files of the example, `(name, text)`.
pub const FILES: &[(&str, &str)] = &[
    (
        "lab.toml",
        r#"# A plcsh lab: `plcsh lab check .` runs the grader on the reference solution,
# `plcsh lab grade . SUBMISSIONS...` grades students' files (.il or .lua).
title = "Conveyor start/stop with drive interlock"
bench = "bench.toml"          # the machine: devices, wiring, initial values
starter = ["starter.il"]      # what students get
reference = "reference.il"    # the teacher's solution (lab check grades it)
grader = "grade.lua"          # criteria, in Lua
device = "plc"                # where an IL submission is loaded

[budget]                      # per submission; verdicts name the limit passed
sim_time = "10min"
instructions = 50_000_000
memory = "256MiB"
wall = "60s"                  # safety net only: the other limits do not depend on the machine

[points]                      # every criterion, with its points (the grader may add more)
"start latches the motor" = 3
"ready lamp after 2 s" = 2
"stop resets" = 2
"no start while the drive is disabled" = 3
"#,
    ),
    (
        "bench.toml",
        r#"# A K2 and a Kinco drive; the drive's "enabled" output is wired to the PLC's I0.2.
name = "conveyor"
current = "plc"
wires = ["servo:enabled -> plc:I0.2"]
# The DS402 enable sequence: shutdown, switch on, enable operation.
init = ["servo:controlword=6", "servo:controlword=7", "servo:controlword=15"]

[devices]
plc = "sim:K205-16DT"
servo = "sim-servo:?id=1"
"#,
    ),
    (
        "starter.il",
        r#"(* Conveyor lab. Inputs: I0.0 start button, I0.1 stop button, I0.2 drive enabled.
   Outputs: Q0.0 motor (latched by start while the drive is enabled, reset by stop),
   Q0.1 ready lamp (on 2 s after the motor starts; timer T37 counts 100 ms steps). *)

(* Network 1: motor latch *)
LD      %I0.0
=       %Q0.0
"#,
    ),
    (
        "reference.il",
        r#"(* Conveyor lab, reference solution. *)

(* Network 1: motor latch: start, held by Q0.0, only while the drive is enabled; stop wins *)
LD      %I0.0
O       %Q0.0
A       %I0.2
AN      %I0.1
=       %Q0.0

(* Network 2: ready lamp 2 s (20 × 100 ms) after the motor starts *)
LD      %Q0.0
TON     T37, 20
=       %Q0.1
"#,
    ),
    (
        "grade.lua",
        r#"-- Grader of the conveyor lab. lab.run() loads the submission; each lab.criterion runs at
-- once, in simulated time, and says what it expected and what it got. Every criterion checks
-- something the task asks for: the starter as handed out, or an empty program, gets 0 points
-- (`lab check` warns about a criterion such a program passes).
local plc, servo = plcsh.device("plc"), plcsh.device("servo")

local function press(input)
  plc[input] = true
  plcsh.sleep(50)
  plc[input] = false
  plcsh.sleep(50)
end

local loaded, why = lab.run()
if not loaded then
  -- A program that does not load gets no criterion; each says why.
  for _, name in ipairs({ "start latches the motor", "ready lamp after 2 s", "stop resets",
    "no start while the drive is disabled" }) do
    lab.criterion(name, nil, function() return false, why, "a program that loads" end)
  end
  return
end

local off_at_start = plc["Q0.0"] == false and plc["Q0.1"] == false
press("I0.0")
local started = plc["Q0.0"]
lab.criterion("start latches the motor", 3, function()
  lab.expect(off_at_start, true, "Q0.0 and Q0.1 off before start")
  lab.expect(started, true, "Q0.0 after the start button is released")
end)

lab.criterion("ready lamp after 2 s", 2, function()
  plcsh.sleep(1800) -- 1.9 s after the motor started
  lab.expect(plc["Q0.1"], false, "Q0.1 before 2 s")
  plcsh.sleep(300) -- 2.2 s
  lab.expect(plc["Q0.1"], true, "Q0.1 after 2 s")
end)

local running = plc["Q0.0"]
press("I0.1")
lab.criterion("stop resets", 2, function()
  lab.expect(running, true, "Q0.0 running before stop")
  lab.expect(plc["Q0.0"], false, "Q0.0 after stop")
  lab.expect(plc["Q0.1"], false, "Q0.1 after stop")
end)

servo.controlword = 6 -- shutdown: the drive's enabled output (I0.2) drops
plcsh.sleep(20)
press("I0.0")
lab.criterion("no start while the drive is disabled", 3, function()
  lab.expect(started, true, "Q0.0 started while the drive was enabled")
  lab.expect(plc["I0.2"], false, "I0.2 with the drive shut down")
  lab.expect(plc["Q0.0"], false, "Q0.0 after start with the drive disabled")
end)
"#,
    ),
];
