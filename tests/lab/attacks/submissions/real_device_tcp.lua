-- A Modbus TCP device.
plcsh.connect("tcp://127.0.0.1:502", "real")
