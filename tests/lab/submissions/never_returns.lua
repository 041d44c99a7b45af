-- Waits for an output nothing sets.
local plc = plcsh.device("plc")
while not plc["Q0.5"] do plcsh.sleep(100) end
