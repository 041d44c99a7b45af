-- A folder submission requires its own module.
local steps = require("steps")
steps.enable()
steps.answer()
