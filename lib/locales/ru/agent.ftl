# plcsh messages (ru): agent — программа-помощник в ПЛК и её проверки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
