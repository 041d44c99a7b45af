# plcsh messages (zh-CN): k2 — K2 的驱动、仿真器、辅助功能、接线与快照. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
