-- os.time reads simulated time.
local plc = plcsh.device("plc")
plc.VW0 = os.time() % 30000
plc["Q0.0"] = true
