-- The __close metamethod given after setmetatable, by assignment and by rawset.
local function try(late)
  local mt = {}
  local guard = setmetatable({}, mt)
  if late then mt.__close = function() error("not memory", 0) end
  else rawset(mt, "__close", function() error("not memory", 0) end) end
  local g <close> = guard
  local s = "x"
  while true do s = s .. s end
end
pcall(try, true)
pcall(try, false)
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
