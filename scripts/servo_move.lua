-- Servo drive: enable → absolute move → verify the position → relative move → disable
-- (DS402 helpers, kinco-servo.md). Uses the default session's simulated drive `servo`, or
-- --device servo=kinco:/dev/ttyUSB0?id=1.
-- Run: plcsh --time stepped run scripts/servo_move.lua [TARGET] [RPM]

local servo = plcsh.device("servo")
local TARGET = tonumber(arg[1] or "10000")
local RPM = tonumber(arg[2] or "300")
plcsh.on_abort(function() servo:disable() end)

servo:fault_reset()
plcsh.assert_eq(servo:mode("position").mode_name, "position")
local en = servo:enable()
plcsh.assert_eq(en.state, "operation enabled")
local st = servo:status()
plcsh.assert_eq({ st.state, st.fault, st.mode_name }, { "operation enabled", false, "position" }, "enabled")
local start = st.position_actual

local m = servo:move_abs(TARGET, { rpm = RPM })
plcsh.assert_eq({ m.move, m.target_position }, { "abs", TARGET })
local w = servo:wait_target(5000)
plcsh.check(w.waited_s > 0, "the move takes time", w.waited_s)
plcsh.assert_eq(w.position_actual, TARGET, "wait target reports the target")
plcsh.assert_eq(servo.position_actual, TARGET, "actual position equals the target")
plcsh.assert_eq(servo:status().target_reached, true)

m = servo:move_rel(-TARGET // 2, { rpm = RPM })
plcsh.assert_eq({ m.move, m.target_position }, { "rel", -TARGET // 2 })
servo:wait_target(5000)
plcsh.assert_eq(servo.position_actual, TARGET - TARGET // 2, "relative move")

-- `disable` is DS402 shutdown (0x06): the power stage is off.
plcsh.assert_eq(servo:disable().state, "ready to switch on")
st = servo:status()
plcsh.assert_eq({ st.state, st.position_actual }, { "ready to switch on", TARGET - TARGET // 2 }, "disabled in place")
print(string.format("servo_move: %d → %d → %d, %d checks passed", start, TARGET, st.position_actual, plcsh.checks))
