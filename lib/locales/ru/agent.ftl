# plcsh messages (ru): agent — программа-помощник в ПЛК и её проверки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## PLS refused on a value kept from an earlier PLS (update bit clear; K2 §3.4.2.2): the same
## words in process and through the helper (k2::sim::pto::explain).
agent-pls-kept-cycle = сохранённое ранее время цикла неверное: бит обновления SM{ $control }.0 сброшен, поэтому PLS взяла значение, загруженное предыдущей PLS (0 после включения питания), а не SMW{ $cycle } (время цикла и количество импульсов должны быть больше 1, §3.4.2.2; частота — в пределах выхода, §3.4)
agent-pls-kept-cycle-hint = задайте SMW{ $cycle } и его бит обновления SM{ $control }.0, затем снова PLS
agent-pls-kept-count = сохранённое ранее количество импульсов неверное: бит обновления SM{ $control }.2 сброшен, поэтому PLS взяла значение, загруженное предыдущей PLS (0 после включения питания), а не SMD{ $count } (время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
agent-pls-kept-count-hint = задайте SMD{ $count } и его бит обновления SM{ $control }.2, затем снова PLS
agent-pls-kept-both = сохранённое ранее время цикла или количество импульсов неверное: биты обновления SM{ $control }.0 и SM{ $control }.2 сброшены, поэтому PLS взяла значения, загруженные предыдущей PLS (0 после включения питания), а не SMW{ $cycle } и SMD{ $count } (время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
agent-pls-kept-both-hint = задайте SMW{ $cycle }, SMD{ $count } и их биты обновления SM{ $control }.0 и SM{ $control }.2 (например, SMB{ $control }=16#85), затем снова PLS

# An instruction the helper ran whose status register reports something the PLC does not
# refuse for (HSC's multi-PV table fault, §3.3.2): what ran, then the note.
agent-done-with-note = { $what }: выполнено программой-помощником; { $note }
