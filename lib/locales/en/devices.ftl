# plcsh messages (en): devices — the servo, UMPK and FX drivers and simulators, and the links. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## UMPK terminal protocol (umpk::codec; UMPK manual §4.1, §4.2, Tables 6 and 8)

# The manual's names of the terminal commands (Table 6).
umpk-command-name = { $command ->
    [reset] reset controller
    [echo-on] echo on
    [echo-off] echo off
    [info] controller info
    [program-info] program info
    [inputs] input states
    [outputs] output states
    [errors] error history
    [clear-errors] clear error history
    [programming] enter Programming mode
    [monitor-start] start real-time monitor
    [monitor-stop] stop real-time monitor
   *[timing] timing figures
    }
umpk-form-short-command = `{ $text }` has { $count } character(s) after ?, and the UMPK waits for four: a terminal command is ? and four hex digits, the code and a checksum that makes them sum to 100 hex
umpk-form-short-command-like = `{ $text }` has { $count } character(s) after ?, and the UMPK waits for four: a terminal command is ? and four hex digits, the code and a checksum that makes them sum to 100 hex; for { $command } send { $bytes }
umpk-form-no-reclen = `{ $text }` does not start with a record length (two hex digits after :): a terminal command is ? and four hex digits, the code and a checksum that makes them sum to 100 hex (e.g. ?03FD, controller info); a HEX record is : RECLEN OFFSET TYPE DATA CHECKSUM in hex (e.g. :00000002FE, start programming)
umpk-form-record-length = `{ $text }` is { $count } characters, and a HEX record with RECLEN { $reclen } is { $want }: : RECLEN(2) OFFSET(4) TYPE(2) DATA({ $data }) CHECKSUM(2), e.g. :00000002FE (start programming)
umpk-form-neither = `{ $text }` is neither a UMPK terminal command nor a HEX record: a terminal command is ? and four hex digits, the code and a checksum that makes them sum to 100 hex (e.g. ?03FD, controller info); a HEX record is : RECLEN OFFSET TYPE DATA CHECKSUM in hex (e.g. :00000002FE, start programming)
umpk-status-bits-not-six = `{ $text }` is not six bit numbers 0–7 for W,H,R,E,P,T (e.g. 5,4,3,2,1,0)
umpk-status-bits-count = `{ $text }` must name six bits, for W,H,R,E,P,T (e.g. 5,4,3,2,1,0)
umpk-status-bits-twice = bit { $bit } is given twice in `{ $text }`
# The meaning of an error-history code (§4.1.8).
umpk-error-none = no error
umpk-error-user = user error { $code } (set by the program)
umpk-error-output-overflow = system error 255: output buffer overflow — a command was sent before the previous reply was complete (§4.1)
umpk-error-cycle-overrun = system error 254 (plcsh's simulator: the program overran the 10 ms cycle and was stopped; Wait mode until reset)
umpk-error-program-fault = system error 253 (plcsh's simulator: the program stopped on a fault; Wait mode until reset)
umpk-error-system = system error { $code }
# What each reply letter means (§4.1, §4.2).
umpk-letter = { $letter ->
    [E] E: checksum error — the command's checksum does not match its bytes
    [U] U: unknown command
    [C] C: the command contains an illegal character
    [L] L: the record's data is longer than allowed (64 bytes a page, 22 bytes of program info)
    [A] A: address out of sequence or out of range — pages must follow one another inside the program memory
    [W] W: the flash (IAP) write failed
    [X] X: programming is not allowed now (not in Programming mode, no start record yet, or an earlier record failed)
   *[other] an unknown reply letter
    }
# What came instead of a reply (umpk::codec::parse_exchange).
umpk-bad-monitor-packet = a damaged monitor packet: { $bytes }
umpk-bad-r-cr = `R` CR followed by { $bytes }
umpk-bad-echo = the echo { $echo } differs from the command { $sent }
umpk-bad-length-field = a packet with a bad length field: { $bytes }
umpk-bad-packet-length = a packet of { $got } bytes where { $want } were expected
umpk-bad-packet-hex = a packet with non-hex characters: { $bytes }
umpk-bad-packet-checksum = a packet with a bad checksum: { $bytes } (expected { $expected })
umpk-bad-reply = an unexpected reply { $bytes }
umpk-bad-crlf = the reply does not end in CR LF: { $bytes }

## UMPK driver (umpk::driver)

umpk-no-complete-reply = no complete reply to { $sent } from the UMPK on { $link } within { $timeout }
umpk-no-complete-reply-partial = no complete reply to { $sent } from the UMPK on { $link } within { $timeout }; only { $partial } came
umpk-hint-silent = check power, the RS-232 cable (≤ 2 m) and 57600 8N1; a controller being reset is silent for ~0.6 s
umpk-unexpected-reply = unexpected reply to { $sent } on { $link }: { $what }
umpk-hint-garbled = another program may be using the port, or the baud rate is not 57600
umpk-refused-command = the UMPK refused ?{ $code } ({ $command }): { $letter }
umpk-hint-programming-mode = in Programming mode the UMPK answers only reset, echo on/off and controller info (manual Table 6); `umpk reset` leaves Programming mode
umpk-hint-corrupted = the line corrupts bytes: check the cable and 57600 8N1
umpk-answered-other = the UMPK answered { $reply } to ?{ $code } ({ $command })
umpk-packet-size = { $what ->
    [info] a controller-info packet without six bytes
    [errors] an error-history packet without eight bytes
    [timing] a timing packet without four bytes
   *[other] a 4-byte packet expected
    }
umpk-no-monitor-packet = no real-time monitor packet from the UMPK on { $link } within { $timeout }
umpk-send-empty = umpk send needs a command (?03FD) or a record (:00000002FE)
umpk-not-sent = not sent to the UMPK on { $link }: { $reason }
umpk-refused-record = the UMPK refused record { $n } of { $total } ({ $record ->
        [start] the start record
        [info] the program-info record
        [end] the end record
       *[data] the data page at 16#{ $first }..16#{ $last }
    }): { $letter }
umpk-hint-program-incomplete = programming stopped and the new program is incomplete: run `umpk program FILE` again from the start; the controller stays in Programming mode (`umpk reset` leaves it, to Wait)
umpk-answered-record = the UMPK answered { $reply } to a HEX record
umpk-unknown-model-reported = the controller reports model { $model } with { $inputs } inputs and { $outputs } outputs, which is none of { $models }
umpk-model-mismatch = model={ $given } was given but the controller is a { $found }
umpk-hint-model-mismatch = drop model= or use model={ $found }
umpk-not-writable = the UMPK terminal protocol has no write commands (manual §4.1, Table 6), so { $operand } cannot be set
umpk-hint-not-writable = inputs are wired, outputs, timers, counters and markers belong to the program; on the simulator use `umpk sim input I3=1`
umpk-no-option = UMPK devices have no option `{ $key }`
umpk-hint-options = options: timeout, status_bits
umpk-not-model = `{ $model }` in { $url } is not a UMPK model
umpk-hint-models = models: { $models }
umpk-baud-zero = `baud=0` in { $url }: the baud rate must be positive
umpk-cannot-read-program = { $url }: cannot read { $file }: { $reason }

## UMPK operands (umpk::space; UMPK manual §3.3–§3.5)

# What an area holds (`help I0`, completion).
umpk-area-meaning = { $area ->
    [I] digital input
    [Q] digital output (opto-relay, 48 V 0.3 A)
    [T] on-delay timer output
    [C] counter output pulse
   *[M] marker
    }
# Where plcsh reads an area from.
umpk-area-source = { $area ->
    [I] ?05FB or the monitor
    [Q] ?06FA or the monitor
   *[other] the real-time monitor
    }
umpk-not-operand = `{ $text }` is not a UMPK operand
umpk-hint-operands = UMPK operands: I0…, Q0…, M0…, T0…, C0…C3 (help I0 tells more)
umpk-number-must-follow = `{ $text }`: a number must follow { $letter } (e.g. { $letter }0)
umpk-past-end = { $operand } is past the end: the { $model } has { $letter }0…{ $letter }{ $last }
umpk-not-range = `{ $text }` is not a range of one area (e.g. I0..I7)
umpk-describe = { $meaning } { $operand } (read from { $source })
umpk-help-operand = { $operand }: { $meaning } of the { $model } ({ $letter }0…{ $letter }{ $last }); BOOL; read from { $source }; manual { $section }. The UMPK terminal protocol has no write commands.
## UMPK Intel HEX files (umpk::hex; UMPK manual §4.2, Appendix 1)

umpk-hex-no-colon = a record starts with `:`
umpk-hex-not-hex-digit = character { $position } of the record is not a hex digit
umpk-hex-odd-digits = a record has an odd number of hex digits, at least 10; this one has { $count }
umpk-hex-reclen = RECLEN says { $reclen } data bytes but the record holds { $count }
umpk-hex-checksum = checksum { $got }, the bytes need { $want }
umpk-hex-line = line { $line }: { $message }
umpk-hex-after-end = line { $line }: a record after the end record (01)
umpk-hex-outside-memory = line { $line }: data at 16#{ $first }..16#{ $last } is outside the program memory (16#0000..16#{ $top }, { $memory } bytes)
umpk-hex-twice = line { $line }: address 16#{ $address } is written twice
umpk-hex-type-02 = line { $line }: a type-02 record with { $count } data byte(s): the UMPK takes type 02 only as the start record without data (:00000002FE, sent by plcsh itself); in standard Intel HEX it is an extended segment address, which a program of at most 3 KB never needs — remove the line
umpk-hex-info-size = line { $line }: program info holds 1–22 bytes, not { $count }
umpk-hex-record-type = line { $line }: record type { $rtype } is not one the UMPK takes (00 data, 01 end, 02 start, 03 program info)
umpk-hex-no-end = the file has no end record (:00000001FF)
umpk-hex-no-data = the file holds no data records

## The simulated UMPK's control words (umpk::sim::control; `umpk sim …`, the control channel)

umpk-sim-hint-words = control words: { $words }
umpk-sim-not-input = `{ $text }` is not an input (I0…I{ $last })
umpk-sim-no-such-input = I{ $n } is not an input of the { $model } (I0…I{ $last })
umpk-sim-input-usage = input needs an input and a level: input I3=1
umpk-sim-input-extra = `{ $word }` after input I{ $n } is not understood
umpk-sim-level-and-freq = give a level or freq=, not both
umpk-sim-freq-range = freq={ $freq }: the 10 ms cycle sees square waves of 0.0001–50 Hz
umpk-sim-wave-set = I{ $n }: square wave, period { $period } ms
umpk-sim-not-input-option = `{ $option }` is not an input option (freq=)
umpk-sim-level-missing = I{ $n }: give =1, =0 or freq=…
umpk-sim-inputs-extra = `inputs` takes nothing after it (got `{ $word }`)
umpk-sim-inputs = inputs { $bits } (I{ $last }…I0); square waves on { $waves }
umpk-sim-inputs-no-waves = inputs { $bits } (I{ $last }…I0); square waves on none
umpk-sim-not-page = `{ $page }` is not a page number
umpk-sim-flash-fail = flash writes to page { $page } (16#{ $address }) will fail with W
umpk-sim-flash-ok = flash writes succeed
umpk-sim-not-word = `{ $word }` is not a control word of a simulated UMPK
umpk-sim-empty-line = an empty control line

## Snapshots of the simulated UMPK (umpk::sim::snapshot): why one cannot be taken or restored

umpk-snap-monitor = its real-time monitor is streaming (stop it with `umpk monitor off` first)
umpk-snap-programming = a programming sequence is under way (finish it or reset first)
umpk-snap-line-busy = bytes are on its serial line (a command half-received or a reply unsent)
umpk-snap-builtin-program = its program `{ $program }` is built into plcsh, not IL text (load an IL file instead)
umpk-snap-other-model = the snapshot holds a { $saved }, this device is a { $model }
umpk-snap-flash-size = the flash image has the wrong size
umpk-snap-info-size = the program info or error history has the wrong size
umpk-snap-markers = the markers are not 32 hex digits
umpk-snap-timers = the timers or counters do not match the model
umpk-snap-wave = a square wave on input { $input } every { $period } cycles cannot run on this model
umpk-snap-flash-fail-page = its failing flash page { $page } is past the model's program memory
umpk-snap-fault-input = its fault { $fault } holds an input this model does not have
umpk-snap-cycle-ahead = its cycle count is ahead of the snapshot's clock
umpk-snap-mode = mode `{ $mode }` cannot be restored
umpk-snap-il-compile = its IL program { $source } does not compile: { $reason }
umpk-snap-il-state = its IL program's saved state does not fit the program ({ $part })
umpk-snap-il-mid-scan-part = its IL program was saved in the middle of a scan ({ $part })
umpk-snap-il-mid-scan = its IL program was saved in the middle of a scan

## The simulated UMPK's flash file and its server (umpk::sim::state, umpk::sim::serve)

umpk-state-cannot-encode = cannot encode the UMPK state
umpk-state-cannot-read = cannot read { $file }
umpk-state-bad-file = { $file } is not a UMPK state file: { $reason }
umpk-state-hint-remove = remove it to start with an empty flash
umpk-state-other-model = { $file } holds a { $saved }'s flash, not a { $model }'s
umpk-state-hint-other-file = use another state file for this model
umpk-state-info-size = program info or error history has the wrong size
umpk-serve-read-failed = reading the UMPK's line failed
umpk-serve-binary = simulated UMPK: a binary was programmed; { $note }
umpk-serve-write-failed = writing the UMPK's line failed
umpk-serve-not-model = `{ $model }` is not a UMPK model ({ $models })
umpk-serve-cannot-read-program = cannot read the UMPK program { $file }: { $reason }
umpk-serve-line-stopped = the UMPK line stopped before it was ready

## The simulated UMPK (umpk::sim)

# What the simulator says when a binary is programmed into it.
umpk-sim-binary-not-executed = the simulator stores and verifies a programmed binary but does not execute it (the UMPK's machine code is not published): after a reset the status shows Work mode (a program is loaded) while the outputs stay off; to run logic in the simulator, load an IL program (`sim program load FILE.il`, `sim serve --umpk-program FILE.il`; docs/il.md)
umpk-sim-page-past-end = flash page { $page } is past the { $model }'s program memory: pages 0–{ $last } ({ $bytes } bytes of { $size }-byte pages)
umpk-sim-hint-page = give a page from 0 to { $last }, or `off`
umpk-sim-program-kind = { $kind ->
    [none] none
   *[binary] a binary (stored and verified, not executed)
    }
umpk-sim-program-logic = { $program } (executed each cycle)
# The status word's flags in words (`umpk info`; UMPK manual §4.1.4).
umpk-status-flag = { $flag ->
    [W] W Work mode
    [H] H error history not empty
    [R] R real-time monitor on
    [E] E echo switched off
    [P] P Programming mode
   *[T] T LED blink phase
    }

## IL programs on the simulated UMPK (umpk::sim::program, umpk::sim::logic; UMPK manual §3.5)

umpk-il-range = `{ $text }` is a range; a program operand is one bit
umpk-il-elements = { $text }: the UMPK's timers and counters are its own instructions
umpk-il-hint-elements = on-delay: TIMER T0, GROUP, STEPS (e.g. TIMER T0, 1, 20 for 2.0 s); divide-by-N: DIVIDE C0, 4[, I1]
umpk-il-cannot-assign = { $text }: a program cannot assign { $operand } ({ $meaning })
umpk-il-hint-assign = a program assigns outputs Q and markers M; timers and counters change through TIMER and DIVIDE
umpk-il-user-error = { $text }: a user error code is 1–127 (128–255 are the system's)
umpk-il-hint-user-error = e.g. LD I7 / ERROR 12: error 12 in the history when I7 turns on
umpk-il-first-operand = { $text }: the first operand must be a { $what ->
        [timer] timer T0…
       *[counter] counter C0…
    }
umpk-il-delay-group = { $text }: the delay group is 0 (10 ms), 1 (0.1 s) or 2 (1 s)
umpk-il-delay-steps = { $text }: the delay is 1–255 steps of its group
umpk-il-ratio = { $text }: the division ratio is 1–255
umpk-logic-no-timer = there is no timer T{ $n }
umpk-logic-delay = T{ $n }: the delay is 1–255 steps
umpk-logic-no-counter = there is no counter C{ $n }
umpk-logic-ratio = C{ $n }: the division ratio is 1–255
umpk-logic-cannot-assign = { $operand }: a program cannot assign { $area } operands

## FX driver: the programming port and the computer link (fx::driver; the FX protocol notes, seed 004)

# What a request was, inside the messages below (`no reply to … on COM6`).
fx-req-port = { $kind ->
    [read] a read
    [e00] an E00 read
    [write] a write
   *[e10] an E10 write
    } of { $count } bytes at { $address }H
fx-req-port-operand = { $kind ->
    [write] a write
   *[e10] an E10 write
    } of { $operand }
fx-req-link-read = { $cmd } of { $count } point(s) from { $device }
fx-req-link-bw = BW of { $count } point(s) at { $device }
fx-req-link-ww = WW of { $count } value(s) at { $device }
fx-req-link-wt = WT of { $count } value(s)
# What one attempt got, in the list of attempts.
fx-got = { $got ->
    [data] data
    [bad-sum] bad sum check
    [other] another reply
    [noise] noise
    [partial] an incomplete reply
   *[silence] silence
    }
fx-attempts = { $n ->
    [one] 1 attempt
   *[other] { $n } attempts
    }
fx-attempts-list = { $n } attempts: { $list }
fx-late = ; { $count } characters came later and were dropped (a late reply is never taken for the next request's)
# The parts of a timeout: where its milliseconds come from.
fx-timeout-given = { $time } (timeout={ $given })
fx-timeout-wire = { $count } characters at { $serial }: { $ms } ms on the wire
fx-timeout-wait = message wait { $ms } ms
fx-timeout-plc = { $ms } ms for the PLC to answer
fx-timeout-server = { $ms } ms for the device server
fx-timeout-total = { $ms } ms ({ $parts })
fx-not-quiet = the line { $line } did not go quiet before { $what }: { $count } characters arrived in { $ms } ms
fx-hint-not-quiet-port = only one program may talk to the programming port: close GX Developer, an HMI or a terminal on it; check the cable for noise
fx-hint-not-quiet-link = plcsh must be the only master on the computer link: stop other programs polling it; check the cable for noise and the RS-485 termination
fx-no-reply = no reply to { $what } on { $line } within { $timeout }{ $late }
fx-no-reply-station = no reply to { $what } (station { $station }) on { $line } within { $timeout }{ $late }
fx-no-reply-no-enq = no reply to { $what } (sent without ENQ: it answered no ENQ either) on { $line } within { $timeout }{ $late }
fx-nak-code = { $who ->
    [plc] the PLC
   *[station] station { $station }
    } answered NAK { $code }H to { $what } on { $line }: { $meaning }
fx-hint-nak-area = check the operand against the model (`help OPERAND`)
fx-hint-nak-pc = the PC number of an FX is FF (pc=FF)
fx-hint-nak-sum = check the sum check setting (sum=, D8120) and the line's noise
fx-hint-nak-other = check the PLC's computer-link settings (D8120, D8121)
fx-nak = the PLC answered NAK to { $what } on { $line } ({ $tries }): it refuses a frame with a wrong sum check or an address where it has no device
fx-hint-nak-extended = check the operand against the model (`help OPERAND`) and the line's noise; a PLC without the E-commands (E00/E10/E7/E8) answers them NAK: open it as model=FX2N
fx-hint-nak-classic = check the operand against the model (`help OPERAND`) and the line's noise
fx-bad-reply = bad reply to { $what } on { $line } ({ $tries }): { $reason }
fx-hint-bad-sum-port = noise on the line or a wrong baud rate/parity (the port runs 7E1)
fx-hint-bad-sum-link = noise on the line, or a baud rate or character format that differs from the PLC's (D8120)
fx-noise = noise on the line { $line } instead of a reply to { $what } ({ $tries }): { $bytes } — characters that cannot start a reply (00H is what a serial port delivers for a character with a parity or framing error)
fx-hint-noise = check the cable's shield and ground, the converter's power and the RS-422/485 termination, and that the PLC runs { $serial } (a different baud rate or format also reads as noise)
fx-incomplete = incomplete reply to { $what } on { $line } within { $timeout } ({ $tries }): only { $bytes } came
fx-hint-incomplete = check the baud rate ({ $serial }), or raise the timeout (timeout= in the URL)
fx-other-reply = { $who ->
    [plc] the PLC
   *[station] station { $station }
    } answered { $what } on { $line } with something else ({ $tries }): { $reason }
fx-hint-other-port = only one program may talk to the programming port: close GX Developer, an HMI or a terminal on it
fx-hint-other-link = check that no other station is set to station { $station } (D8121) and that no other program polls this line; a reply that comes after the timeout belongs to an earlier request (raise timeout=)
fx-no-usable-reply = no usable reply to { $what } on { $line } ({ $tries })
fx-hint-late = the PLC answers later than { $time }: raise the timeout (timeout={ $twice } in the URL), or check its scan time (D8012)
fx-hint-silent-port = check the cable, that this is the programming port, and that it runs { $serial }
fx-hint-silent-link = check station { $station } (the PLC's D8121), PC number FF, the baud rate and format (D8120), and the sum check setting
fx-read-only = { $operand } ({ $meaning }) cannot be set
fx-special-device = a special device
fx-driven-by-plc = { $operand } — { $meaning } — is driven by the PLC: a write would be ignored
fx-hint-run-stop = RUN/STOP is the PLC's switch: on the simulator `sim cpu stop` / `sim cpu run`
fx-hint-driven = the PLC sets it every scan; read it, or use an ordinary M or D for your own flags
fx-retries = retries `{ $value }` must be 0–10
fx-no-option = fx devices have no option `{ $key }`
fx-hint-options = options: timeout, retries
# What a reply was instead of the one asked for (fx::driver::computer_link, programming_port).
fx-reply-other-length = a data frame with { $got } characters of data where { $want } were asked for (the reply to another request)
fx-reply-data-not-ack-link = a data frame ({ $bytes }) where ACK should be: a write is done only when the station answers ACK
fx-reply-data-not-ack = a data frame ({ $bytes }) where ACK should be
fx-reply-ack-not-data = ACK where the data should be
fx-reply-sum = sum check { $got }, the characters add up to { $want }
fx-reply-station = a reply from station { $station } (PC number { $pc }) where station { $want } (PC number { $wantpc }) should answer
fx-reply-garbled = a garbled frame ({ $bytes }): { $reason }
fx-bad-bits-reply = bad reply to { $what }: { $count } characters of 0/1 expected
fx-bad-words-reply = bad reply to { $what }: { $count } hex values expected
fx-param-out-of-range = `{ $key }={ $value }` in { $url } is out of range
fx-hint-param = { $key ->
    [station] station numbers are 0–31
    [wait] the wait is 0–15 (×10 ms, 0–150 ms)
   *[pc] the PC number is two hex digits, FF for FX
    }
fx-sum-param = `sum={ $value }` in { $url } is not 0 or 1
fx-format-param = `format={ $value }` in { $url }: formats 1 and 4 are supported
fx-xy-param = `xy={ $value }` in { $url }: octal or decimal
fx-line-params = { $url }: bits=7|8, parity=e|o|n, stop=1|2, baud above 0
fx-enq-nak = the PLC answered ENQ with NAK { $count } times on { $line }
fx-hint-enq-nak = another program may be talking to the programming port
fx-past-table = past the address table
fx-baud-zero = `baud=0` in { $url }: the baud rate must be positive
fx-sim-other-model = simulated PLC `{ $name }` is an { $model }, not an { $want }
fx-cannot-read-program = { $url }: cannot read { $file }: { $reason }
fx-protocol-param = `protocol={ $value }` in { $url }: port or link

## FX operands (fx::operand, fx::space; the FX protocol notes, seed 004)

# What a device area holds (`help`, completion, messages).
fx-area-meaning = { $area ->
    [X] input
    [Y] output
    [M] auxiliary relay
    [S] state relay
    [TS] timer contact
    [TC] timer coil (driven by the program; read-only)
    [CS] counter contact
    [CC] counter coil (driven by the program; read-only)
    [TN] timer current value
    [CN] counter current value (CN200–CN255 are 32-bit)
   *[D] data register
    }
# Special devices (FX programming manual, special device lists).
fx-special-meaning = { $device ->
    [M8000] RUN monitor (on while the PLC runs)
    [M8001] RUN monitor, inverted (off while the PLC runs)
    [M8002] initial pulse (on for the first scan after RUN)
    [M8003] initial pulse, inverted (off for the first scan after RUN)
    [M8011] 10 ms clock pulse (5 ms on, 5 ms off)
    [M8012] 100 ms clock pulse (50 ms on, 50 ms off)
    [M8013] 1 s clock pulse (0.5 s on, 0.5 s off)
    [M8014] 1 min clock pulse (30 s on, 30 s off)
    [D8000] watchdog time, ms
    [D8010] current scan time, 0.1 ms
    [D8011] shortest scan time, 0.1 ms
    [D8012] longest scan time, 0.1 ms
    [D8120] communication format (computer link: baud, parity, sum check …)
   *[D8121] computer-link station number
    }
fx-range-kind = a range needs two operands of one kind and size: { $first }..{ $last }
fx-range-reversed = range end { $last } is before its start { $first }
fx-range-steps = { $last } is not a whole number of steps of { $step } from { $first }
fx-range-long = range longer than { $max } operands
fx-number-missing = `{ $text }` needs a device number after { $area }
fx-not-digit = `{ $char }` in `{ $text }` is not a digit
fx-number-long = device number `{ $digits }` is too long
fx-not-octal = { $area } numbers are octal ({ $area }0–{ $area }7, { $area }10–{ $area }17 …): `{ $char }` is not an octal digit in `{ $text }`
fx-number-large-octal = `{ $digits }` is too large: device numbers go up to 177777 (octal)
fx-number-large = `{ $digits }` is too large: device numbers go up to { $max }
fx-operand-missing = an operand is missing
fx-unknown-type = unknown type `{ $name }` (use WORD, INT, DWORD, DINT, REAL)
fx-group-digits = K{ $n }: a group has 1–8 digits of 4 bits (K1 … K8)
fx-unknown-device = unknown FX device `{ $text }`
fx-hint-devices = devices: X Y M S (bits), T C or TS CS (timer/counter contacts), TC CC (coils), TN CN D (words), KnX KnY KnM KnS (groups)
fx-group-area = K{ $n }{ $area }: groups are made of X, Y, M or S bits
fx-view = { $operand } cannot be read as { $dtype }
fx-hint-view = D takes /WORD, /INT, /DWORD, /DINT, /REAL (32-bit: D and the next D); K1–K4 groups /INT, /WORD, /DINT, /DWORD; K5–K8 groups /DINT, /DWORD (K8 also /REAL)

fx-not-on-model = { $operand } is not on an { $model } ({ $range })
fx-crosses-special = { $operand } runs from ordinary into special devices
fx-hint-e-commands = on an FX3U the E-commands reach it (open it with model=FX3U); on an { $model } only the computer link does (fxlink:, with an FX-485 board and D8120 set)
fx-past-port-table = { $operand } is past the { $model }'s programming-port address table ({ $commands }; it reaches { $reach })
fx-not-on-link = { $operand } (a { $meaning }) is not reachable over the computer link
fx-hint-not-on-link = read the contact (TS/CS) instead, or use the programming port (fx:)
fx-describe-group = { $bits }-bit group of { $meaning } bits { $first }–{ $last }
fx-describe-pair = 32-bit value in D{ $low } (low) and D{ $high } (high)
fx-describe-special = special { $meaning }
fx-describe-unaligned = {" "}— warning: group starts at { $first }; the manual advises a number ending in 0 ({ $area }0, { $area }10 …)
fx-complete-group = { $bits }-bit group of { $meaning } bits

## Kinco servo driver (servo::driver, servo::frame; Kinco servo RS232 notes, seed 002)

# The manual's three reasons a drive stays silent (§2.4).
servo-silence-causes = a Kinco drive does not answer (1) a wrong drive id, (2) an object that does not exist, (3) a bad checksum (manual §2.4)
servo-port-still-gone = the serial port { $port } is still gone
servo-port-gone = the serial port { $port } is gone
servo-port-io = serial I/O on { $port } failed
servo-hint-port-gone = the USB adapter may be unplugged or the port's server restarted: check the cable and the adapter (`plcsh ports` lists the ports present); the next command reopens the port once it is back
servo-no-echo = no echo of the request on { $port } (loop mode is on)
servo-hint-no-echo = the loop is open (cable) or the line is not in loop mode: drop echo=1 from the URL
servo-reply-before-echo = expected the echo of the request on { $port } (echo=1), but the drive's reply came first: { $bytes }; the line is not in loop mode
servo-hint-reply-before-echo = connect with echo=0 (or set the drive's loop mode, panel d5.15 = 1)
servo-echo-differs = the echo differs from the request on { $port }: sent { $sent }, echoed { $echo }; likely cause: bad checksum — the drive ignores a corrupted frame
servo-hint-baud-wiring = check the baud rate (drive default 38400, panel d5.02) and the wiring
servo-reply-is-request = the reply to { $verb ->
        [read] read
        [write] write
       *[request] request
    } of { $object } is the request itself: the line echoes requests (RS232 loop mode)
servo-hint-use-echo = connect with echo=1 so plcsh skips the echo
servo-bad-reply = bad reply to { $verb ->
        [read] read
        [write] write
       *[request] request
    } of { $object }: { $reason }
servo-hint-bad-reply = another master or drive may be talking on the line, or the baud rate is wrong
# No reply: the head and the likely cause in one sentence.
servo-silent = no reply from drive id { $id } to { $verb ->
        [read] read
        [write] write
       *[request] request
    } of { $object } within { $timeout }; likely cause: { $cause ->
        [function] unknown function code { $code } — a drive answers only reads (40) and writes (23, 2B, 2F) and ignores anything else
        [checksum] bad checksum — the frame ends in { $got }, the bytes before it need { $want }
        [stray] bad checksum — only { $count } stray byte(s) came back ({ $bytes }), so frames are being corrupted on the line (baud rate or wiring)
        [object] unknown object — drive id { $id } answers statusword reads, so { $object } probably does not exist on this drive
        [stopped] the drive stopped answering — id { $id } answered before; check power and cable
       *[id] wrong id — nothing answers on drive id { $id } (factory id 1, panel d5.01; also check power, cable and baud rate)
    }
servo-silent-late = no reply from drive id { $id } to { $verb ->
        [read] read
        [write] write
       *[request] request
    } of { $object } within { $timeout }; likely cause: late replies — { $what }
servo-late-stale = a reply to another request came instead ({ $frames })
servo-late-bytes = { $count } byte(s) came after the timeout and were dropped
servo-hint-late = the drive answers later than the timeout: raise it (timeout= in the URL, now { $timeout }), and check that no other master talks on the line; a late reply is never taken for the next request's
servo-refused = drive id { $id } refused the { $verb ->
        [read] read
        [write] write
       *[request] request
    } of { $object }: abort code 16#{ $code } — { $meaning }
servo-resolution-zero = the drive reports encoder resolution 0 (6410.03)
servo-no-option = servo devices have no option `{ $key }`
servo-hint-options = options: encoder, timeout
servo-flag-param = `{ $key }={ $value }` in { $url } is not 0 or 1
servo-baud-zero = `baud=0` in { $url }: the baud rate must be positive
servo-latency-param = `latency={ $value }` in { $url } is not a duration (e.g. 1ms)
servo-ids-in-url = { $message } in { $url }
servo-not-ids = `{ $list }` is not a list of drive ids (0–255), e.g. 1,2
# What is wrong with a reply frame (servo::frame).
servo-frame-checksum = bad checksum { $got } (the bytes before it sum to checksum { $want })
servo-frame-reply-checksum = reply has a bad checksum { $got } (the bytes before it sum to checksum { $want })
servo-frame-id = reply from drive id { $got }, expected id { $want }
servo-frame-object = reply is for object { $got }, expected { $want }
servo-frame-func = reply function code { $got } does not answer a { $request } request
servo-frame-echo = write acknowledgement echoes data { $got }, the request sent { $want }
# CANopen abort codes the drive answers with (function code 80).
servo-abort = { $code ->
    [x05040001] invalid command
    [x06010001] attempt to read a write-only object
    [x06010002] attempt to write a read-only object
    [x06020000] object does not exist in the object dictionary
    [x06040041] object cannot be mapped
    [x06070010] data type does not match, length of service parameter does not match
    [x06070012] data type does not match, length of service parameter too high
    [x06090030] value range of parameter exceeded
   *[other] unknown abort code
    }

## The simulated Kinco drive's faults and switches (servo::sim::control, servo::sim::faults; `servo sim …`)

servo-sim-not-number = `{ $text }` is not a number
servo-sim-id-range = a drive id is 0-255
servo-sim-unknown-option = unknown option `{ $key }`
servo-sim-count = count is 1 or more, or all
servo-sim-all-and-count = say `all` or count=N, not both
servo-sim-fault-extra = unexpected `{ $word }` after `fault { $kind }`: say all or count=N
servo-sim-fault-duration = fault { $kind } needs one duration, e.g. fault { $kind } 50ms
servo-sim-fault-abort = fault abort needs an object and an abort code, e.g. fault abort target_position 16#06090030
servo-sim-abort-bits = an abort code is 32 bits
servo-sim-pulses-freq = pulses needs freq=HZ
servo-sim-pulses-count = pulses needs count=N
servo-sim-not-freq = `{ $text }` is not a frequency in Hz
servo-sim-pulse-count = count is 0 or more
servo-sim-not-dir = `dir={ $dir }` is not fwd or rev
servo-sim-unknown-word = unknown `servo sim { $word }`
servo-sim-fault-bits = a fault code is 16 bits
servo-sim-no-drive = no simulated drive has id { $id } (ids { $ids })
servo-sim-several-drives = several drives ({ $ids }) on the line: say which with id=N
servo-sim-fault-injected = drive id { $id }: fault 16#{ $code } injected
servo-sim-fault-armed = drive id { $id }: fault 16#{ $code } armed at position { $position } inc
servo-sim-fault-acted = { $time }s  drive id { $id }: fault 16#{ $code } at position { $position } inc (armed fault acted)
servo-sim-no-fault-acted = no armed fault has acted
servo-sim-line-fault = { $scope ->
        [all] every drive
       *[one] drive id { $id }
    }: { $fault } for { $count ->
        [one] the next request
        [every] every request until `servo sim fault clear`
       *[many] the next { $n } requests
    }
servo-sim-faults-cleared = line faults cleared
servo-sim-switch = drive id { $id }: { $switch ->
        [home] home switch
        [neg] negative limit switch
       *[pos] positive limit switch
    } { $position ->
        [off] off
       *[at] at { $at } inc
    }
servo-sim-pulses = drive id { $id }: { $count } pulses at { $freq } Hz { $dir ->
        [reverse] reverse
       *[forward] forward
    } from t={ $start } s to t={ $end } s
servo-sim-strict = write sizes: { $strict ->
        [on] sizes must match the object (0x06070010 otherwise)
       *[off] lenient sizes
    }
# A line fault in words (`servo sim fault …`, `faults`).
servo-sim-fault-kind = { $kind ->
    [no-reply] no reply
    [bad-checksum] bad checksum in the reply
    [delay] reply delayed by { $ms } ms
    [abort] abort 16#{ $code } ({ $meaning }) for { $object }
   *[drop-echo] echo dropped
    }

## FX frames (fx::link, fx::port; the FX protocol notes, seed 004)

# What is wrong with a frame (inside `a garbled frame (…): …`).
fx-malformed = { $what ->
    [no-crlf] no CR LF after the reply
    [too-short] too short
    [station-not-hex] the station or PC number is not hex
    [code-not-hex] error code is not hex
    [length-after-etx] wrong length after ETX
    [sum-not-hex] sum check is not hex
    [bytes-after-etx] bytes after ETX
    [unknown-command] unknown command or wrong length
    [address-not-hex] address is not hex
    [count-not-hex] count is not hex
    [data-length] data length differs from the count
    [data-not-hex] data is not hex
   *[not-read-reply] not STX data ETX sum of the asked length
    }
# The computer link's NAK error codes (seed 004: "若发送码有误，则有以下回应").
fx-nak-meaning = { $code ->
    [c02] sum check error (the sum in the request does not match its characters)
    [c03] protocol error (the request does not follow the control procedure)
    [c06] character area error (unknown command, or a device number or count the PLC does not have)
    [c07] character error (data to write is not hexadecimal ASCII)
    [c0A] PC number error (no station with this PC number)
    [c18] remote error (RUN/STOP cannot be switched remotely)
   *[other] unknown error code
    }

## The simulated FX PLC's control words, snapshots and server (fx::control, fx::snapshot, fx::sim)

fx-sim-not-x = `{ $text }` is not an X input (X0, X17 …)
fx-sim-no-such-input = { $operand } is not an input of the { $model } (X0–X{ $last })
fx-sim-input-usage = input needs an input and a level: input X0=1
fx-sim-input-extra = `{ $word }` after input { $input } is not understood
fx-sim-input-level = `{ $input }`: write input { $input }=1 or =0
fx-sim-inputs-none = no X input is on
fx-sim-inputs-on = on: { $inputs }
fx-sim-not-word = `{ $word }` is not a control word of a simulated FX PLC
fx-snap-other-model = the snapshot is of an { $saved }, this simulator is an { $model }
fx-snap-image = the saved device image does not fit this model
fx-serve-cannot-read = cannot read { $file }: { $reason }
fx-serve-stopped = the FX port stopped before it was ready

## The simulated drive's homing and pulse input (servo::sim)

servo-sim-homing-neg = method 17 needs a negative limit switch
servo-sim-homing-pos = method 18 needs a positive limit switch
servo-sim-homing-method = homing method { $method } is not simulated (methods { $methods })
servo-sim-no-drive-id = no drive id { $id } on the simulated line
servo-sim-pulse-ab = the drive's pulse input is set to A/B (2508.03 = 2); a PLC pulse output is pulse + direction: set 2508.03 to 1 first
servo-sim-no-drive-short = no drive id { $id }
servo-not-servo-any-more = the device no longer answers as a servo drive

## Links: control channels, shared lines, RFC 2217, pseudo-terminals (core::link)

link-cannot-open-channel = cannot open { $what } at { $path }
link-hint-channel-path = choose another path, or remove a stale file left by a server that was killed
link-control-line-long = a control line is at most { $max } bytes
link-control-line-utf8 = a control line is UTF-8 text
link-cannot-reach-channel = cannot reach the simulator's control channel { $path }
link-hint-reach-channel = is `plcsh sim serve` still running? Its readiness line names the control channel's path
link-channel-answered = the control channel answered `{ $reply }`
link-simulator-refused = the simulator refused
# The names of the simulators' control channels (inside link-cannot-open-channel).
link-channel-name = { $device ->
    [servo] the servo control socket
    [umpk] the served UMPK's control channel
   *[fx] the served FX PLC's control channel
    }
link-line-settings = { $line } is already open with { $open }, not { $settings }
link-hint-line-settings = every drive on one line uses the same baud rate and loop setting
link-pipe-closed = the other end of the pipe closed
link-no-reply-timeout = no reply within the timeout
link-rfc2217 = the RFC 2217 server at { $addr } { $what ->
        [confirm] did not confirm the line settings in time
        [agree] did not agree to set the serial port (COM-PORT-OPTION) in time
        [closed] closed the connection ({ $reason })
        [refused] refused to let this side set the serial port
       *[baud] set { $got } baud instead of { $want }
    }
link-hint-rfc2217 = check that the device server's channel is in RFC 2217 mode (or use +tcp:// for a raw TCP channel) and that it supports this baud rate and format
link-pty-dup-master = cannot duplicate the pty master
link-pty-dup-slave = cannot duplicate the pty slave
link-pty-register = cannot register the pty master with tokio
link-pty-open = cannot open a pseudo-terminal
link-pty-call = { $call } on pty
link-pty-nonblocking = cannot make the pty non-blocking
link-not-symlink = { $path } exists and is not a symlink; choose another path
link-cannot-symlink = cannot create the symlink { $path }
link-control-no-port = the control file holds no port number
link-windows-no-pty = Windows has no pseudo-terminals to serve a simulator on
link-hint-windows-tcp = serve it on a TCP port instead (sim serve --rtu-tcp 0, --servo-tcp 0, --fx-tcp 0, --fx-link-tcp 0, --umpk-tcp 0) and connect with rtu+tcp://, kinco+tcp://, fx+tcp://, fxlink+tcp:// or umpk+tcp://

# `help OPERAND` on an FX (fx::space).
fx-help-group-range = 0…{ $max } (missing high bits are zero)
fx-help-port = programming port ({ $commands }): byte address { $address }H, { $bytes } byte(s)
fx-help-force = , force address { $address }H
fx-help-link = computer link: device { $device }
fx-help-manual = manual: seed 004 (FX device groups KnX, programming-port protocol; fx-and-masterk.md A, B)
fx-help-type = type { $dtype } ({ $bits } bits), range { $range }
fx-help-on-model = on { $model }: { $range }

# The two ways to an FX (fx::space::Proto).
fx-proto = { $proto ->
    [port] programming port
   *[link] computer link
    }
