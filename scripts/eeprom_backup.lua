-- Save and restore the E2PROM backup area (VB3648–VB3902 by default, k2.md §7): write a
-- pattern, dump it to a file, scribble over it, restore it, compare.
-- Run: plcsh --time stepped run scripts/eeprom_backup.lua [FILE]

local plc = plcsh.device("plc")
local file = arg[1] or os.tmpname()

local pattern = {}
for i = 0, 15 do
  pattern[#pattern + 1] = { string.format("VB%d", 3648 + i), (i * 37 + 11) % 256 }
end
plc:set(table.unpack(pattern))
plc:eeprom_dump(file)
local f = assert(io.open(file, "rb"))
local size = #f:read("a")
f:close()
plcsh.check(size > 0, "the dump file is not empty", size)

for i = 0, 15 do plc[string.format("VB%d", 3648 + i)] = 0 end
plcsh.assert_eq(plc.VB3648, 0, "scribbled")

plc:eeprom_restore(file)
for _, p in ipairs(pattern) do
  plcsh.assert_eq(plc[p[1]], p[2], p[1] .. " restored")
end
if not arg[1] then os.remove(file) end
print(string.format("eeprom_backup: %d bytes saved and restored", #pattern))
