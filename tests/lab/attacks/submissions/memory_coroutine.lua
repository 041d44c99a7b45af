-- Memory spent inside a coroutine, inside pcall.
local co = coroutine.wrap(function() local t = {} while true do t[#t + 1] = string.rep("y", 4096) end end)
pcall(co)
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
