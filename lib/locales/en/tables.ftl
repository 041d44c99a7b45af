# plcsh messages (en): tables — descriptions of SM bytes, servo objects, instructions and elements. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
