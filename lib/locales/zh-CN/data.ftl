# plcsh messages (zh-CN): data. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
