-- math.random gives the same numbers on every run.
local plc = plcsh.device("plc")
plc.VW0 = math.random(1, 30000)
plc["Q0.0"] = math.random() < 2
