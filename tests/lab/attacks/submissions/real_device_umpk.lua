-- A real UMPK.
plcsh.connect("umpk:/dev/ttyUSB0?model=UMPK16", "u")
