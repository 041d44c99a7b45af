-- Opens a fresh simulator under the lab's device name (replacing it) and presets it.
local plc = plcsh.connect("sim:K205-16DT", "plc")
plc.VW0 = 1234
plc["Q0.0"] = true
