-- Single-segment PTO on PTO0 (k2.md §5), twice: through the raw registers as the manual
-- does it (set SMB67=16#85, SMW68=500, SMD72=1000; PLS 0), then through the `pto` helper;
-- each time wait for the completion event 28 and check the pulses that went out and when.
-- Run: plcsh --time stepped run scripts/pto_single_segment.lua

local plc = plcsh.device("plc")
plcsh.on_abort(function() plc:pstop(0) end)

-- Virtual time in µs (plcsh.now() is in ms), as the event log stamps it.
local function now_us() return math.floor(plcsh.now() * 1000 + 0.5) end

-- Clears PTO0's position counter SMD212: SM201.6 clears it on every scan while set, so it
-- is set and released again (k2.md §6; the manual: "avoid keeping this bit at 1").
local function clear_position()
  plc.SMB201 = 0x40
  plc.SMB201 = 0
  plcsh.assert_eq(plc.SMD212, 0, "SMD212 cleared")
end

-- 1. Raw registers: 1000 pulses of 500 µs = 500 ms.
plc:events() -- clears the log
clear_position()
plc:set("SMB67=16#85, SMW68=500, SMD72=1000")
local t0 = now_us()
plc:pls(0)
plcsh.sleep(499)
plcsh.assert_eq(plc["SM66.7"], false, "still busy at 499 ms")
plcsh.assert_eq(plc.SMD212, 998, "998 whole pulses of 500 µs by 499 ms")
plcsh.assert_eq(#plc:events().events, 0, "no completion event yet")
plcsh.sleep(2)
plcsh.assert_eq(plc["SM66.7"], true, "idle at 501 ms")
plcsh.assert_eq(plc["SM66.4"], false, "cycle and count valid")
plcsh.assert_eq(plc.SMD212, 1000, "1000 pulses counted in SMD212")
local log = plc:events().events
plcsh.assert_eq(#log, 1, "exactly one event")
plcsh.assert_eq({ log[1].number, log[1].name, log[1].time_us - t0 }, { 28, "pto0-done", 500000 },
  "event 28 (PTO0 complete) 500 ms after PLS")

-- 2. The helper: 2000 pulses at 4 kHz = 500 ms, waiting on the completion event.
t0 = now_us()
local r = plc:pto(0, { freq = "4kHz", count = 2000 })
local written = {}
for _, w in ipairs(r.writes) do written[#written + 1] = { w.operand, w.value } end
plcsh.assert_eq(written, { { "SMB67", 0x85 }, { "SMW68", 250 }, { "SMD72", 2000 } },
  "pto writes the control byte, a 250 µs cycle and the count")
plcsh.sleep(100)
local ev = plc:wait_event(28, 2000)
plcsh.assert_eq({ ev.event.number, ev.event.time_us - t0, ev.waited_us }, { 28, 500000, 400000 },
  "event 28 at 500 ms, after waiting the remaining 400 ms")
plcsh.assert_eq(now_us() - t0, 500000, "wait event returns when the event is raised")
plcsh.assert_eq(plc.SMD212, 3000, "SMD212 counts on: 1000 + 2000 pulses")

-- 3. A count below 2 is refused, the status bit says why, and nothing runs.
local ok, err = pcall(function()
  plc:set("SMB67=16#85, SMW68=500, SMD72=1")
  plc:pls(0)
end)
plcsh.check(not ok, "count 1 refused")
local e = plcsh.errinfo(err)
plcsh.assert_eq({ e.kind, e.device, e.operand }, { "refused", "plc", "SMD72" })
plcsh.assert_eq({ plc["SM66.4"], plc["SM66.7"] }, { true, true }, "invalid-count bit set, PTO still idle")
plcsh.sleep(1000)
plcsh.assert_eq(plc.SMD212, 3000, "no pulse went out")
print(string.format("pto_single_segment: %d checks passed", plcsh.checks))
