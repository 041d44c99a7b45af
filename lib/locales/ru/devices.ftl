# plcsh messages (ru): devices — драйверы и симуляторы сервопривода, УМПК и FX, линии связи. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
