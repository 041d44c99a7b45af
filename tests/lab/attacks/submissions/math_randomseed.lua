-- Reseeding from the time changes nothing between runs.
math.randomseed(os.time())
local plc = plcsh.device("plc")
plc.VW0 = math.random(1, 30000)
plc["Q0.0"] = true
