-- A combined sequence: the K2 drives a stepper axis with PTO0 while the servo drive makes a
-- relative move; both finish, both are verified; everything is stopped on Ctrl-C.
-- Run: plcsh --time stepped run scripts/k2_and_servo.lua

local commission = require("commission")
local plc = plcsh.device("plc")
local servo = plcsh.device("servo")
plcsh.on_abort(function() plc:pstop(0) end)
plcsh.on_abort(function() servo:disable() end)

-- Virtual time in whole µs (plcsh.now() is in ms), as the event log stamps it.
local function now_us() return math.floor(plcsh.now() * 1000 + 0.5) end

local c = commission.new("K2 + servo combined move")
local start, t0, done

c:step("servo enabled in position mode", function()
  servo:fault_reset()
  plcsh.assert_eq(servo:mode("position").mode_name, "position")
  plcsh.assert_eq(servo:enable().state, "operation enabled")
  local st = servo:status()
  plcsh.assert_eq({ st.state, st.mode_name, st.fault }, { "operation enabled", "position", false })
  start = servo.position_actual
  plcsh.assert_eq(st.position_actual, start, "status and object read agree")
  return "at " .. start
end)

c:step("PTO0 position counter cleared", function()
  plc.SMB201 = 0x40 -- SM201.6 clears SMD212 while set (k2.md §6) …
  plc.SMB201 = 0    -- … so release it
  plcsh.assert_eq(plc.SMD212, 0)
  plc:events()
end)

c:step("stepper and servo move together", function()
  t0 = now_us()
  plc:pto(0, { freq = "4kHz", count = 2000 }) -- 500 ms
  local m = servo:move_rel(5000, { rpm = 300 })
  plcsh.assert_eq({ m.move, m.target_position }, { "rel", 5000 })
  local ev = plc:wait_event(28, 2000)
  done = ev.event.time_us - t0
  plcsh.assert_eq({ ev.event.number, done }, { 28, 500000 }, "PTO0 complete after 2000 pulses at 4 kHz")
  -- 5000 increments at 300 rpm take less than the stepper's 500 ms.
  local st = servo:status()
  plcsh.assert_eq(st.target_reached, true, "the servo arrived before the stepper finished")
  local w = servo:wait_target(5000)
  plcsh.assert_eq(w.waited_s, 0, "nothing left to wait for")
  return string.format("both done after %.0f ms", done / 1000)
end)

c:step("stepper made 2000 steps", function()
  plcsh.assert_eq({ plc.SMD212, plc["SM66.7"] }, { 2000, true })
  return "SMD212 = 2000"
end)

c:step("servo moved 5000 increments", function()
  plcsh.assert_eq(servo.position_actual, start + 5000)
  return "at " .. servo.position_actual
end)

c:step("servo disabled", function()
  -- `disable` is DS402 shutdown (0x06): the power stage is off, the drive ready to switch on.
  plcsh.assert_eq(servo:disable().state, "ready to switch on")
  plcsh.assert_eq(servo:status().state, "ready to switch on")
end)

local results = c:run()
plcsh.assert_eq(#results, 6)
for _, r in ipairs(results) do plcsh.assert_eq(r.status, "ok", r.name) end
