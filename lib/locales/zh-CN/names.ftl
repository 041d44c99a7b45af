# plcsh messages (zh-CN): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-hint-check = 请修正上面列出的行；`plcsh tags check { $file }` 可检查文件本身
names-hint-did-you-mean = 是否想输入 { $names }？
names-profile-tags-not-text = `tags` 应为文件名，例如 tags = "press1.csv"
names-help-tag = { $name } 即 { $operand }（来自 { $file } 的标签）
names-help-comment = 注释：{ $comment }
names-unknown = `{ $word }` 既不是 { $file } 中的标签，也不是操作数
