-- A wait past the simulated-time limit.
plcsh.sleep(1e9)
