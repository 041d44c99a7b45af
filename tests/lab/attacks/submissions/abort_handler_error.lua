-- An abort handler after a runtime error runs as the submission: the reference stays unread.
plcsh.on_abort(function()
  print(io.open("tests/lab/attacks/lab/reference.lua"):read("a"))
end)
error("stop here")
