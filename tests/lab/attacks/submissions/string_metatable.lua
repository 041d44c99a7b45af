-- The string metatable.
getmetatable("").__index.rep = function() return "" end
