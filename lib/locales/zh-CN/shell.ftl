# plcsh messages (zh-CN): shell — 外壳与命令行的命令和选项. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
