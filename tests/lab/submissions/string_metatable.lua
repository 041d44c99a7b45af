getmetatable("").__index.rep = function() return "" end
