# plcsh messages (zh-CN): agent — PLC 端辅助程序及其检查. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## PLS refused on a value kept from an earlier PLS (update bit clear; K2 §3.4.2.2): the same
## words in process and through the helper (k2::sim::pto::explain).
agent-pls-kept-cycle = 沿用的周期时间无效：更新位 SM{ $control }.0 为 0，PLS 使用的是上一次 PLS 装载的值（上电后为 0），而不是 SMW{ $cycle }（周期时间和脉冲数都必须大于 1，§3.4.2.2；频率不得超过该输出的上限，§3.4）
agent-pls-kept-cycle-hint = 设置 SMW{ $cycle } 及其更新位 SM{ $control }.0，然后再执行 PLS
agent-pls-kept-count = 沿用的脉冲数无效：更新位 SM{ $control }.2 为 0，PLS 使用的是上一次 PLS 装载的值（上电后为 0），而不是 SMD{ $count }（周期时间和脉冲数都必须大于 1，§3.4.2.2）
agent-pls-kept-count-hint = 设置 SMD{ $count } 及其更新位 SM{ $control }.2，然后再执行 PLS
agent-pls-kept-both = 沿用的周期时间或脉冲数无效：更新位 SM{ $control }.0 和 SM{ $control }.2 均为 0，PLS 使用的是上一次 PLS 装载的值（上电后为 0），而不是 SMW{ $cycle } 和 SMD{ $count }（周期时间和脉冲数都必须大于 1，§3.4.2.2）
agent-pls-kept-both-hint = 设置 SMW{ $cycle }、SMD{ $count } 及其更新位 SM{ $control }.0 和 SM{ $control }.2（例如 SMB{ $control }=16#85），然后再执行 PLS

# An instruction the helper ran whose status register reports something the PLC does not
# refuse for (HSC's multi-PV table fault, §3.3.2): what ran, then the note.
agent-done-with-note = { $what }：已由辅助程序执行；{ $note }
