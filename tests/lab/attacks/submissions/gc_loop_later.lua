-- Finalizers that loop, run by the collector whenever it likes.
for _ = 1, 1000 do setmetatable({}, { __gc = function() local x = 0 while true do x = x + 1 end end }) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
local t = {}
for i = 1, 1e5 do t[i] = {} end
