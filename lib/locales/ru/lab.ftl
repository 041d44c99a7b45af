# plcsh messages (ru): lab — лабораторные работы, сценарии и записи. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
