-- A multi-segment PTO profile computed in Lua from a target speed and a ramp (k2.md §5):
-- accelerate from START_HZ to TARGET_HZ in RAMP_MS over STEPS segments, run at speed, and
-- decelerate symmetrically. The table goes to an odd V address outside the E2PROM area.
-- Checks the table in V memory, the pulses counted at the end of the ramp-up, the total
-- pulse count, and that the completion event comes exactly after the sum of the segments.
-- Run: plcsh --time stepped run scripts/pto_profile_ramp.lua [TARGET_HZ] [RAMP_MS] [HOLD_PULSES]

local plc = plcsh.device("plc")
plcsh.on_abort(function() plc:pstop(0) end)

local TARGET_HZ = tonumber(arg[1] or "20000")
local RAMP_MS = tonumber(arg[2] or "200")
local HOLD = tonumber(arg[3] or "10000")
local START_HZ, STEPS, AT = 1000, 10, 3001

-- Virtual time in whole µs (plcsh.now() is in ms), as the event log stamps it.
local function now_us() return math.floor(plcsh.now() * 1000 + 0.5) end

-- One segment per ramp step: the step's mid frequency for RAMP_MS / STEPS. A cycle given
-- as a number is in µs (the 1 µs time base).
local function ramp(from, to)
  local segs = {}
  for i = 1, STEPS do
    local f = from + (to - from) * (i - 0.5) / STEPS
    local cycle = math.floor(1e6 / f + 0.5)
    local count = math.max(1, math.floor(f * RAMP_MS / STEPS / 1000 + 0.5))
    segs[#segs + 1] = { cycle = cycle, count = count }
  end
  return segs
end

local segments = ramp(START_HZ, TARGET_HZ)
segments[#segments + 1] = { cycle = math.floor(1e6 / TARGET_HZ + 0.5), count = HOLD }
for _, s in ipairs(ramp(TARGET_HZ, START_HZ)) do segments[#segments + 1] = s end
plcsh.check(#segments <= 64, "at most 64 segments")

local pulses, us, ramp_pulses, ramp_us = 0, 0, 0, 0
local rows = {}
for i, s in ipairs(segments) do
  pulses = pulses + s.count
  us = us + s.count * s.cycle
  if i <= STEPS then ramp_pulses, ramp_us = pulses, us end
  rows[i] = { i, s.cycle, s.count, math.floor(1e6 / s.cycle) }
end
plcsh.table(rows, { "segment", "cycle µs", "pulses", "Hz" })

-- Clear the position counter (SM201.6 acts while set, so release it again).
plc.SMB201 = 0x40
plc.SMB201 = 0
plc:events()
local t0 = now_us()
local r = plc:profile(0, "VB" .. AT, segments) -- writes the table, SMW168, SMB67=16#A0, then PLS
plcsh.assert_eq({ r.timeline.total_pulses, r.timeline.duration_us }, { pulses, us }, "the helper's plan")

-- The table as the manual lays it out: count byte, then 8 bytes per segment.
plcsh.assert_eq({ plc["VB" .. AT], plc.SMW168, plc.SMB67 }, { #segments, AT, 0xA0 })
for i, s in ipairs(segments) do
  local base = AT + 1 + (i - 1) * 8
  plcsh.assert_eq({ plc["VW" .. base], plc["VD" .. (base + 4)] }, { s.cycle, s.count }, "segment " .. i)
end

-- At the end of the ramp-up exactly the ramp's pulses are out.
plcsh.sleep(ramp_us / 1000)
plcsh.assert_eq(plc.SMD212, ramp_pulses, "pulses at the end of the ramp-up")
plcsh.assert_eq(plc["SM66.7"], false, "PTO0 busy at speed")

local ev = plc:wait_event(28, math.ceil(us / 1000) + 1000)
plcsh.assert_eq(ev.event.time_us - t0, us, "the profile takes the sum of its segments")
plcsh.assert_eq(now_us() - t0, us, "the wait returns at the completion")
plcsh.assert_eq(plc.SMD212, pulses, "every segment's pulses went out")
plcsh.assert_eq(plc["SM66.7"], true, "PTO0 idle afterwards")
plcsh.assert_eq(plc["SM66.5"], false, "not aborted")
print(string.format("profile: %d segments, %d pulses, %.3f ms", #segments, pulses, us / 1000))
