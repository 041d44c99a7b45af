# plcsh messages (zh-CN): tags. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
