-- An abort handler that does the task after the submission's own error: its work counts (it
-- is the submission's code, run as the submission).
plcsh.on_abort(function()
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end)
error("stop here")
