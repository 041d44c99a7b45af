# plcsh messages (ru): tables — описания байтов SM, объектов сервопривода, инструкций и элементов. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).
