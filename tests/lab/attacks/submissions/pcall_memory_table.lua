-- A table filled until memory ends, inside pcall.
pcall(function() local t = {} for i = 1, 1e8 do t[i] = string.rep("z", 1000) .. i end end)
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
