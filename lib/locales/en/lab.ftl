# plcsh messages (en): lab — labs, scripts and recordings. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
