# plcsh messages (en): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-hint-check = fix the lines named above; `plcsh tags check { $file }` checks the file itself
names-hint-did-you-mean = did you mean { $names }?
names-profile-tags-not-text = `tags` must be a file name, e.g. tags = "press1.csv"
names-help-tag = { $name } is { $operand } (a tag of { $file })
names-help-comment = comment: { $comment }
names-unknown = `{ $word }` is neither a tag of { $file } nor an operand
