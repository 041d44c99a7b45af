-- The raising __close catches a memory error of its own with pcall before raising over the
-- first one: a caught string.rep of 1 GiB inside the handler, over a doubling string's.
local function try()
  local mt = setmetatable({}, { __index = {} })
  local guard = setmetatable({}, mt)
  mt.__close = function()
    pcall(string.rep, "y", 1 << 30)
    error("not memory", 0)
  end
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
