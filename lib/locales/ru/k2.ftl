# plcsh messages (ru): k2 — драйвер, симулятор и помощники K2, схемы соединений и снимки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
