-- The same error caught, then the task.
local t = {}
for _ = 1, 200000 do t = { t } end
local self = {}
self[1] = self
pcall(plcsh.json.encode, t)
pcall(plcsh.json.encode, self)
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
