-- load() gives the chunk this submission's environment (plcsh, io, string are there).
local build = load([[
  local t = {}
  for _, l in ipairs({ "LD %I0.0", "O %Q0.0", "A %I0.2", "AN %I0.1", "= %Q0.0", "LD %Q0.0", "TON T37, 20", "= %Q0.1" }) do
    t[#t + 1] = l
  end
  return table.concat(t, "\n")
]])
local file = plcsh.write_dir .. "/p.il"
local f = io.open(file, "w")
f:write(build())
f:close()
plcsh.device("plc"):program_load(file)
