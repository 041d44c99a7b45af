-- A recipe kept in an FX-compatible PLC is copied to a K2: one script, two families, the same
-- field access and batch calls on both. The FX holds eight setpoints in D200–D207, the batch
-- size as a 32-bit pair D210/D211 and option bits M100–M115; the K2 takes them in VW400–VW414,
-- VD420 and VW424.
-- Rehearse: plcsh --time stepped run scripts/fx_recipe_to_k2.lua
-- At the machine: plcsh -d fx=fx:/dev/ttyUSB1 -d plc=rtu:/dev/ttyUSB0 run scripts/fx_recipe_to_k2.lua

local plc = plcsh.device("plc")
local ok, fx = pcall(plcsh.device, "fx")
if not ok then
  -- No FX given: rehearse on the simulator, loaded with what the line's PLC holds.
  fx = plcsh.connect("sim-fx:FX2N", "fx")
  fx:set{ D200 = 1200, D201 = 850, D202 = 40, D203 = -15, D204 = 300, D205 = 0, D206 = 7, D207 = 2500 }
  fx["D210/DINT"] = 150000
  fx.K4M100 = 0x0015
end

-- Read the whole recipe: one batch (the driver coalesces it into few frames).
local setpoints = { fx:get("D200..D207") }
local batch = fx["D210/DINT"]
local options = fx["K4M100/WORD"] -- option bits: unsigned (a plain K4 group reads as a signed INT)
plcsh.assert_eq(#setpoints, 8, "eight setpoints")

-- Write it to the K2 in one batch, checked before anything is written.
local items = {}
for i, v in ipairs(setpoints) do
  items[#items + 1] = { string.format("VW%d/INT", 400 + 2 * (i - 1)), v } -- FX D is signed
end
items[#items + 1] = { "VD420/DINT", batch } -- the FX pair is a DINT
items[#items + 1] = { "VW424", options }
plc:set(table.unpack(items))

-- Verify on the K2 what was read from the FX.
plcsh.assert_eq({ plc:get("VW400/INT..VW414/INT") }, setpoints, "setpoints copied")
plcsh.assert_eq(plc["VD420/DINT"], batch, "batch size copied")
plcsh.assert_eq(plc.VW424, options, "option bits copied")
if not ok then
  plcsh.assert_eq(setpoints, { 1200, 850, 40, -15, 300, 0, 7, 2500 }, "the rehearsal recipe")
  plcsh.assert_eq({ batch, options, fx.M100, fx.M101 }, { 150000, 0x15, true, false }, "pair and bits")
end
print(string.format("recipe copied: %d setpoints, batch %d, options 16#%04X", #setpoints, batch, options))
