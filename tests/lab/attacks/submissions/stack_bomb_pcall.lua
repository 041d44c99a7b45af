-- A caught stack overflow is the student's business; the run goes on.
local function f() return 1 + f() end
pcall(f)
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
