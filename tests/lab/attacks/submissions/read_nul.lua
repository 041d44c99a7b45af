-- A NUL byte in a path.
assert(io.open("tests/lab/attacks/submissions/x\0../../../../Cargo.toml"))
