-- Servo drive: enable → absolute move → verify the position → disable (DS402 helpers).
-- Uses the default session's simulated drive `servo`, or --device servo=kinco:/dev/ttyUSB0?id=1.
-- Run: plcsh --time stepped run scripts/servo_move.lua [TARGET] [RPM]

local servo = plcsh.device("servo")
local TARGET = tonumber(arg[1] or "10000")
local RPM = tonumber(arg[2] or "300")
plcsh.on_abort(function() servo:disable() end)

servo:fault_reset()
servo:mode("position")
servo:enable()
local st = servo:status()
plcsh.check(plcsh.json.encode(st):lower():find("operation enabled") ~= nil, "state is operation enabled", st)

servo:move_abs(TARGET, { rpm = RPM })
servo:wait_target(5000)
plcsh.assert_eq(servo.position_actual, TARGET, "actual position equals the target")

servo:move_rel(-TARGET // 2, { rpm = RPM })
servo:wait_target(5000)
plcsh.assert_eq(servo.position_actual, TARGET - TARGET // 2, "relative move")

servo:disable()
st = servo:status()
plcsh.check(plcsh.json.encode(st):lower():find("operation enabled") == nil, "disabled", st)
print(string.format("servo_move: %d checks passed", plcsh.checks))
