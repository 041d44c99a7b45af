# plcsh messages (zh-CN): data. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).

## 数据集 (dataset, data save/diff/load)

data-usage = 用法：data save FILE OPERAND… | data diff FILE [FILE2] | data load FILE
data-cannot-read = 无法读取 { $file }
data-bad-file = { $file } 不是数据集文件：{ $reason }
data-no-identity = { $file } 不是数据集文件：其 [device] 表未写明系列或型号
data-bad-operand = { $file } 列出的 `{ $operand }` 不是操作数名称：为空、含空格或超过 128 个字符
data-bad-type = { $file } 给 { $operand } 的类型是 `{ $dtype }`；类型有 BOOL、BYTE、SINT、WORD、INT、DWORD、DINT 和 REAL
data-bad-value = { $file }：{ $value } 不是 { $operand } 的 { $dtype } 类型值
data-duplicate = { $file } 两次列出了 { $operand }
data-other-device = { $file } 保存的是 { $family } { $model } 的数据，而 { $device } 是 { $dfamily } { $dmodel }：数据集只能载入读取它的同一系列、同一型号的设备
data-families-differ = { $left } 保存的是 { $lfamily } 系列的数据，{ $right } 是 { $rfamily } 系列的：只能比较同一系列的数据集
data-unknown-operand = { $file } 列出的 { $operand } 类型为 { $dtype }，但 { $device } 上没有这样一个该类型的操作数：{ $reason }
data-operand-elsewhere = { $operand } 属于另一台设备；一个数据集只保存一台设备（{ $device }）的操作数
data-no-area = `{ $area }` 指的是 K2 PLC 的区域，而 { $device } 不是 K2：请列出它的操作数
data-retained-unknown = 实际 K2 的断电保持范围在其硬件配置（KincoBuilder）中设定，无法通过 Modbus 读取：请列出这些范围，例如对 { $device } 使用 data save FILE VB0..VB99
data-retained-none = { $device } 没有断电保持范围：`sim retain VB0..VB99` 设定仿真器的断电保持范围
data-saved = 已将 { $device } 的 { $count } 个操作数保存到 { $file }
data-same = 没有差异
data-loaded = 已写入 { $written } 个操作数，均已读回；未改变：{ $unchanged }
data-read-back = 写入 { $value } 后 { $operand } 读回 { $back }；载入在此停止，此前已写入 { $written } 次
data-stopped = 载入在 { $operand } 处停止，此前已写入 { $written } 次：{ $reason }
data-not-a-drive = { $device } 不是伺服驱动器：servo params diff --with 应指定另一台已打开的驱动器
