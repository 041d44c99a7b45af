-- A table nested 200 000 deep, encoded: an error, never a stack overflow of the worker.
local t = {}
for _ = 1, 200000 do t = { t } end
plcsh.json.encode(t)
