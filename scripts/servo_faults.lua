-- Rehearse a commissioning script's error handling on a faulted servo line: a reply that
-- never comes (a link error, retried) and a drive that refuses an object (an abort code,
-- not retried: the script stops the axis and reports). The faults are injected through the
-- simulator's control language, in-process (the default session's `servo`) or on a drive
-- served by `plcsh sim serve --servo-pty LINK` (its control socket LINK.ctl):
--   plcsh --time stepped run scripts/servo_faults.lua
--   plcsh -d servo=kinco:/tmp/ttyKINCO?id=1 run scripts/servo_faults.lua
-- With the argument `unhandled` the refusal is not caught, so the script ends in error and
-- its on_abort handler brings the axis to a safe state.

local servo = plcsh.device("servo")
local UNHANDLED = arg[1] == "unhandled"

-- The safety net: whatever ends this script in error, the axis is left disabled.
plcsh.on_abort(function(why)
  servo:sim_fault("clear")
  servo:disable()
  print("on_abort: axis disabled after " .. why)
end)

--- Runs fn, retrying link errors (no reply, bad checksum) up to `tries` times. A refusal
--- (the drive answered with an abort code) is raised at once: retrying cannot help.
local function with_retry(what, tries, fn)
  for attempt = 1, tries do
    local ok, e = pcall(fn)
    if ok then
      return e, attempt
    end
    local info = plcsh.errinfo(e)
    if info.kind ~= "link" or attempt == tries then
      error(e, 0)
    end
    print(string.format("%s: attempt %d failed (%s), retrying", what, attempt, info.kind))
  end
end

servo:sim_fault("clear")
servo:fault_reset()
servo:enable()

-- 1. No reply: the next request goes unanswered; the retry wrapper rides over it.
servo:sim_fault("no-reply")
local sw, attempts = with_retry("read statusword", 3, function()
  return servo.statusword
end)
plcsh.assert_eq(attempts, 2, "the first read got no reply, the second was answered")
plcsh.assert_eq(sw & 0x6F, 0x27, "operation enabled")

-- The same fault without a retry shows what the error looks like.
servo:sim_fault("no-reply")
local ok, e = pcall(function() return servo.position_actual end)
local info = plcsh.errinfo(e)
plcsh.assert_eq({ ok, info.kind }, { false, "link" }, "no reply is a link error")
plcsh.check(info.message:find("no reply", 1, true) ~= nil, "the message says no reply", info.message)

-- 2. Abort: the drive refuses target_position with 0x06090030 (value range exceeded).
servo:sim_fault("abort", "target_position", "16#06090030")
local function move()
  servo.target_position = 20000
end
if UNHANDLED then
  move() -- not caught: the script ends here and on_abort runs
end
local calls = 0
ok, e = pcall(with_retry, "write target_position", 3, function()
  calls = calls + 1
  move()
end)
info = plcsh.errinfo(e)
plcsh.assert_eq({ ok, info.kind, calls }, { false, "refused", 1 }, "a refusal is not retried")
plcsh.check(info.message:find("16#06090030", 1, true) ~= nil, "the abort code is named", info.message)
plcsh.check(info.message:find("value range", 1, true) ~= nil, "and explained", info.message)
-- The error path: stop the axis, as on_abort would.
plcsh.assert_eq(servo:quickstop().state, "quick stop active", "error path: quick stop")

-- The fault was used up: the same write now goes through.
servo:enable()
move()
plcsh.assert_eq(servo.target_position, 20000)
servo:disable()
print(string.format("servo_faults: no-reply retried, abort 16#06090030 refused and handled, %d checks passed", plcsh.checks))
