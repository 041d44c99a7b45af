-- Removing the instruction hook.
debug.sethook()
