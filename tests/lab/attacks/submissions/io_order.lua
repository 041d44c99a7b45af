-- print and io.write in turn: kept in the order written.
io.write("one\n")
print("two")
io.write("three\n")
print("four")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
