-- Reads the PLC's clock: the lab's epoch on every machine, at every hour.
if plcsh.exec("rtc plc").rtc == "2026-01-01T00:00:00" then
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end
