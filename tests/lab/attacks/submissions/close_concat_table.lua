-- A to-be-closed variable whose __close raises, around table.concat past the memory limit.
local function try()
  local guard <close> = setmetatable({}, { __close = function() error("not memory", 0) end })
  local t = {}
  local s = string.rep("q", 1 << 20)
  for i = 1, 200 do t[i] = s end
  return table.concat(t)
end
for _ = 1, 5 do pcall(try) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
