plcsh.exec("sim snapshot save lab1")
