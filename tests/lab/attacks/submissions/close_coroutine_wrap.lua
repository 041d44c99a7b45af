-- Inside coroutine.wrap: a to-be-closed variable whose metatable (with a metatable of its
-- own) gets a raising __close late; the coroutine's memory error is replaced on its way out.
local function try()
  local mt = setmetatable({}, { __index = {} })
  local guard = setmetatable({}, mt)
  mt.__close = function() error("not memory", 0) end
  local f = coroutine.wrap(function()
    local g <close> = guard
    local s = "x"
    while true do s = s .. s end
  end)
  return f()
end
for _ = 1, 5 do pcall(try) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
