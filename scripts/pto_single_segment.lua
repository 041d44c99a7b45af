-- Single-segment PTO on PTO0 (k2.md §5), twice: through the raw registers as the manual
-- does it (set SMB67=16#85, SMW68=500, SMD72=1000; PLS 0), then through the `pto` helper;
-- each time wait for the completion event 28 and check the pulses that went out.
-- Run: plcsh --time stepped run scripts/pto_single_segment.lua

local plc = plcsh.device("plc")
plcsh.on_abort(function() plc:pstop(0) end)

local function has_event(outcome, number)
  -- Walks an `events`/`wait event` outcome for an entry with this event number.
  local function walk(v)
    if type(v) == "number" then return v == number end
    if type(v) ~= "table" then return false end
    if v.event == number or v.number == number then return true end
    for _, x in pairs(v) do
      if walk(x) then return true end
    end
    return false
  end
  return walk(outcome)
end

-- 1. Raw registers: 1000 pulses of 500 us = 500 ms.
plc:events() -- clears the log
plc.SMB201 = 0x40 -- clear the current value (bit 6)
plc:set("SMB67=16#85, SMW68=500, SMD72=1000")
local t0 = plcsh.now()
plc:pls(0)
plcsh.sleep(499)
plcsh.assert_eq(plc["SM66.7"], false, "still busy at 499 ms")
plcsh.sleep(2)
plcsh.assert_eq(plc["SM66.7"], true, "idle at 501 ms")
plcsh.assert_eq(plc["SM66.4"], false, "cycle and count valid")
plcsh.check(has_event(plc:events(), 28), "event 28 (PTO0 complete) in the log")
plcsh.assert_eq(plc.SMD212, 1000, "1000 pulses counted in SMD212")

-- 2. The helper: 2000 pulses at 4 kHz = 500 ms, waiting on the completion event.
plc.SMB201 = 0x40
t0 = plcsh.now()
local r = plc:pto(0, { freq = "4kHz", count = 2000 })
plcsh.check(r.ok, "pto accepted")
local ev = plc:wait_event(28, 2000)
plcsh.check(has_event(ev, 28), "wait event returned event 28")
local took = plcsh.now() - t0
plcsh.check(took >= 500 and took < 600, "2000 pulses at 4 kHz take 500 ms", took)
plcsh.assert_eq(plc.SMD212, 2000, "2000 pulses counted")

-- 3. A count below 2 is refused and the status bit says why.
local ok = pcall(function()
  plc:set("SMB67=16#85, SMW68=500, SMD72=1")
  plc:pls(0)
end)
plcsh.check((not ok) or plc["SM66.4"], "count < 2 refused (SM66.4 or an error)")
print(string.format("pto_single_segment: %d checks passed", plcsh.checks))
