# plcsh messages (ru): engine — движок сканирования IL и его компилятор. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
