-- A class hierarchy: the metatable's __index chain reaches a base whose __close raises; the
-- subclass copies it in after the object is made. A doubling string, caught.
local Base = {}
Base.__close = function() error("not memory", 0) end
local Class = setmetatable({}, { __index = Base })
Class.__index = Class
local function try()
  local obj = setmetatable({}, Class)
  Class.__close = Class.__close
  local g <close> = obj
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
