-- An endless loop in a resumed coroutine (resume catches errors).
coroutine.resume(coroutine.create(function() while true do end end))
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
