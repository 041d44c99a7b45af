-- Loading another lab's IL reference.
plcsh.exec("sim program load tests/lab/conveyor/reference.il")
