-- A late __close that returns a fresh error object (a table) and a loop that keeps going: no
-- error text ever says "memory" again.
local function try()
  local mt = setmetatable({}, { __index = {} })
  local guard = setmetatable({}, mt)
  mt.__close = function() error({ fine = true }) end
  local g <close> = guard
  local s = "x"
  while true do s = s .. s end
end
local caught = 0
for _ = 1, 5 do
  local ok, e = pcall(try)
  if type(e) == "table" and e.fine then caught = caught + 1 end
end
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
