-- A commissioning checklist with lib/commission.lua, against the simulated K2: prepare
-- PTO0's registers, check the system bits, the clock and a retained value.
-- Run: plcsh --time stepped run scripts/commission_checklist.lua [CYCLE_US] [COUNT]

local commission = require("commission")
local plc = plcsh.device("plc")
local cycle = tonumber(arg[1] or "500")
local count = tonumber(arg[2] or "1000")

local c = commission.new("PTO0 register check on " .. plc:info().model)

c:step("PLC answers and is a K2", function()
  local info = plc:info()
  plcsh.assert_eq(info.family, "k2")
  return info.model
end)

c:step("SM0.0 is always on", function()
  plcsh.check(plc["SM0.0"], "SM0.0 must be on")
end)

c:step("PTO0 control, cycle and count written in order", function()
  plc:set({ "SMB67", 0x85 }, { "SMW68", cycle }, { "SMD72", count })
  plcsh.assert_eq({ plc:get("SMB67", "SMW68", "SMD72") }, { 0x85, cycle, count })
  return string.format("16#85, %d us, %d pulses", cycle, count)
end)

c:step("Expected pulse train length", function()
  local ms = cycle * count / 1000
  plcsh.assert_near(ms, 500, 1e-9, "500 us x 1000 pulses")
  return string.format("%.0f ms", ms)
end)

c:step("1-second clock toggles", function()
  local first = plc["SM0.5"]
  plcsh.wait_until(function() return plc["SM0.5"] ~= first end, { timeout = 1000, every = 50, what = "SM0.5 edge" })
  return "SM0.5 edge seen"
end)

c:step("Backup area holds a value", function()
  plc.VW3648 = 1234
  plcsh.assert_eq(plc.VW3648, 1234)
end)

local results = c:run()
plcsh.assert_eq(#results, 6)
for _, r in ipairs(results) do
  plcsh.assert_eq(r.status, "ok", r.name)
end
