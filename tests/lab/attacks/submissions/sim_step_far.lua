-- A simulator step past the limit.
plcsh.exec("sim step 2h")
