-- plcsh.show and print of a table with a function in it show no address.
local shown = plcsh.show({ f = print, t = {} })
print({ print })
if not shown:find("0x") then
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end
