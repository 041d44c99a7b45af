-- Heavy work inside a C function: a few Lua instructions, gigabytes of bytes.
for _ = 1, 2000 do local _ = string.rep("x", 1 << 22) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
