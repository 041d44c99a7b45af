-- Teaching lab: a traffic light written in IL (scripts/traffic_light.il) runs in the
-- simulated K2's scan engine; this script loads it and grades the sequence.
-- Run from the project directory: plcsh --time stepped run scripts/traffic_light.lua

local plc = plcsh.device("plc")
plc:program_load("scripts/traffic_light.il")
plcsh.assert_eq(plc:program().mode, "RUN", "the CPU runs the program")

local function lamps() return { plc["Q0.0"], plc["Q0.1"], plc["Q0.2"] } end

plcsh.assert_eq(lamps(), { true, false, false }, "red at start-up")
plc["I0.0"] = true
local t0 = plcsh.now()
-- Sample every 100 ms for 20 s and note when each lamp comes on.
local on_at, last = {}, lamps()
while plcsh.now() - t0 < 20000 do
  plcsh.sleep(100)
  local now = lamps()
  for i = 1, 3 do
    if now[i] and not last[i] then table.insert(on_at, { i, plcsh.now() - t0 }) end
  end
  local n = (now[1] and 1 or 0) + (now[2] and 1 or 0) + (now[3] and 1 or 0)
  plcsh.assert_eq(n, 1, "exactly one lamp at a time")
  last = now
end
-- green after 5 s of red, yellow 4 s later, red 1 s later: green at ~5 s, yellow ~9 s, red ~10 s, green ~15 s.
local want = { { 2, 5000 }, { 3, 9000 }, { 1, 10000 }, { 2, 15000 }, { 3, 19000 } }
plcsh.assert_eq(#on_at, #want, "five changes in 20 s")
for k, w in ipairs(want) do
  plcsh.assert_eq(on_at[k][1], w[1], "change " .. k .. ": lamp")
  plcsh.assert_near(on_at[k][2], w[2], 150, "change " .. k .. ": time (ms)")
end
plcsh.assert_eq(plc.VW0, 1, "one full cycle counted")
local st = plc:program()
print(string.format("traffic light: %d scans, scan time %.3f ms", st.scans, st.scan_ms))
print("ok")
