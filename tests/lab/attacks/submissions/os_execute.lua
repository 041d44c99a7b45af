-- A process.
os.execute("echo hi")
