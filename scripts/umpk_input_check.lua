-- UMPK16 input check through the real-time monitor (manual §4.1.11): each input switched on
-- in turn must show in the monitor stream, alone, while the outputs stay off (Wait mode:
-- no program, outputs forced off, §3.4). On the simulator the inputs are switched with
-- `umpk sim input`; the same monitor reading works on a real controller
-- (--device lab=umpk:/dev/ttyUSB0, the inputs then switched by hand).
-- Run: plcsh --time stepped run scripts/umpk_input_check.lua

local lab = plcsh.connect("sim-umpk:UMPK16", "lab")
local info = lab:umpk_info()
plcsh.assert_eq({ info.model, info.mode, info.inputs, info.outputs }, { "UMPK16", "Wait", 16, 8 }, "controller info")
plcsh.assert_eq(lab:umpk_errors().codes, {}, "the error history is empty")

for i = 0, info.inputs - 1 do
  lab:umpk_sim_input(("I%d=1"):format(i))
  local m = lab:umpk_monitor({ count = 2 })
  plcsh.assert_eq(m.samples, 2)
  for k = 0, info.inputs - 1 do
    plcsh.assert_eq(m.columns["I" .. k][2], k == i and 1 or 0, ("I%d while I%d is on"):format(k, i))
  end
  for q = 0, info.outputs - 1 do
    plcsh.assert_eq(m.columns["Q" .. q][2], 0, ("Q%d is off in Wait mode"):format(q))
  end
  lab:umpk_sim_input(("I%d=0"):format(i))
end

-- A square wave on I2 at 10 Hz: 50 ms on, 50 ms off, seen once per 10 ms cycle.
lab:umpk_sim_input("I2", { freq = "10Hz" })
local m = lab:umpk_monitor({ ms = 990, every = 10 })
local on = 0
for _, v in ipairs(m.columns.I2) do on = on + v end
plcsh.assert_eq({ m.packets, on }, { 100, 50 }, "a 10 Hz square wave over one second of cycles")
print(("checked %d inputs; I2 square wave on in %d of %d cycles"):format(info.inputs, on, m.packets))
