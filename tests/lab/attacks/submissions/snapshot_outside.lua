-- A snapshot written into the lab.
plcsh.exec("sim snapshot save tests/lab/attacks/lab/start.json")
