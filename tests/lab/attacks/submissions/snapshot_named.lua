-- A named snapshot (the user's data directory).
plcsh.snapshot_save("lab1")
