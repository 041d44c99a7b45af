# plcsh messages (zh-CN): report. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
