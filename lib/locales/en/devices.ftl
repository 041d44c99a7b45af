# plcsh messages (en): devices — drivers, links, simulators and snapshots. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
