-- Teaching lab: a conveyor counting boxes with CTU and an edge interrupt
-- (scripts/conveyor.il). A box that passes within one scan is seen by the interrupt only.
-- Run from the project directory: plcsh --time stepped run scripts/conveyor.lua

local plc = plcsh.device("plc")
plc:program_load("scripts/conveyor.il")
plcsh.sleep(5)
plcsh.assert_eq(plc["Q0.0"], true, "the belt runs")

-- Four boxes, each blocking the barrier for 20 ms.
local function box(ms)
  plc["I0.0"] = true
  if ms > 0 then plcsh.sleep(ms) end
  plc["I0.0"] = false
  plcsh.sleep(20)
end
for _ = 1, 4 do box(20) end
plcsh.assert_eq({ plc.C1, plc.VW20 }, { 4, 4 }, "four boxes: CTU and interrupt agree")
plcsh.assert_eq(plc["Q0.0"], true, "still running")

-- A box faster than a scan: the interrupt sees its edge, the scan never sees the input on.
box(0)
plcsh.assert_eq({ plc.C1, plc.VW20 }, { 4, 5 }, "only the interrupt counted the short pulse")

box(20)
plcsh.assert_eq(plc.C1, 5, "fifth box counted by CTU")
plcsh.assert_eq({ plc["Q0.1"], plc["Q0.0"] }, { true, false }, "batch complete: belt stops")

-- Reset the batch.
plc["I0.2"] = true
plcsh.sleep(5)
plc["I0.2"] = false
plcsh.sleep(5)
plcsh.assert_eq({ plc.C1, plc["Q0.0"] }, { 0, true }, "reset: counting again, belt on")
local st = plc:program()
print(string.format("conveyor: %d scans, %d boxes seen by the interrupt", st.scans, plc.VW20))
print("ok")
