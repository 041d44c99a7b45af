-- The lab command starts processes.
plcsh.exec("lab new elsewhere")
