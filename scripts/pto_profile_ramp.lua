-- A multi-segment PTO profile computed in Lua from a target speed and a ramp (k2.md §5):
-- accelerate from START_HZ to TARGET_HZ in RAMP_MS over STEPS segments, run at speed, and
-- decelerate symmetrically. The table goes to an odd V address outside the E2PROM area.
-- Run: plcsh --time stepped run scripts/pto_profile_ramp.lua [TARGET_HZ] [RAMP_MS] [HOLD_PULSES]

local plc = plcsh.device("plc")
plcsh.on_abort(function() plc:pstop(0) end)

local TARGET_HZ = tonumber(arg[1] or "20000")
local RAMP_MS = tonumber(arg[2] or "200")
local HOLD = tonumber(arg[3] or "10000")
local START_HZ, STEPS = 1000, 10

-- One segment per ramp step: the step's mid frequency for RAMP_MS / STEPS.
local function ramp(from, to)
  local segs = {}
  for i = 1, STEPS do
    local f = from + (to - from) * (i - 0.5) / STEPS
    local cycle = math.floor(1e6 / f + 0.5) -- µs, 1 µs time base
    local count = math.max(1, math.floor(f * RAMP_MS / STEPS / 1000 + 0.5))
    segs[#segs + 1] = { cycle = cycle .. "us", count = count, _cycle = cycle }
  end
  return segs
end

local segments = ramp(START_HZ, TARGET_HZ)
local cycle_at_speed = math.floor(1e6 / TARGET_HZ + 0.5)
segments[#segments + 1] = { cycle = cycle_at_speed .. "us", count = HOLD, _cycle = cycle_at_speed }
for _, s in ipairs(ramp(TARGET_HZ, START_HZ)) do segments[#segments + 1] = s end
plcsh.check(#segments <= 64, "at most 64 segments")

local pulses, us = 0, 0
local table_rows = {}
for i, s in ipairs(segments) do
  pulses = pulses + s.count
  us = us + s.count * s._cycle
  table_rows[i] = { i, s._cycle, s.count, math.floor(1e6 / s._cycle) }
  s._cycle = nil
end
plcsh.table(table_rows, { "segment", "cycle µs", "pulses", "Hz" })

plc.SMB201 = 0x40 -- clear the current value
plc:events()
local t0 = plcsh.now()
plc:profile(0, "VB3001", segments)
plc:pls(0)
plc:wait_event(28, math.ceil(us / 1000) + 1000)
local took = plcsh.now() - t0

plcsh.assert_eq(plc.SMD212, pulses, "every segment's pulses went out")
plcsh.check(took >= us / 1000, "the profile takes the sum of its segments", took, us / 1000)
plcsh.check(took < us / 1000 + 50, "and not much more", took, us / 1000)
plcsh.assert_eq(plc["SM66.7"], true, "PTO0 idle afterwards")
print(string.format("profile: %d segments, %d pulses, %.1f ms", #segments, pulses, us / 1000))
