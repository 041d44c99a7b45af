-- A very long path.
assert(io.open(string.rep("a/", 5000) .. "x"))
