# plcsh messages (ru): agent — программа-помощник в ПЛК и её проверки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## PLS refused on a value kept from an earlier PLS (update bit clear; K2 §3.4.2.2): the same
## words in process and through the helper (k2::sim::pto::explain).
agent-pls-kept-cycle = время цикла, оставшееся от предыдущей PLS, неверное (бит обновления SM{ $control }.0 сброшен: PLS не загрузила SMW{ $cycle }; время цикла и количество импульсов должны быть больше 1, §3.4.2.2; частота — в пределах выхода, §3.4)
agent-pls-kept-cycle-hint = задайте SMW{ $cycle } и его бит обновления SM{ $control }.0, затем снова PLS
agent-pls-kept-count = количество импульсов, оставшееся от предыдущей PLS, неверное (бит обновления SM{ $control }.2 сброшен: PLS не загрузила SMD{ $count }; время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
agent-pls-kept-count-hint = задайте SMD{ $count } и его бит обновления SM{ $control }.2, затем снова PLS
agent-pls-kept-both = время цикла или количество импульсов, оставшиеся от предыдущей PLS, неверные (биты обновления SM{ $control }.0 и SM{ $control }.2 сброшены: PLS не загрузила ни SMW{ $cycle }, ни SMD{ $count }; время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
agent-pls-kept-both-hint = задайте SMW{ $cycle }, SMD{ $count } и их биты обновления SM{ $control }.0 и SM{ $control }.2 (например, SMB{ $control }=16#85), затем снова PLS

# An instruction the helper ran whose status register reports something the PLC does not
# refuse for (HSC's multi-PV table fault, §3.3.2): what ran, then the note.
agent-done-with-note = { $what }: выполнено программой-помощником; { $note }
