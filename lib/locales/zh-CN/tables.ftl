# plcsh messages (zh-CN): tables — SM 字节、伺服对象、指令与元件的说明. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
