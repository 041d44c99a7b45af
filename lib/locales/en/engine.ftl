# plcsh messages (en): engine — the IL scan engine and its compiler. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Loading IL: the reader and the compiler (docs/il.md)

engine-comment-unclosed = comment `(*` is never closed with `*)`
engine-line-too-long = line longer than { $max } characters
engine-empty-operand = empty operand in `{ $text }`
engine-no-program = no PROGRAM in the file: the main program runs every scan
engine-no-program-hint = start the main program with `PROGRAM MAIN` (or put it before the first SUBROUTINE)
engine-pou-twice = { $name } is defined twice
engine-label-twice = label { $name } is defined twice in { $pou }
engine-for-too-deep = FOR loops nested deeper than { $max }
engine-next-without-for = NEXT without a FOR
engine-next-without-for-hint = a loop is FOR INDX, INIT, FINAL … NEXT in the same POU
engine-for-without-next = FOR without a NEXT in { $pou }
engine-no-label = no label { $name } in { $pou }
engine-did-you-mean = did you mean { $name }?
engine-no-routine = no subroutine or interrupt routine { $name } in { $file }
engine-no-routine-hint = define it with `SUBROUTINE NAME` (or `INTERRUPT NAME`) … `END_SUBROUTINE`
engine-needs-constant = { $mnemonic }: { $operand } must be a constant
engine-unknown-instruction = unknown instruction { $mnemonic }
engine-unknown-instruction-near = did you mean { $name }? (docs/il.md lists the instructions)
engine-unknown-instruction-hint = docs/il.md lists the instructions this simulator runs
engine-pointer-not-dword = { $operand }: a pointer is a double word, { $target } is not
engine-pointer-not-dword-hint = keep pointers in double words, e.g. *%VD{ $index }
engine-not-pointable = { $operand }: { $target } cannot be pointed to
engine-not-pointable-hint = point to V, M, I, Q or SM bytes
engine-operand-type = { $name } is a { $have } but this operation works on { $want }
engine-pointer-needs-dword = { $operand }: a pointer needs a double word
engine-output-not-location = { $operand } cannot be written: the output must be a memory location
engine-not-a-bit = { $name } is a { $have }, not a bit
engine-not-a-bit-hint = bit operands look like %M0.0, %I0.1, %SM0.0 (or T5/C5 for a timer's or counter's bit)
engine-bit-needed = { $operand }: a bit location is needed here
engine-count-range = { $operand }: expected a count 1…255
engine-convert-first = convert first: { $how }
engine-same-size = use operands of the same size (B, W, D)
engine-numbers-not-bits = { $mnemonic } works on numbers, not bits
engine-int-dint-real = { $mnemonic } works on INT, DINT or REAL values
engine-no-event = ATCH: no interrupt event { $event } (events: { $events })
engine-block-n = { $mnemonic }: N must be 1…255, found { $n }
engine-timer-preset-range = { $time } is { $units } units of this { $base } ms timer; the preset must be 0…32767 (at most { $longest } s)
engine-timer-rounded = { $time } is not a whole number of this timer's { $base } ms units: rounded up to { $got } ms ({ $units } units), never shorter than asked

## Running: faults (K2 §2.2.1 serious and normal errors)

engine-fault = fault { $code } ({ $name }): { $message }
engine-fault-at = fault { $code } ({ $name }): { $message } at line { $line } `{ $instruction }`
engine-fault-watchdog = watchdog
engine-fault-bad-address = bad indirect address
engine-fault-call-depth = call depth
engine-fault-instruction = instruction
engine-fault-div-zero = division by zero
engine-ran-off = ran off the program
engine-parens-too-deep = parentheses nested deeper than { $max }
engine-division-by-zero = division by zero
engine-calls-too-deep = subroutines nested deeper than { $max }
engine-watchdog = the scan ran past the watchdog limit of { $ms } ms (an endless loop?)
engine-block-length = block length { $n } is not 1…255
engine-no-destination = no destination
engine-bad-address = bad indirect address
engine-bad-address-at = bad indirect address { $pointer }

## The families' own instructions (docs/il.md's tables: K2 manual §3.3, §3.4; FX PM; UMPK §3.5)

