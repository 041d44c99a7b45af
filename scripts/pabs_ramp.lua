-- Teaching lab: PABS from an IL program (scripts/pabs_ramp.il) — a 10 000-pulse move with a
-- 125 Hz → 10 kHz ramp over 100 ms. Samples the position every 10 ms, checks the ramp's
-- shape (accelerate, cruise, decelerate) and the end position, and plots SMD212 over time.
-- Run from the project directory: plcsh --time stepped run scripts/pabs_ramp.lua

local plc = plcsh.device("plc")
plc:program_load("scripts/pabs_ramp.il")
plc.SMB201 = 0x40 -- clear the position counter (SM201.6), then release it
plc.SMB201 = 0
plc["M0.0"] = true -- EXEC

local pos, hz = {}, {}
local last = plc["SMD212/DINT"]
for k = 1, 120 do
  plcsh.sleep(10)
  local p = plc["SMD212/DINT"]
  pos[k], hz[k] = p, (p - last) * 100 -- pulses per 10 ms → Hz
  last = p
end
-- Accelerating over the first 100 ms, cruising at 10 kHz, decelerating in the last 100 ms.
plcsh.check(hz[2] < hz[5] and hz[5] < hz[9], "accelerating: " .. hz[2] .. " < " .. hz[5] .. " < " .. hz[9])
plcsh.assert_near(hz[50], 10000, 200, "cruise frequency (Hz)")
local stop_k
for k = 20, 120 do
  if pos[k] == 10000 then stop_k = k break end
end
plcsh.check(stop_k ~= nil, "the move ended")
plcsh.check(hz[stop_k - 5] < hz[stop_k - 12], "decelerating before the end")
plcsh.assert_eq({ plc["M0.1"], plc["M0.2"], plc["SMD212/DINT"] }, { true, false, 10000 }, "DONE at POS")
-- Accel + decel ≈ 2 × 506 pulses at a mean 5 kHz, cruise 8 990 pulses at 10 kHz: ≈ 1.1 s.
plcsh.assert_near(stop_k * 10, 1100, 30, "move time (ms)")

-- The same move traced and plotted: a braille chart in the terminal, and an SVG picture
-- when a file is given (plcsh --time stepped run scripts/pabs_ramp.lua ramp.svg).
plc.SMB201 = 0x40
plc.SMB201 = 0
plc["M0.0"] = false
plcsh.sleep(5)
plc["M0.0"] = true
plc:cmd("trace SMD212/DINT every=10ms for=1200ms")
local chart = plc:cmd("plot" .. (arg[1] and (" to=" .. arg[1]) or ""))
plcsh.check(chart ~= nil, "plotted")
print("ok")
