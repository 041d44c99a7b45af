-- Grader of UMPK lab 1 (latch and on-delay), in simulated time.
local u = plcsh.device("lab")
local loaded, why = lab.run()
lab.criterion("program loads", 1, function() return loaded, why, "a program that loads" end)
if not loaded then return end

local function input(i, level) plcsh.exec(("sim input %s=%d"):format(i, level)) end

input("I0", 1)
plcsh.sleep(100)
input("I0", 0)
lab.criterion("start latches Q0", 1, function() lab.expect(u.Q0, true, "Q0 after start") end)
lab.criterion("Q1 after 2.0 s", 2, function()
  plcsh.sleep(1800)
  lab.expect(u.Q1, false, "Q1 at 1.9 s")
  plcsh.sleep(300)
  lab.expect(u.Q1, true, "Q1 at 2.2 s")
end)
input("I1", 1)
plcsh.sleep(100)
input("I1", 0)
lab.criterion("stop resets", 1, function() lab.expect(u.Q0, false, "Q0 after stop") end)
