-- A pipe to a process.
io.popen("echo hi")
