# plcsh messages (en): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-hint-check = fix the lines named above; `plcsh tags check { $file }` checks the file itself
names-hint-did-you-mean = did you mean { $names }?
