# plcsh messages (ru): shell — команды и параметры оболочки и командной строки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
