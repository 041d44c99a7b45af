-- A Lua submission: writes its IL into the run's write directory and loads it.
local lines = {
  "LD %I0.0", "O %Q0.0", "A %I0.2", "AN %I0.1", "= %Q0.0",
  "LD %Q0.0", "TON T37, 20", "= %Q0.1",
}
local file = plcsh.write_dir .. "/conveyor.il"
local f = assert(io.open(file, "w"))
f:write(table.concat(lines, "\n"), "\n")
f:close()
plcsh.exec("sim program load " .. file)
