-- A combined sequence: the K2 drives a stepper axis with PTO0 while the servo drive makes a
-- relative move; both finish, both are verified; everything is stopped on Ctrl-C.
-- Run: plcsh --time stepped run scripts/k2_and_servo.lua

local commission = require("commission")
local plc = plcsh.device("plc")
local servo = plcsh.device("servo")
plcsh.on_abort(function() plc:pstop(0) end)
plcsh.on_abort(function() servo:disable() end)

local c = commission.new("K2 + servo combined move")
local start

c:step("servo enabled in position mode", function()
  servo:fault_reset()
  servo:mode("position")
  servo:enable()
  start = servo.position_actual
  return "at " .. start
end)

c:step("stepper and servo move together", function()
  plc.SMB201 = 0x40 -- clear PTO0's current value
  plc:events()
  plc:pto(0, { freq = "4kHz", count = 2000 }) -- 500 ms
  servo:move_rel(5000, { rpm = 300 })
  plc:wait_event(28, 2000)
  servo:wait_target(5000)
end)

c:step("stepper made 2000 steps", function()
  plcsh.assert_eq(plc.SMD212, 2000)
  return "SMD212 = 2000"
end)

c:step("servo moved 5000 increments", function()
  plcsh.assert_eq(servo.position_actual, start + 5000)
end)

c:step("servo disabled", function()
  servo:disable()
end)

c:run()
