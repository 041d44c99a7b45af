-- The metatable's own metatable sends new keys to a proxy with __newindex, which stores
-- __close into the metatable itself; the handler raises over a doubling string's memory error.
local function try()
  local mt = {}
  local meta = { __newindex = function(t, k, v) rawset(t, k, v) end }
  setmetatable(mt, meta)
  local guard = setmetatable({}, mt)
  mt.__close = function() error("not memory", 0) end
  local g <close> = guard
  local s = "x"
  while true do s = s .. s end
end
for _ = 1, 3 do pcall(try) end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
