-- io.stdout:write with no newline at the end.
io.stdout:write("starting\n")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
io.stdout:write("move done")
