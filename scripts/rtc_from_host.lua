-- Set the PLC's real-time clock from the host (`rtc sync`), check it, then set it to a
-- fixed time and watch it advance with machine time (k2.md §7).
-- Run: plcsh --time stepped run scripts/rtc_from_host.lua

local plc = plcsh.device("plc")

-- Finds the first "YYYY-MM-DDTHH:MM:SS" text in an outcome and returns it as os.time.
local function rtc_time(outcome)
  local found
  local function walk(v)
    if found then return end
    if type(v) == "string" then
      local y, mo, d, h, mi, s = v:match("(%d%d%d%d)%-(%d%d)%-(%d%d)[T ](%d%d):(%d%d):(%d%d)")
      if y then found = os.time({ year = y, month = mo, day = d, hour = h, min = mi, sec = s }) end
    elseif type(v) == "table" then
      for _, x in pairs(v) do walk(x) end
    end
  end
  walk(outcome)
  return found
end

local host = os.time()
plc:rtc_sync()
local t = rtc_time(plc:rtc())
plcsh.check(t ~= nil, "rtc shows a date and time")
plcsh.check(math.abs(t - host) <= 5, "the PLC clock matches the host's", t, host)

plc:rtc_set("2026-11-22T10:00:00")
local set = rtc_time(plc:rtc())
plcsh.assert_eq(os.date("%Y-%m-%dT%H:%M:%S", set), "2026-11-22T10:00:00")
plcsh.sleep(90 * 1000)
plcsh.assert_eq(os.date("%Y-%m-%dT%H:%M:%S", rtc_time(plc:rtc())), "2026-11-22T10:01:30",
  "the clock runs with machine time")
print("rtc_from_host: ok")
