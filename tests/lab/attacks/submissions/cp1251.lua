-- Сохранено в Windows-1251: строки остаются такими, как написаны.
local s = "Привет"
if #s == 6 then
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end
