# plcsh messages (en): shell — the commands and options of the shell and the command line. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
