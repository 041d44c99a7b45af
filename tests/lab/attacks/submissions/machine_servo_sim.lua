-- Drives the simulated drive's own controls (a limit switch made by hand).
plcsh.exec("servo sim switch home 0")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
