# plcsh messages (zh-CN): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-duplicate = 名称 `{ $name }` 出现了两次（名称不区分大小写）
names-more-problems = ……另有 { $count } 处
names-not-attached = { $file }：{ $count } 个标签与此设备不符；未采用文件中的任何名称
names-hint-check = 请修正上面列出的行；`plcsh tags check { $file }` 可检查文件本身
names-not-one-operand = `{ $address }` 是多个操作数；一个标签只对应一个
names-type-does-not-fit = 类型 { $dtype } 与 `{ $address }` 不符（{ $bits } 位）
names-hint-did-you-mean = 是否想输入 { $names }？
