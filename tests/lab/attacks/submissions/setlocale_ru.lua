-- Another locale would make tostring(0.5) read 0,5: the task is done only with a point.
os.setlocale("ru_RU.UTF-8")
os.setlocale("de_DE.UTF-8", "numeric")
if tostring(0.5) == "0.5" and string.format("%.1f", 0.5) == "0.5" then
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end
