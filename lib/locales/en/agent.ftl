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

# The mailbox base (`agent install base=`, `sm … base=`): below the E2PROM area (§2.2.8).
agent-base-not-vb = `{ $text }` is not a V byte address (e.g. VB{ $base })
agent-base-range = the helper's mailbox needs an even address with { $total } bytes free below the E2PROM area VB{ $eeprom } (got VB{ $n })

# The helper's result codes, as a refusal reads them.
agent-result-done = done
agent-result-unknown-command = the helper does not know this command (update lib/k2_agent.il)
agent-result-bad-range = SM range outside the registers the manual names or longer than 64 bytes
agent-result-read-only = the SM bytes are read-only
agent-result-bad-channel = no such channel on this PLC
agent-result-bad-mode = the counter does not have this mode
agent-result-instruction-failed = the PLC instruction reported an error (its ENO)
agent-result-bad-clock = the date or time is not valid
agent-result-status-bit = the instruction's status bit reports a refusal
agent-result-other = unknown result code { $code }

# The helper's causes of a status-bit refusal (§3.4.2.2, §3.4.3.1, §3.3.2).
agent-pls-invalid = the PLC set status bit SM{ $status }.4 after PLS { $n }: cycle time or pulse count invalid (cycle and count must both be > 1, §3.4.2.2); no pulses were sent
agent-pls-invalid-hint = load SMW{ $cycle } with SM{ $control }.0 and SMD{ $count } with SM{ $control }.2 set (e.g. SMB{ $control }=16#85), then PLS again
agent-pstop-not-latched = the emergency-stop bit SM{ $control }.7 did not latch after PSTOP { $n } (manual §3.4.3.1: PSTOP sets it)
agent-pstop-not-latched-hint = check that the PLC runs the current helper and that position channel exists on it
agent-hsc-pv-table = the PLC set status bit SM{ $status }.3 after HSC { $n }: fault in the multi-PV table (manual §3.3.2)
agent-hsc-pv-table-hint = check the PV table at SMW{ $table } (an odd V address, a count of 1..32, PVs that differ by more than 1; §3.3.3)

# `plcsh agent check` (docs/agent.md, "agent check"): what each step proves, what it saw and
# what to do when it failed; then the verdict.
agent-check-proves-signature = the helper program runs with its mailbox at this base (plcsh reads its own signature there)
agent-check-proves-protocol = the helper speaks the mailbox protocol this plcsh speaks
agent-check-proves-heartbeat = the helper is called every scan, so commands are taken within a scan or two; the rate gives the scan time
agent-check-proves-system-bits = the helper's SM copy reaches the system status bits: a command goes in, its reply comes back, and the bytes are the PLC's own
agent-check-proves-clock = READ_RTC works through the helper and the PLC's real-time clock runs
agent-check-proves-refusal = a PLC instruction the PLC refuses is reported as refused (status bit 4), not as done, and the refusal moves nothing
agent-check-not-run = not run: an earlier step failed
agent-check-not-run-todo = fix the first failed step, then run plcsh agent check again
agent-check-install = load the helper into the PLC (plcsh agent il --base VB{ $base } prints it; docs/reference/first-connection.md), or give the base it was made for (agent=VB…)
agent-check-link-probe = check the link (plcsh probe URL says what the PLC answers)
agent-check-signature-seen = VW{ $base } = 16#{ $got } (the helper writes 16#{ $want })
agent-check-version-seen = version { $got } (this plcsh speaks { $want })
agent-check-version-todo = download the current helper: plcsh agent il (then run plcsh agent check again)
agent-check-link = check the link
agent-check-heartbeat-stopped = the heartbeat stayed at { $hb } for { $ms } ms
agent-check-heartbeat-todo = put the PLC in RUN, and check that the main program calls the helper every scan (LD %SM0.0 / CAL PLCSH_AGENT)
agent-check-heartbeat-seen = { $scans } scans in { $ms } ms: { $rate } scans a second, scan time about { $scan } ms
agent-check-sm00-todo = SM0.0 reads 0 but is always 1 in a running PLC (manual, SM table): the helper's SM copy reads other memory; check that the helper was made for this model (plcsh agent il) and attach plcsh agent check --json when asking
agent-check-sm01-todo = SM0.1 (first scan) reads 1 long after the first scan: the helper's SM copy does not follow the PLC's SM bytes; load the current helper (plcsh agent il)
agent-check-reply-length = the reply holds { $n } bytes, not 1
agent-check-load-current-il = load the current helper (plcsh agent il)
agent-check-mailbox-todo = check that no other client uses the mailbox, then run the check again
agent-check-rtc-short = the helper's READ_RTC reply is shorter than 8 bytes
agent-check-rtc-invalid = the PLC clock reads as { $reading }
agent-check-rtc-invalid-hint = set it: plcsh -d URL -c 'rtc set YYYY-MM-DDTHH:MM:SS' (the clock battery may be flat)
agent-check-clock-seen = { $first }, then { $second } { $dt } s later ({ $moved } s on the PLC's clock)
agent-check-clock-todo = the PLC's clock does not run: check the clock battery and set the clock (rtc set …)
agent-check-relay-model = { $model } has relay outputs and no pulse channel (manual §2.2.6): nothing to try
agent-check-again = run the check again
agent-check-all-enabled = every pulse channel has its enable bit set ({ $bytes }): the program uses them
agent-check-all-enabled-todo = the check tries PLS only on a channel the program leaves disabled; run it when the program does not use a pulse channel (a test program, or the machine's outputs disconnected)
agent-check-restore-failed = { $name }: the bytes could not be written back: { $error }
agent-check-restore-todo = write them back by hand: SMB{ $control } = 16#{ $value }, SMD{ $count } = { $pulses }
agent-check-wrong-length = a reply had the wrong length
agent-check-load-current = load the current helper
agent-check-reported-done = the helper reported it done
agent-check-reported = the helper reported: { $message }
agent-check-refusal-seen = { $name }: status SMB{ $status } 16#{ $before } → 16#{ $after } (bit 4 { $bit4 ->
        [set] set
       *[clear] clear
    }), position SMD{ $cv } { $moved ->
        [changed] CHANGED
       *[unchanged] unchanged
    }; { $helper }; { $written } written back
agent-check-no-bit4-todo = the PLC did not flag the invalid count in its status byte (manual §3.4.2.2, bit 4): the helper may address the wrong SM bytes on this PLC; attach plcsh agent check --json when asking
agent-check-cr-todo = the helper takes PLS's CR as success, which a K2 leaves as it was (§3.4.2, IL): a refused PLS would read as done; load the current helper (plcsh agent il)
agent-check-moved-todo = the channel moved: stop the machine and check channel { $channel } before using pulse outputs
agent-check-title = helper at { $base } on { $model }
agent-check-proves = proves: { $text }
agent-check-todo = what to do: { $text }
agent-check-passed = every step passed
agent-check-failed = the check FAILED

# The client of the helper's mailbox (docs/agent.md): what a request did, whether the helper
# is there and current, and why a request did not run.
agent-what-sm-write = writing SMB{ $start }…SMB{ $end }
agent-what-sm-read = reading SMB{ $start }…SMB{ $end }
agent-no-helper = no plcsh helper answers in VB{ $base }…VB{ $last } (signature 16#{ $got }, expected 16#{ $want })
agent-no-helper-hint = SM registers and instructions need the helper program in the PLC: `plcsh agent il --base VB{ $base }` prints it (also lib/k2_agent.il); docs/agent.md says how to install it; or check agent=VB… matches the program
agent-helper-v2 = the helper in the PLC is version 2, which reports a refused PLS as done (it read the CR, which PLS leaves as it was, manual §3.4.2)
agent-helper-v1 = the helper in the PLC is version 1, which runs a repeated PLS or PSTOP on a channel only the first time
agent-helper-old-hint = download the current helper (version { $version }) into the PLC: `plcsh agent il --model MODEL` prints it (lib/k2_agent.il)
agent-helper-version = the helper in the PLC speaks mailbox protocol version { $got }; this plcsh speaks { $want }
agent-helper-version-hint = download the current helper: `plcsh agent il` (lib/k2_agent.il)
agent-mailbox-busy = mailbox busy: { $what } could not be sent
agent-mailbox-busy-hint = another client's request (sequence { $pending }) has waited { $ms } ms for the helper; is the PLC in RUN? try again
agent-reply-short = the helper's reply to { $what } is shorter than asked
agent-refused = the helper refused { $what }: { $why } (result { $result }, cause { $cause })
agent-no-ack = the helper did not acknowledge { $what } within { $ms } ms
agent-no-ack-stopped = the helper's heartbeat stopped: the PLC is probably in STOP, or the helper is no longer called every scan
agent-no-ack-busy = the helper runs but did not take the request; another client may be using the mailbox
agent-mailbox-races = mailbox busy: { $what } lost { $races } races to other clients
agent-mailbox-races-hint = another plcsh (or program) is sending helper commands to this PLC at the same time; try again
agent-heartbeat-stopped = the plcsh helper is installed but its heartbeat did not move in { $ms } ms
agent-heartbeat-stopped-hint = the PLC is probably in STOP, or PLCSH_AGENT is not called every scan (LD %SM0.0 / CAL PLCSH_AGENT)

# The probe's Markdown report (`plcsh probe … --report FILE`): its title, lines and headings.
agent-probe-report-title = plcsh probe report
agent-probe-report-device = device: `{ $url }`
agent-probe-report-requests = requests sent: { $requests } (reads only: FC 01, 02, 03, 04)
agent-probe-report-areas = Modbus areas
agent-probe-report-models = Catalogue models that fit
agent-probe-report-no-models = none
agent-probe-report-timing = Response time
agent-probe-report-timed = { $reads } reads of { $what }: { $failed } failed; p50 { $p50 }, p99 { $p99 }, max { $max }
agent-probe-report-verdicts = Verdicts

# The helper's checks (k2::agent::protocol::checks): the reason of each row, in the helper
# program's comments and docs/agent.md (English) and in a refusal a person reads.
agent-row-commands = the helper knows commands 1..9
agent-row-smb0 = SMB0 holds the system status bits and is read-only
agent-row-length = 1..{ $max } bytes at once
agent-row-start = the start is SMB0..SMB{ $last }, the registers the manual names
agent-row-end = the last byte is SMB{ $last } at most (SMD{ $dword } is the highest register the manual names)
agent-row-block = SMB{ $first }..SMB{ $last } is one block: split there
agent-row-gap = { $bytes }: no register of { $model } the manual names
agent-row-pos-cv = SMD{ $at } is read-only (section 3.4.3.1)
agent-row-no-pto = { $model } has no pulse outputs
agent-row-no-hsc = { $model } has no high-speed counters
agent-row-pto = { $model } has pulse outputs 0..{ $last }
agent-row-hsc = { $model } has high-speed counters 0..{ $last }
agent-result-because = { $result }: { $why }
