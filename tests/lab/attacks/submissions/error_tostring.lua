-- An error with its own __tostring.
error(setmetatable({}, { __tostring = function() return "custom" end }))
