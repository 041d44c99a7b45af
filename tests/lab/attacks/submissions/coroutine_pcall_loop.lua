-- pcall inside a coroutine, around a loop.
coroutine.wrap(function() while true do pcall(function() while true do end end) end end)()
