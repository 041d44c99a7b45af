-- A module with a Cyrillic name beside main.lua.
local m = require("модуль")
m.run()
