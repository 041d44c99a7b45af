# plcsh messages (ru): devices — драйверы, линии связи, симуляторы и снимки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
