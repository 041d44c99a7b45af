-- An honest program near the memory limit: 64 MiB kept, then 200 MiB of tables made and
-- dropped in the 32 MiB left. The garbage must be collected as it goes (by the collector's
-- steps, or in an emergency when an allocation is refused, which Lua retries after a full
-- collection): the program runs to its end, as in stock Lua.
local t = { 1 }
while #t < (1 << 22) do table.move(t, 1, #t, #t + 1) end
for _ = 1, 100 do
  local g = {}
  table.move(t, 1, 1 << 16, 1, g)
end
if #t == (1 << 22) then
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
  servo.controlword = 6
  servo.controlword = 7
  servo.controlword = 15
  plc.VW0 = 1234
  plc["Q0.0"] = true
end
