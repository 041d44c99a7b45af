-- The lab's own modules may be required.
local check = require("checks")
local f = io.open(plcsh.write_dir .. "/p.il", "w")
f:write("LD %I0.0\nO %Q0.0\nA %I0.2\nAN %I0.1\n= %Q0.0\nLD %Q0.0\nTON T37, 20\n= %Q0.1\n")
f:close()
local plc = plcsh.device("plc")
plc:program_load(plcsh.write_dir .. "/p.il")
assert(check.running(plc))
