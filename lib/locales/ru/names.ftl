# plcsh messages (ru): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-hint-check = исправьте названные строки; `plcsh tags check { $file }` проверяет сам файл
names-hint-did-you-mean = может быть, { $names }?
names-profile-tags-not-text = `tags` — имя файла, например tags = "press1.csv"
names-help-tag = { $name } — это { $operand } (тег из { $file })
names-help-comment = комментарий: { $comment }
names-unknown = `{ $word }` — не тег из { $file } и не операнд
