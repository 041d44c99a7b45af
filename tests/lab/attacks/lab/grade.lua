-- Grader of the attack class's lab: each criterion reads the devices after the submission ran.
local helpers = require("helpers")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")

local ran, why = lab.run()
plcsh.sleep(200) -- an IL program scans; a Lua submission has already finished

lab.criterion("runs", 1, function()
  if not ran then return false, why, "a submission that runs to its end" end
end)
lab.criterion("drive enabled", 3, function()
  lab.expect(helpers.enabled(servo), true, "the drive's operation enabled")
end)
lab.criterion("answer in VW0", 3, function()
  lab.expect(plc.VW0, helpers.ANSWER, "VW0")
end)
lab.criterion("lamp on", 3, function()
  lab.expect(plc["Q0.0"], true, "Q0.0")
end)
