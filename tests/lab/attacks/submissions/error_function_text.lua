-- tostring of functions, tables and threads in an error.
error(tostring(print) .. " " .. tostring({}) .. " " .. tostring(coroutine.create(print)), 0)
