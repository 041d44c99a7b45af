-- More than the lab's write cap (64 MiB by default) left in the write directory.
local f = assert(io.open(plcsh.write_dir .. "/big.bin", "wb"))
local s = string.rep("z", 1 << 20)
for _ = 1, 70 do f:write(s) end
f:close()
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
