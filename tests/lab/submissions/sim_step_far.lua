-- Jumps the simulated clock far past the limit with a shell command.
plcsh.exec("sim step 100h")
plcsh.exec("get Q0.0")
