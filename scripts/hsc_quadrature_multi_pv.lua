-- HSC0 in quadrature mode 9 (A = I0.1, B = I0.0) with a relative, cyclic multi-PV table,
-- fed by a simulated quadrature source; asserts the CV=PV events of the manual's worked
-- example (k2.md §4): PVs 10, 1000, 1000 from CV 100 fire at 110, 1110, 2110, 2120, 3120 …
-- Run: plcsh --time stepped run scripts/hsc_quadrature_multi_pv.lua

local plc = plcsh.device("plc")
-- On an error or Ctrl-C, stop the signal (pcall: it may already be off).
plcsh.on_abort(function() pcall(plc.sim_off, plc, "I0.1") end)

local FREQ_HZ = 1000
local COUNTS_PER_S = 4 * FREQ_HZ -- quadrature counted 4x
local US_PER_COUNT = 1000000 // COUNTS_PER_S

-- Virtual time in whole µs (plcsh.now() is in ms), as the event log stamps it.
local function now_us() return math.floor(plcsh.now() * 1000 + 0.5) end

plc:events() -- clear
local r = plc:hsc(0, { mode = 9, rate = "4x", pv = { 10, 1000, 1000 }, relative = true, cyclic = true,
  at = "VB3009", cv = 100 })
local written = {}
for _, w in ipairs(r.writes) do written[w.operand] = w.value end
plcsh.assert_eq({ written.SMW142, written.VB3009, written["VD3010/DINT"], written["VD3014/DINT"] },
  { 3009, 3, 10, 1000 }, "PV table at VB3009: 3 PVs")
plcsh.assert_eq(written.SMB141, 0x17, "multi-PV, relative, cyclic, load table")
plcsh.assert_eq({ plc.VB3009, plc.SMD38, plc.SMB140 }, { 3, 100, 0 }, "table, CV 100, segment 0")

-- 1 kHz quadrature, A leading: 4000 counts per second, up.
local t0 = now_us()
plc:sim_quad("I0.1", "I0.0", { freq = FREQ_HZ, dir = "up" })
plcsh.wait_until(function() return plc.SMD38 >= 3200 end, { timeout = 2000, every = 10, what = "CV reaches 3200" })
plc:sim_off("I0.1")
local cv = plc.SMD38
plcsh.sleep(100)
plcsh.assert_eq(plc.SMD38, cv, "the source is off: CV holds")

-- Event numbers with multiple PVs: HSC0 64–95, PV k → 64 + k − 1; the CV at each event is
-- the manual's sequence, so the time between events is the counts between them.
local log = plc:events().events
local want = {
  { number = 64, pv = 1, cv = 110 },
  { number = 65, pv = 2, cv = 1110 },
  { number = 66, pv = 3, cv = 2110 },
  { number = 64, pv = 1, cv = 2120 },
  { number = 65, pv = 2, cv = 3120 },
}
plcsh.assert_eq(#log, #want, "five CV = PV events up to CV 3200")
-- The simulated A signal starts low: the first count comes one period after the source
-- starts, then one count every quarter period.
local first_us = t0 + 1000000 // FREQ_HZ
for i, w in ipairs(want) do
  local e = log[i]
  plcsh.assert_eq({ e.number, e.pv, e.kind }, { w.number, w.pv, "hsc_cv_eq_pv" }, "event " .. i)
  plcsh.assert_eq(e.time_us, first_us + (w.cv - 101) * US_PER_COUNT, "event " .. i .. " at CV " .. w.cv)
end
plcsh.assert_eq({ plc["SM36.5"], plc.SMB140 }, { true, 2 }, "counting up, next PV is PV3")
print(string.format("hsc: %d events, CV = %d", #log, plc.SMD38))
