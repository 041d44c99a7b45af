-- The write directory's path, printed: shown as `write` in the kept output.
print(plcsh.write_dir)
local f = assert(io.open(plcsh.write_dir .. "/x.txt", "w"))
f:write("x")
f:close()
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
