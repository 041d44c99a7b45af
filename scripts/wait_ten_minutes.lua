-- Waits ten minutes of machine time. With --time stepped the simulator's clock jumps, so
-- this finishes in milliseconds; on a real clock it takes ten real minutes.
-- Run: plcsh --time stepped run scripts/wait_ten_minutes.lua

local plc = plcsh.device("plc")
if not plcsh.stepped() then
  error("run with --time stepped (this script waits 10 minutes of machine time)")
end

local t0 = plcsh.now()
plcsh.assert_eq(plc["SM0.1"], true, "first scan at power-up")

-- SM0.5 is the 1-second clock: on for 0.5 s, off for 0.5 s (k2.md §8).
local edges, last = 0, plc["SM0.5"]
plcsh.wait_until(function()
  local now = plc["SM0.5"]
  if now and not last then edges = edges + 1 end
  last = now
  return plcsh.now() - t0 >= 10 * 60 * 1000
end, { every = 250, timeout = 11 * 60 * 1000 })

plcsh.assert_eq(plcsh.now() - t0, 600000.0, "ten simulated minutes")
plcsh.assert_eq(edges, 600, "one SM0.5 rising edge per second")
plcsh.assert_eq(plc["SM0.1"], false, "first scan is long over")
plcsh.sleep(60 * 1000)
plcsh.assert_eq(plcsh.now() - t0, 660000.0, "plcsh.sleep advances the clock too")
print(string.format("waited %.0f simulated seconds", (plcsh.now() - t0) / 1000))
