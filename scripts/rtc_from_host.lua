-- Set the PLC's real-time clock from the host (`rtc sync`), check it, then set it to a
-- fixed time and watch it advance with machine time (k2.md §7). The `rtc` outcome carries
-- the time as text (`rtc`), the weekday (1 = Sunday) and the 8 BCD bytes READ_RTC returns.
-- Run: plcsh --state none --time stepped run scripts/rtc_from_host.lua   (--state none: your own state
-- file, with its clock, stays untouched)

local plc = plcsh.device("plc")

-- "YYYY-MM-DDTHH:MM:SS" → os.time (host local time, as `rtc sync` uses).
local function parse(text)
  local y, mo, d, h, mi, s = text:match("^(%d%d%d%d)%-(%d%d)%-(%d%d)T(%d%d):(%d%d):(%d%d)$")
  plcsh.check(y ~= nil, "rtc is YYYY-MM-DDTHH:MM:SS", text)
  return os.time({ year = y, month = mo, day = d, hour = h, min = mi, sec = s })
end

local host = os.time()
local synced = parse(plc:rtc_sync().rtc)
plcsh.check(math.abs(synced - host) <= 2, "rtc sync sets the host's local time", synced, host)
local read = plc:rtc()
plcsh.check(math.abs(parse(read.rtc) - host) <= 2, "rtc reads it back", read.rtc, host)
plcsh.assert_eq(read.weekday, tonumber(os.date("%w", parse(read.rtc))) + 1, "weekday, 1 = Sunday")

local set = plc:rtc_set("2026-11-22T10:00:00")
plcsh.assert_eq(set.rtc, "2026-11-22T10:00:00")
local r = plc:rtc()
plcsh.assert_eq({ r.rtc, r.weekday }, { "2026-11-22T10:00:00", 1 }, "a Sunday")
plcsh.assert_eq(r.bcd, { 0x26, 0x11, 0x22, 0x10, 0x00, 0x00, 0x00, 0x01 }, "BCD: yy mm dd hh mm ss 0 weekday")

plcsh.sleep(90 * 1000)
r = plc:rtc()
plcsh.assert_eq(r.rtc, "2026-11-22T10:01:30", "the clock runs with machine time")
plcsh.assert_eq(r.bcd, { 0x26, 0x11, 0x22, 0x10, 0x01, 0x30, 0x00, 0x01 })

plcsh.sleep(14 * 3600 * 1000) -- past midnight: Monday
r = plc:rtc()
plcsh.assert_eq({ r.rtc, r.weekday }, { "2026-11-23T00:01:30", 2 }, "the date and weekday roll over")
print(string.format("rtc_from_host: %d checks passed", plcsh.checks))
