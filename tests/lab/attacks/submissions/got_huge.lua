-- A long multi-line error after partial work.
local plc = plcsh.device("plc")
plc.VW0 = 1
plc["Q0.0"] = true
error(string.rep("B\n", 100000), 0)
