-- Makes the drive the current device: the grader's commands still reach its own.
plcsh.exec("use servo")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
