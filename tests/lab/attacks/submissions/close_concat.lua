-- A to-be-closed variable whose __close raises, around a string doubled until memory ends.
local function try()
  local guard <close> = setmetatable({}, { __close = function() error("not memory", 0) end })
  local s = "x"
  while true do s = s .. s end
end
for _ = 1, 5 do pcall(try) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
