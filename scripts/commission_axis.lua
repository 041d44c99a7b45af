-- Commissioning one axis of the wired bench (machines/pto_servo_encoder.toml): PTO0 of a K2
-- drives a Kinco servo in pulse-train mode (gear 4:1), the drive's encoder output comes back
-- to HSC0, its "target reached" output to I0.5 and a home switch at 20000 increments to I0.4.
-- Ends with the commissioning report (docs/commissioning.md):
--   plcsh --time stepped --bench machines/pto_servo_encoder.toml run --report axis-x.html scripts/commission_axis.lua
-- Without --bench the script wires the same machine itself; arg[1] is the folder for the
-- drive's saved parameter set (the system's temporary folder when not given).

local commission = require("commission")
local plc = plcsh.device("plc")
local servo = plcsh.device("servo")
plcsh.on_abort(function() pcall(plc.pstop, plc, 0) end)

local here = (arg[0] or ""):match("^(.*)[/\\][^/\\]*$") or "."
local reference = here .. "/../machines/pto_servo_encoder.servo.toml"
local folder = arg[1] or os.tmpname():match("^(.*)[/\\][^/\\]*$") or "."

local c = commission.new("Axis X: PTO0 → servo → HSC0", { operator = "commissioning engineer", site = "wired bench" })

c:step("PLC and drive answer", function()
  local p, s = plc:info(), servo:info()
  plcsh.assert_eq(p.family, "k2")
  plcsh.assert_eq(s.family, "servo")
  return { plc = p.model, drive = s.model }
end)

c:step("Drive set up for pulse train, gear 4:1, enabled", function()
  if #plcsh.wires() == 0 then -- not opened from the bench file: do what its init does
    servo.gear_factor = 4
    servo.gear_divider = 1
    servo:fault_reset()
    servo:mode("pulse")
    servo:enable()
  end
  local st = c:record(servo:status())
  plcsh.assert_eq(st.state, "operation enabled")
  c:measure("gear", servo.gear_factor .. ":" .. servo.gear_divider)
  return st.state
end)

c:step("Drive parameters match the reference set", function()
  local d = c:attach_params(servo, reference)
  c:measure("parameters that differ", d.count)
  plcsh.assert_eq(d.count, 0, "no parameter differs from " .. reference)
end)

c:step("Wiring: pulses, encoder, target reached, home switch", function()
  if #plcsh.wires() == 0 then
    plcsh.wire("plc:Q0.0 -> servo:pulse")
    plcsh.wire("servo:encoder -> plc:I0.1,I0.0 lines=1250") -- HSC0 mode 9: A = I0.1, B = I0.0
    plcsh.wire("servo:target_reached -> plc:I0.5")
    plcsh.wire("servo:home@20000 -> plc:I0.4")
    plcsh.on_abort(function() pcall(plcsh.unwire, "all") end)
  end
  plcsh.assert_eq(#plcsh.wires(), 4, "four wires")
  return #plcsh.wires() .. " wires"
end)

local p0
c:step("HSC0 counts the encoder (A/B, 4x)", function()
  plc:events()
  plc:hsc(0, { mode = 9, rate = "4x", pv = 10000, cv = 0 })
  plc.SMB201 = 0x40 -- clear the position counter
  plc.SMB201 = 0
  p0 = servo.position_actual
  plcsh.assert_eq(plc.SMD38, 0)
  return "SMD38 = 0"
end)

c:step("Move: 8000 pulses in three segments", function()
  plc:profile(0, "VB3001", { { cycle = 100, count = 1000 }, { cycle = 50, count = 6000 }, { cycle = 100, count = 1000 } })
  plcsh.assert_eq(plc["I0.5"], false, "moving: target not reached")
  -- The move lasts 0.6 s: record it (and a little more) every 5 ms.
  c:trace { plc, "SMD38", "SMD212", every = 5, ["for"] = 700, title = "HSC0 count and PTO0 pulses during the move" }
  plc:wait_event(28, 2000) -- PTO0 done
  c:measure("pulses out (SMD212)", plc.SMD212)
  c:measure("drive moved", servo.position_actual - p0, "increments")
  c:measure("HSC0 count (SMD38)", plc.SMD38)
  plcsh.assert_eq(plc.SMD212, 8000, "8000 pulses out")
  plcsh.assert_eq(servo.position_actual - p0, 32000, "the drive moved 8000 pulses x gear 4")
  plcsh.assert_eq(plc.SMD38, 16000, "HSC0 counted 32000 increments x 5000/10000")
end)

c:step("Target reached arrives on I0.5", function()
  plcsh.assert_eq(plc["I0.5"], true, "target reached, wired to I0.5")
  return "I0.5 = 1"
end)

c:step("Drive parameter set saved", function()
  local file = folder .. "/axis-x-servo.toml"
  local r = c:params_save(servo, file)
  c:measure("parameters saved", #r.parameters)
  c:note("saved to " .. file)
end)

local results = c:run()
plcsh.assert_eq(#results, 8)
for _, r in ipairs(results) do
  plcsh.assert_eq(r.status, "ok", r.name)
end
