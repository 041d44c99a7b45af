# plcsh messages (zh-CN): devices — 伺服、UMPK 与 FX 的驱动和仿真器，以及链路. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
