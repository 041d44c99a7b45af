# plcsh messages (ru): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-hint-check = исправьте названные строки; `plcsh tags check { $file }` проверяет сам файл
names-hint-did-you-mean = может быть, { $names }?
