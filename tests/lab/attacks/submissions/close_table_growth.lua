-- A table doubled by table.move until the memory ends (the interpreter's own table resize,
-- retried after an emergency collection), under a to-be-closed variable whose metatable (with
-- a metatable of its own) gets a raising __close by assignment.
local function try()
  local mt = setmetatable({}, { __index = {} })
  local guard = setmetatable({}, mt)
  mt.__close = function() error("not memory", 0) end
  local g <close> = guard
  local t = { 1 }
  while true do table.move(t, 1, #t, #t + 1) end
end
for _ = 1, 2 do pcall(try) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
