# plcsh messages (en): engine — the IL scan engine and its compiler. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
