-- Save and restore the E2PROM backup area (VB3648–VB3902 by default, k2.md §7): write a
-- pattern, dump the area to a file, check the file, scribble over the area, restore it,
-- compare.
-- Run: plcsh --state none --time stepped run scripts/eeprom_backup.lua [FILE]   (--state none: your own
-- state file, with its backup area and clock, stays untouched)

local plc = plcsh.device("plc")
local file = arg[1] or os.tmpname()

local area = plc:eeprom_status()
local first, last = area.first, area.last
plcsh.assert_eq({ first, last }, { 3648, 3902 }, "the default backup area")
local size = last - first + 1

local pattern = {}
for i = 0, 15 do
  pattern[#pattern + 1] = { string.format("VB%d", first + i), (i * 37 + 11) % 256 }
end
pattern[#pattern + 1] = { "VB" .. last, 0xA5 } -- the area's last byte too
plc:set(table.unpack(pattern))

local d = plc:eeprom_dump(file)
plcsh.assert_eq({ d.bytes, d.file }, { size, file }, "the whole area is saved")
local f = assert(io.open(file, "rb"))
local data = f:read("a")
f:close()
plcsh.assert_eq(#data, size, "the file holds one byte per backup byte")
for _, p in ipairs(pattern) do
  local offset = tonumber(p[1]:sub(3)) - first
  plcsh.assert_eq(data:byte(offset + 1), p[2], p[1] .. " in the file")
end

for _, p in ipairs(pattern) do plc[p[1]] = 0 end
plcsh.assert_eq({ plc.VB3648, plc["VB" .. last] }, { 0, 0 }, "scribbled")

local r = plc:eeprom_restore(file)
plcsh.assert_eq(r.bytes, size)
for _, p in ipairs(pattern) do
  plcsh.assert_eq(plc[p[1]], p[2], p[1] .. " restored")
end

-- A file larger than the area is refused and changes nothing.
local bad = os.tmpname()
local g = assert(io.open(bad, "wb"))
g:write(string.rep("\255", size + 1))
g:close()
plc.VB3648 = 1
local ok, err = pcall(plc.eeprom_restore, plc, bad)
plcsh.check(not ok, "a file one byte larger than the area is refused")
plcsh.assert_eq(plcsh.errinfo(err).kind, "usage")
plcsh.assert_eq(plc.VB3648, 1, "nothing restored from it")
os.remove(bad)

if not arg[1] then os.remove(file) end
print(string.format("eeprom_backup: %d bytes saved and restored, %d checks", size, plcsh.checks))
