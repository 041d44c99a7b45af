-- A serial device by command.
plcsh.exec("connect r rtu:/dev/ttyS0")
