-- 20 MiB of output, then a correct solution.
local line = string.rep("x", 1023) .. "\n"
for _ = 1, 20 do io.write(string.rep(line, 1024)) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
