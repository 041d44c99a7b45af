-- require('io') gives nothing more than io.
local io2 = require("io")
io2.popen("echo hi")
