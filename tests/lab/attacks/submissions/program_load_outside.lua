-- A simulator program from outside.
plcsh.exec("sim program load /etc/hostname")
