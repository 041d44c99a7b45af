lab.criterion = function() return true end
