-- require('package') is a missing module.
local p = require("package")
p.loaded.helpers = { enabled = function() return true end, ANSWER = 1 }
