-- A metatable on a shared module.
local ok, h = pcall(require, "helpers")
if ok then setmetatable(h, { __index = function() return function() return true end end }); h.enabled = nil end
local plc = plcsh.device("plc")
plc.VW0 = 1234
plc["Q0.0"] = true