engine-doc-k2-pls = PLS q: load the channel's SM settings and start PTO/PWM (on the rising edge of EN); the CR is left as it was — a refusal sets only the status bit SM66.4 …
engine-doc-k2-hdef = HDEF hsc, mode: assign a counting mode
engine-doc-k2-hsc = HSC n: apply the control byte and start or stop the counter
engine-doc-k2-pstop = PSTOP AXIS[, EXEC, DONE, ERRID]: emergency stop on the rising edge of EXEC (or of EN without EXEC); latches SM201.7
engine-doc-k2-prel = PREL AXIS, EXEC, MINF, MAXF, TIME, DIST, DONE, ERR, ERRID: relative move with a MINF→MAXF ramp over TIME ms, on EXEC's rising edge
engine-doc-k2-pabs = PABS AXIS, EXEC, MINF, MAXF, TIME, POS, DONE, ERR, ERRID: absolute move to POS (SMD212 …)
engine-doc-k2-phome = PHOME AXIS, EXEC, HOME, NHOME, MODE, DIRC, MINF, MAXF, TIME, DONE, ERR, ERRID: run in DIRC until HOME (MODE 0: creep at MINF after NHOME)
engine-doc-k2-pjog = PJOG AXIS, EXEC, MAXF, DIRC, DONE, ERR, ERRID: run at MAXF (re-read every scan) while EXEC is on
engine-doc-k2-pflo-f = PFLO_F AXIS, EXEC, F, NUM, DENOM, COUNT, DONE, ERR, ERRID: follow F × NUM / DENOM Hz for COUNT pulses (≥ 30 Hz)
engine-doc-k2-read-rtc = READ_RTC buf: 8 BCD bytes yy mm dd hh mm ss 00 weekday
engine-doc-k2-set-rtc = SET_RTC buf: set the clock from 8 BCD bytes (invalid: ENO = 0)
engine-doc-k2-stop = if CR: the CPU goes to STOP at the end of this scan (outputs to their STOP values; `sim cpu run` restarts)
engine-doc-fx-fxtim = OUT Tn K|D: FX timer coil (input = CR, CR unchanged)
engine-doc-fx-fxcnt = OUT Cn K|D: FX 16-bit counter coil
engine-doc-fx-fxcnt32 = OUT Cn K|D: FX 32-bit up/down counter coil
engine-doc-fx-fxrst = RST D/T/C: clear a register, timer or counter
engine-doc-umpk-timer = TIMER Tn, GROUP, STEPS: on-delay timer, input = CR, delay STEPS (1–255) × GROUP (0: 10 ms, 1: 0.1 s, 2: 1 s); CR := Tn
engine-doc-umpk-divide = DIVIDE Cn, RATIO[, RESET]: divide-by-N counter of the CR's pulses (RATIO 1–255); the output pulse lasts as long as the input pulse; RESET on clears it; CR := Cn
engine-doc-umpk-error = ERROR CODE: on the CR's rising edge, puts user error CODE (1–127) into the error history (?07F9); the program keeps running

## Exit statuses (docs/reference/exit-status.md is made from these, in English)

exit-ok-name = ok
exit-ok-when = every command succeeded; a script finished; every device of a fleet answered; `sim serve` stopped by SIGTERM, SIGHUP or Ctrl-C; `publish` stopped by Ctrl-C, SIGTERM or SIGHUP after every reading was delivered
exit-failed-name = failed
exit-failed-when = a command, a script or a check failed (the `error[KIND]` message says which); one device of a fleet failed; a lab criterion failed; a damaged recording was shown in part
exit-usage-name = usage
exit-usage-when = the command line is wrong: unknown flag or subcommand, missing or bad value, a file named with --config that does not exist, an unreadable recording
exit-broker-refused-name = broker refused
exit-broker-refused-when = `publish`: the MQTT broker refused the credentials (username, password or its ACL)
exit-broker-unreachable-name = broker unreachable
exit-broker-unreachable-when = `publish`: the broker's TLS certificate did not verify, or no broker answered within 10 s of the start
exit-hangup-name = SIGHUP
exit-hangup-when = the terminal went away (a dropped SSH session; Windows: the console window closed); the running command stopped and the abort handlers ran
exit-interrupted-name = Ctrl-C
exit-interrupted-when = Ctrl-C stopped a one-shot, a script or a fleet run; the abort handlers ran (in the interactive shell Ctrl-C returns to the prompt instead)
exit-terminated-name = SIGTERM
exit-terminated-when = SIGTERM (`timeout`, `systemctl stop`, CI; Windows: Ctrl-Break) stopped the work; the abort handlers ran
