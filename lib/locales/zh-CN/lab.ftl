# plcsh messages (zh-CN): lab — 实验、脚本与记录. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
