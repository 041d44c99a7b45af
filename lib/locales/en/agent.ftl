# plcsh messages (en): agent — the PLC-side helper and its checks. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
