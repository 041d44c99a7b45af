-- Saves the state with the task done, and restores it (the bench's state, not its program).
plcsh.snapshot_save(plcsh.write_dir .. "/s.json")
plcsh.snapshot_restore(plcsh.write_dir .. "/s.json")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
