-- Teaching demo: an FX PLC blinks Y0 with its 1 s clock M8013 (scripts/fx_blink.il, an FX
-- instruction list run by the simulated FX2N on the scan engine), and this script checks it
-- in virtual time: Y0 changes every 0.5 s, T0 (100 ms timer, K30) turns Y1 on 3 s after X0,
-- C0 counts Y0's blinks and turns Y2 on at the fifth, X1 resets it.
-- Run from the project directory: plcsh --time stepped run scripts/fx_blink.lua

local fx = plcsh.connect("sim-fx:FX2N", "fx")
fx:program_load("scripts/fx_blink.il")
plcsh.assert_eq(fx:program().mode, "RUN", "the PLC runs the program")
plcsh.assert_eq(fx.M8000, true, "RUN monitor")
plcsh.assert_eq(fx.D0, 1234, "MOV K1234 D0 ran in the first scan (M8002)")

-- Y0 for 10 s (and the sample after), every 10 ms: a change every 0.5 s.
local t0 = plcsh.now()
local last, changes = fx.Y0, {}
while plcsh.now() - t0 <= 10000 do
  plcsh.sleep(10)
  local y = fx.Y0
  if y ~= last then table.insert(changes, plcsh.now() - t0) end
  last = y
end
plcsh.assert_eq(#changes, 20, "twenty changes in 10 s")
for k, t in ipairs(changes) do
  plcsh.assert_near(t, 500 * k, 10, "change " .. k .. " (ms)")
end
plcsh.assert_eq(fx.CN0, 5, "C0 counted five blinks and holds at its preset")
plcsh.assert_eq(fx.Y2, true, "C0's contact")

-- X0 on: T0 (K30 × 100 ms) turns Y1 on 3 s later.
fx.X0 = true
local on = plcsh.now()
while not fx.Y1 do
  plcsh.sleep(10)
  if plcsh.now() - on > 4000 then error("Y1 did not come on within 4 s") end
end
plcsh.assert_near(plcsh.now() - on, 3000, 10, "T0 reaches K30 after 3 s")
plcsh.assert_eq(fx.TN0, 30, "TN0 holds at the preset")

-- X1 resets C0; STOP turns the outputs off.
fx.X1 = true
plcsh.sleep(10)
plcsh.assert_eq(fx.CN0, 0, "RST C0")
fx:cpu("stop")
plcsh.assert_eq({ fx.Y0, fx.Y1, fx.M8000 }, { false, false, false }, "STOP: outputs off, M8000 off")
print(string.format("fx blink: %d scans, scan time %.2f ms", fx:program().scans, fx:program().scan_ms))
print("ok")
