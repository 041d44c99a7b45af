-- os.date reads simulated time.
local plc = plcsh.device("plc")
plc.VW0 = tonumber(os.date("%S")) + tonumber(os.date("%M")) * 60
plc["Q0.0"] = true
error(os.date("%Y-%m-%d %H:%M:%S"), 0)
