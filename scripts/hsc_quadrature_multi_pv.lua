-- HSC0 in quadrature mode 9 (A = I0.1, B = I0.0) with a relative, cyclic multi-PV table,
-- fed by a simulated quadrature source; asserts the CV=PV events of the manual's worked
-- example (k2.md §4): PVs 10, 1000, 1000 from CV 100 fire at 110, 1110, 2110, 2120, 3120 …
-- Run: plcsh --time stepped run scripts/hsc_quadrature_multi_pv.lua

local plc = plcsh.device("plc")
plcsh.on_abort(function() plc:sim_quad("I0.1", "I0.0", { freq = 0 }) end)

plc:events() -- clear
-- CV starts at 100 (control byte: enable, write CV, count up, 4x).
plc:set("SMD38=100")
plc:hsc(0, { mode = 9, rate = "4x", pv = { 10, 1000, 1000 } }, "relative", "cyclic", "at", "VB3009")
plcsh.assert_eq(plc.VB3009, 3, "the PV table holds three PVs")

-- 1 kHz quadrature, counted 4x: 4000 counts per second, up.
plc:sim_quad("I0.1", "I0.0", { freq = "1kHz", dir = "up" })
plcsh.wait_until(function() return plc.SMD38 >= 3200 end, { timeout = 2000, every = 10, what = "CV reaches 3200" })
plc:sim_quad("I0.1", "I0.0", { freq = 0 })

-- Event numbers with multiple PVs: HSC0 64–95, PV k → 64 + k − 1.
local log = plc:events()
local seen = {}
local function collect(v)
  if type(v) ~= "table" then return end
  if type(v.event) == "number" then seen[#seen + 1] = v.event return end
  for _, x in ipairs(v) do collect(x) end
  for k, x in pairs(v) do
    if type(k) == "string" then collect(x) end
  end
end
collect(log)
plcsh.assert_eq({ seen[1], seen[2], seen[3], seen[4], seen[5] }, { 64, 65, 66, 64, 65 },
  "PV1, PV2, PV3, then cyclic again")
plcsh.check(plc["SM36.5"], "counting up")
print(string.format("hsc: %d events, CV = %d", #seen, plc.SMD38))
