# plcsh messages (zh-CN): engine — IL 扫描引擎及其编译器. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
