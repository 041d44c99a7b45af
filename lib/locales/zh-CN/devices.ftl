# plcsh messages (zh-CN): devices — 驱动、链路、仿真器与快照. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
