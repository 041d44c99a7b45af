local d = plcsh.connect("tcp://127.0.0.1:502", "real")
d.VW0 = 4242
