# plcsh messages (en): k2 — the K2's driver, simulator, helpers, wiring and snapshots. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
