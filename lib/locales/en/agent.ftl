# plcsh messages (en): agent — the PLC-side helper and its checks. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## PLS refused on a value kept from an earlier PLS (update bit clear; K2 §3.4.2.2): the same
## words in process and through the helper (k2::sim::pto::explain).
agent-pls-kept-cycle = the cycle time kept from before is invalid: the update bit SM{ $control }.0 is clear, so PLS used the value an earlier PLS loaded (0 since power-up), not SMW{ $cycle } (cycle and count must both be > 1, §3.4.2.2; the frequency within the output's limit, §3.4)
agent-pls-kept-cycle-hint = set SMW{ $cycle } and its update bit SM{ $control }.0, then PLS again
agent-pls-kept-count = the pulse count kept from before is invalid: the update bit SM{ $control }.2 is clear, so PLS used the value an earlier PLS loaded (0 since power-up), not SMD{ $count } (cycle and count must both be > 1, §3.4.2.2)
agent-pls-kept-count-hint = set SMD{ $count } and its update bit SM{ $control }.2, then PLS again
agent-pls-kept-both = the cycle time or the pulse count kept from before is invalid: the update bits SM{ $control }.0 and SM{ $control }.2 are clear, so PLS used the values an earlier PLS loaded (0 since power-up), not SMW{ $cycle } and SMD{ $count } (cycle and count must both be > 1, §3.4.2.2)
agent-pls-kept-both-hint = set SMW{ $cycle }, SMD{ $count } and their update bits SM{ $control }.0 and SM{ $control }.2 (e.g. SMB{ $control }=16#85), then PLS again

# An instruction the helper ran whose status register reports something the PLC does not
# refuse for (HSC's multi-PV table fault, §3.3.2): what ran, then the note.
agent-done-with-note = { $what }: done by the helper; { $note }
