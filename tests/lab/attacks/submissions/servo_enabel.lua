-- A misspelt method gets the shell's hint.
local servo = plcsh.device("servo")
servo:enabel()
