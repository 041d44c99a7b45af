-- A 3 s os.clock busy loop: the same verdict on every machine.
local t = os.clock()
while os.clock() - t < 3 do end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
