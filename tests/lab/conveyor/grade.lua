-- Grader of the conveyor lab. lab.run() loads the submission; each lab.criterion runs at
-- once, in simulated time, and says what it expected and what it got.
local plc, servo = plcsh.device("plc"), plcsh.device("servo")

local function press(input)
  plc[input] = true
  plcsh.sleep(50)
  plc[input] = false
  plcsh.sleep(50)
end

local check = require("checks") -- the lab's own module (lab folder)
local loaded, why = lab.run()
lab.criterion("program loads", 1, function()
  if not loaded then return false, why, "a program that loads" end
  return check.running(plc)
end)
if not loaded then return end

lab.criterion("off at power-up", 1, function()
  lab.expect(plc["Q0.0"], false, "Q0.0 before start")
  lab.expect(plc["Q0.1"], false, "Q0.1 before start")
end)

press("I0.0")
lab.criterion("start latches the motor", 2, function()
  lab.expect(plc["Q0.0"], true, "Q0.0 after the start button is released")
end)

lab.criterion("ready lamp after 2 s", 2, function()
  plcsh.sleep(1800) -- 1.9 s after the motor started
  lab.expect(plc["Q0.1"], false, "Q0.1 before 2 s")
  plcsh.sleep(300) -- 2.2 s
  lab.expect(plc["Q0.1"], true, "Q0.1 after 2 s")
end)

press("I0.1")
lab.criterion("stop resets", 2, function()
  lab.expect(plc["Q0.0"], false, "Q0.0 after stop")
  lab.expect(plc["Q0.1"], false, "Q0.1 after stop")
end)

servo.controlword = 6 -- shutdown: the drive's enabled output (I0.2) drops
plcsh.sleep(20)
press("I0.0")
lab.criterion("no start while the drive is disabled", 2, function()
  lab.expect(plc["I0.2"], false, "I0.2 with the drive shut down")
  lab.expect(plc["Q0.0"], false, "Q0.0 after start with the drive disabled")
end)

-- The long run: 10 simulated minutes with the motor on, sampled every 10 s.
servo.controlword = 7
servo.controlword = 15
plcsh.sleep(20)
press("I0.0")
lab.criterion("runs 10 minutes", 1, function()
  for _ = 1, 60 do
    plcsh.sleep(9900)
    lab.expect(plc["Q0.0"], true, "Q0.0 while running")
    lab.expect(plc["Q0.1"], true, "Q0.1 while running")
  end
end)
