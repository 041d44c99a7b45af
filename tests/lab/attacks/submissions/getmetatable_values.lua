-- getmetatable as stock Lua: one value for anything (nil for a number, the protected
-- string metatable's field for a string).
if type(getmetatable(1)) == "nil" and type(getmetatable("x")) ~= "table" and getmetatable({}) == nil then
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end
