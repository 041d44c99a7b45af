-- A 20 MiB error.
error(string.rep("A", 20 * 1024 * 1024), 0)
