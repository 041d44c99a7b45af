local f = io.open("Cargo.toml")
print(f:read("a"))
