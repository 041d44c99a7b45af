-- Fault injection on the simulated K2 (k2/sim/fault.rs): a commissioning script meets a PLC
-- that stops answering for a moment and refuses one range, and finds each fault in the event
-- log at the virtual time it acted.
-- Run: plcsh --time stepped run scripts/fault_injection.lua

local plc = plcsh.device("plc")
plc:events() -- clear

plc:inject_fault("no-reply on VW100 after=1s times=1")
plc:inject_fault("exception 2 on MB0..MB3 after=2s for=1s")

plc.VW100 = 7
plcsh.sleep(1000)
local ok, err = pcall(function() return plc.VW100 end)
plcsh.assert_eq(ok, false, "no reply at 1 s")
plcsh.check(tostring(err):find("injected fault 1", 1, true), "the error names the fault: " .. tostring(err))
plcsh.assert_eq(plcsh.errinfo(err).kind, "link")
plcsh.assert_eq(plc.VW100, 7, "times=1: the next read is answered")

plcsh.sleep(1000)
ok, err = pcall(function() plc.MB2 = 1 end)
plcsh.assert_eq(ok, false, "MB2 refused from 2 s")
plcsh.assert_eq(plcsh.errinfo(err).kind, "refused")
plcsh.check(tostring(err):find("illegal data address", 1, true), tostring(err))
plcsh.sleep(1000)
plc.MB2 = 1
plcsh.assert_eq(plc.MB2, 1, "the window closed at 3 s")

local log = plc:events().events
plcsh.assert_eq(#log, 2, "two faults acted")
plcsh.assert_eq({ log[1].name, log[1].time_us, log[2].name, log[2].time_us },
  { "fault1", 1000000, "fault2", 2000000 }, "each at its virtual time")
print("faults observed: " .. log[1].name .. ", " .. log[2].name)
