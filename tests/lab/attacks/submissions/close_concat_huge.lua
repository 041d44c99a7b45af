-- Concatenation of two huge strings under a to-be-closed variable whose late __close raises.
local half = string.rep("h", 40 << 20)
local function try()
  local mt = setmetatable({}, { __index = {} })
  local guard = setmetatable({}, mt)
  mt.__close = function() error("not memory", 0) end
  local g <close> = guard
  local s = half .. half
  return s .. s .. half
end
for _ = 1, 5 do pcall(try) end
half = nil
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
