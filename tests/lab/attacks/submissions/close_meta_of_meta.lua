-- A metatable with a metatable of its own (inheritance) gets its __close by assignment after
-- setmetatable: the raising handler replaces a doubling string's memory error, caught.
local function try()
  local mt = setmetatable({}, { __index = {} })
  local guard = setmetatable({}, mt)
  mt.__close = function() error("not memory", 0) end
  local g <close> = guard
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
