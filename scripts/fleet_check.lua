-- A commissioning check written once for every press of a fleet: run it on all of them at once
-- with `plcsh --config FILE run --fleet presses scripts/fleet_check.lua`, or alone on the
-- default simulator with `plcsh run scripts/fleet_check.lua`. On a fleet, `plcsh.fleet_member`
-- names the device this copy of the script works on.

local plc = plcsh.device(plcsh.fleet_member or "plc")
local info = plc:info()
plcsh.check(info.family == "k2", "the device is a K2")
local speed = plc:get("VW100")
plcsh.check(speed >= 0 and speed <= 3000, "VW100 (speed set-point) is within 0..3000")
print(string.format("%s: %s, VW100 = %d", plcsh.fleet_member or "plc", info.model, speed))
