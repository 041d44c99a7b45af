-- The folder submission's own module.
local M = {}
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
function M.enable()
  servo.controlword = 6
  servo.controlword = 7
  servo.controlword = 15
end
function M.answer()
  plc.VW0 = 1234
  plc["Q0.0"] = true
end
return M
