-- package is absent.
table.insert(package.searchers, 1, function() return function() return {} end end)
