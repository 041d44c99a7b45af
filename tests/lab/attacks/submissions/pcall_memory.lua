-- pcall cannot catch the memory limit.
for _ = 1, 100 do pcall(string.rep, "x", 1e9) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
