# plcsh messages (en): devices — the servo, UMPK and FX drivers and simulators, and the links. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
