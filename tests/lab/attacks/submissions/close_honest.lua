-- An honest to-be-closed variable: its __close runs (and sees no error) and the task is done.
local closed = false
do
  local guard <close> = setmetatable({}, { __close = function(_, e) closed = (e == nil) end })
end
local Base = { name = "base" }
Base.__index = Base
local Derived = setmetatable({}, { __index = Base })
Derived.__index = Derived
local obj = setmetatable({}, Derived)
if closed and obj.name == "base" then
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end
