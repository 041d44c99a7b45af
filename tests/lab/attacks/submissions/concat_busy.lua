-- Heavy work inside table.concat.
local t = {}
for i = 1, 1024 do t[i] = string.rep("y", 4096) end
for _ = 1, 2000 do local _ = table.concat(t) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
