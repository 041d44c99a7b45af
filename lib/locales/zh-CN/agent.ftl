# plcsh messages (zh-CN): agent — PLC 端辅助程序及其检查. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
