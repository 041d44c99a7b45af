-- Snapshots from Lua: set up a starting state once, save it, run, go back to it, run again —
-- the same results, pulse for pulse. Run: plcsh --time stepped run scripts/snapshot_lab.lua
local plc = plcsh.device("plc")
local file = "/tmp/plcsh-snapshot-lab.json" -- a name without a `/` is kept in the data directory
plcsh.on_abort(function() pcall(plc.pstop, plc, 0) end)

plc.VW10 = 42
plc:pto(0, { freq = 2000, count = 1000 }) -- 0.5 s of pulses
plcsh.sleep(100)
local saved_at = plcsh.now()
plcsh.assert_eq(plcsh.snapshot_save(file), file)

local function run()
  plcsh.sleep(200)
  local mid = plc.SMD212 -- pulses out so far, mid-train
  plc.VW10 = plc.VW10 + 1
  plcsh.sleep(1000)
  return mid, plc.SMD212, plc.VW10, plcsh.now() - saved_at
end

local mid1, done1, vw1, dt1 = run()
plcsh.assert_eq(done1, 1000, "the whole train went out")
plcsh.assert_eq(vw1, 43)
local restored = plcsh.snapshot_restore(file)
plcsh.assert_eq(math.floor(restored * 1000 + 0.5), math.floor(saved_at + 0.5), "back to the saved time (ms)")
plcsh.assert_eq(plc.VW10, 42, "memory as saved")
local mid2, done2, vw2, dt2 = run()
plcsh.assert_eq(mid2, mid1, "the same pulses mid-train")
plcsh.assert_eq(done2, done1)
plcsh.assert_eq(vw2, vw1)
plcsh.assert_eq(dt2, dt1)
print(string.format("mid-train %d pulses, then %d, VW10 %d: identical after the restore", mid1, done1, vw1))
