local plc = plcsh.device("plc")
local settings = nil
plc.VW0 = settings.speed
