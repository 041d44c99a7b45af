# plcsh's messages in English: the reference catalogue. Every id here is in ru/ and zh-CN/ too,
# with the same arguments (tests: core::msg). docs/development.md, "How to add a message".
# Operands, mnemonics, commands, options and JSON keys stay as they are in every language.

## The shape of an error (core::error, output)

# The label before an error's hint, on the line under `error[KIND]: …`.
label-hint = hint: { $hint }
# The label before a warning (lab check's free points).
label-warning = warning: { $warning }
label-note = note: { $note }

# What each `error.kind` means and what to do (the table of docs/reference/errors.md).
error-kind-cause = { $kind ->
    [syntax] the line does not parse: a stray character, an unclosed quote, a missing `=` in `set`
    [operand] the operand is unknown or malformed (`VX0`, `M0.8`, `SMB`)
    [value] the value does not fit the operand (`set VB2=300`) or is not a number of the unit asked for
    [range] the operand is past the end of the model's area, or the model has no such area (`AIW0` on a K205-16DT)
    [unsupported] this device or link cannot do it: SM, T and C over plain Modbus, an instruction without the helper
    [refused] the device answered with a refusal: a Modbus exception, a servo abort code, a helper result
    [link] no answer, a timeout, a bad CRC, a dropped connection, a port that cannot be opened
    [timeout] a wait ran out of time (`wait`, a helper command not acknowledged)
    [usage] a command was used wrongly: a missing argument, an unknown command or device, a file in use
    [script] a Lua script failed: a runtime error, a failed `plcsh.assert_eq`, `os.exit`
    [io] a file or the operating system failed: a file that cannot be read or written
    [interrupted] Ctrl-C, SIGTERM or SIGHUP stopped the command; the abort handlers ran
   *[state] the device is in a state where the command cannot run: a PTO busy, the helper's mailbox busy, the helper stopped
}
error-kind-fix = { $kind ->
    [syntax] the caret under the line points at the word; `help COMMAND` shows the form
    [operand] `help VW100` explains an operand; Tab completes them
    [value] the message gives the range of the operand's type; use a view (`VW0/INT`) for signed values
    [range] check `model=` in the URL against the PLC (`plcsh models`); the hint names the models that have the area
    [unsupported] install the helper program for SM registers and instructions (docs/agent.md), or use the simulator
    [refused] the hint says which; for `illegal data address` check `model=` against the PLC
    [link] the no-reply checklist: unit id, baud/parity/stop, A/B wiring, permissions, a program holding the port; `-v` shows the frames
    [timeout] give the wait longer, or check that the PLC is in RUN and the helper is called every scan
    [usage] `help COMMAND`; `devices` lists the device names
    [script] the message names file:line, with a traceback
    [io] the message names the file and the system's reason
    [interrupted] run it again; the exit status says which signal (docs/reference/exit-status.md)
   *[state] wait for the running operation (`pto 0 status`), or put the PLC in RUN
}

# `--lang` or `language` naming a language plcsh does not speak.
lang-unknown = unknown language `{ $lang }`: plcsh speaks en, ru, zh-CN

## Values (core::literal): IEC 61131-3 literals and whether they fit an operand

literal-missing = a value is missing
literal-space = unexpected space in value `{ $value }`
literal-duration = { $message }
literal-typed-integer = { $prefix }# takes an integer; write REAL#{ $rest } for a floating-point value
literal-unknown-prefix = unknown type prefix `{ $prefix }#` (use B#, W#, DW#, INT#, DI#, REAL#, T# or a radix 2#, 8#, 16#)
literal-number-missing = a number is missing
literal-c-notation = `{ $typed }` is C notation; write { $iec } (IEC 61131-3, as KincoBuilder does)
literal-unknown-radix = radix { $radix }# is not one of 2#, 8#, 10#, 16#
literal-no-digits = no digits after { $radix }#
literal-not-digit-of-base = `{ $char }` is not a base-{ $radix } digit
literal-too-wide = { $value } is wider than 32 bits (16#FFFF_FFFF at most)
literal-not-number = `{ $value }` is not a number
literal-not-digit = `{ $char }` is not a digit in `{ $value }`
literal-too-large = { $value } is too large: integers go up to { $max }
value-does-not-fit = { $value } does not fit { $dtype } ({ $min }…{ $max })
value-not-bit = { $value } does not fit a bit (use 0/1, TRUE/FALSE, ON/OFF)
value-bit-not-real = { $value } is a bit, not a REAL
value-not-real = { $value } does not fit a REAL (32-bit IEEE float: ±{ $max } at most)
value-not-integer = { $value } is not an integer; a { $dtype } holds whole numbers (to store an IEEE float use a 32-bit operand with /REAL, e.g. VD100/REAL)
value-type-too-wide = { $value } is a { $dtype } ({ $bits } bits) and does not fit a { $width }-bit operand
value-out-of-range = { $value } is out of range for { $dtype } (0…{ $max })
value-out-of-range-group = { $value } is out of range for a { $bits }-bit group (0…{ $max })
value-out-of-range-signed = { $value } is out of range for { $dtype } (0…{ $max }); write it as { $signed }#{ $number } to store its two's complement
value-out-of-range-group-signed = { $value } is out of range for a { $bits }-bit group (0…{ $max }); write it as { $signed }#{ $number } to store its two's complement

## Durations, timeouts and frequencies (core::literal)

duration-not-whole-ms = T#{ $value } is not a whole number of milliseconds
duration-too-long = `{ $value }` is longer than the longest duration, { $max } µs (about 292 000 years)
duration-missing = a duration is missing (e.g. 500ms, 2s, 250us)
duration-not-duration = `{ $value }` is not a duration (e.g. 500ms, 2s, 250us)
duration-needs-unit = `{ $value }` needs a unit on every number (h, m, s, ms, us), e.g. { $number }ms or { $number }s
duration-unknown-unit = unknown time unit `{ $unit }` in `{ $value }` (use h, m, s, ms, us)
timeout-not-positive = `timeout={ $value }` must be more than zero (e.g. 200ms)
timeout-too-short = `timeout={ $value }` is shorter than a microsecond, the finest a link waits (e.g. 200ms)
timeout-too-long = `timeout={ $value }` is longer than a day ({ $max } ms), the longest a link waits for a reply
freq-not-frequency = `{ $value }` is not a frequency (e.g. 2kHz, 500Hz)
freq-unknown-unit = unknown frequency unit `{ $unit }` in `{ $value }` (use Hz, kHz)
freq-not-positive = `{ $value }` is not a positive frequency
freq-too-large = `{ $value }` is too large a frequency to hold (at most { $max } Hz)

## Operand expressions: counts and ranges (core::operand, k2::operand)

count-missing-bracket = missing `]` in count form (e.g. { $example })
count-not-a-count = `{ $count }` is not a count (e.g. { $example })
count-out-of-range = count must be 1…{ $max }
range-one-dots = a range has one `..`: FIRST..LAST, e.g. { $example }
range-mixed = a range needs two operands of one area and size: { $first }..{ $last }
range-group-sizes = a range of bit groups needs one group size
range-backwards = range end { $last } is before its start { $first }
range-off-step = { $last } is not on a { $step }-step from { $first } (ranges step by the operand size)
range-too-long = range longer than { $max } operands
operand-missing = an operand is missing
operand-unknown-type = unknown type `{ $name }` (use BOOL, BYTE, SINT, WORD, INT, DWORD, DINT, REAL)
operand-view-width = { $operand } is { $bits } bits wide; /{ $view } needs { $need } bits (views keep the width: /SINT on bytes, /INT on words, /DINT or /REAL on double words)
operand-unexpected-after = unexpected `{ $rest }` after { $head }

## K2 operands (k2::operand, k2::space; K2 manual §3.2)

k2-area-meaning = { $area ->
    [I] digital inputs
    [Q] digital outputs
    [M] internal memory bits
    [V] variable memory
    [SM] special memory (system and function registers)
    [AI] analog inputs
    [AQ] analog outputs
    [T] timers (current value)
   *[C] counters (current value)
}
k2-address-too-large = `{ $operand }` is past every K2 area: addresses go up to { $max } at most (the largest area, V, ends at VB{ $last })
k2-element-needs-number = { $area } needs a number ({ $area }0…{ $area }255)
k2-analog-words = analog values are words: { $area }W0, { $area }W2 …
k2-analog-needs-address = { $area }W needs a byte address (e.g. { $area }W0)
k2-analog-even = analog words are at even addresses: { $below } or { $above }
k2-analog-even-last = analog words are at even addresses: { $below }
k2-needs-byte-address = { $operand } needs a byte address
k2-byte-has-no-bit = a byte has no bit; write the bit as { $bit }
k2-word-has-no-bit = a word has no bit; write the bit as { $bit }
k2-needs-bit-or-size = { $area } needs a bit (`{ $area }0.0`) or a size letter (`{ $area }B0`, `{ $area }W0`, `{ $area }D0`)
k2-byte-needs-bit-or-size = { $area }{ $byte } needs a bit ({ $area }{ $byte }.0) or a size ({ $area }B{ $byte }, { $area }W{ $byte }, { $area }D{ $byte })
k2-bit-missing = a bit number 0…7 is missing
k2-bit-too-large = bit { $bit } does not exist: bits are 0…7 ({ $last } is the last)
k2-group-size = bit groups are K1…K8 (4 to 32 bits)
k2-group-nested = { $group } groups bits of I, Q, M, V or SM; groups do not nest
k2-group-needs-bit = { $group } groups bits: write { $example } (a bit address), not a byte or word
k2-group-area = { $group } groups bits of I, Q, M, V or SM
k2-not-operand-no-area = `{ $operand }` is not a K2 operand: operands start with an area letter
k2-not-operand-unknown-area = `{ $operand }` is not a K2 operand: unknown area `{ $area }`
k2-hint-did-you-mean = did you mean { $suggestions }? areas are I Q M V SM AI AQ T C
k2-hint-no-data-blocks = the K2 has no data blocks: its data memory is V (VB0, VW0, VD0 …); areas are I Q M V SM AI AQ T C
k2-hint-no-options = commands take no -options here; name operands such as VW0, I0.0, SMB67
k2-hint-areas = areas are I Q M V SM AI AQ T C, e.g. VW0, I0.0, Q0.1, SMB67, T5
k2-model-has-no-area = { $model } has no { $area } area ({ $meaning })
k2-hint-models-with = models with { $area }: { $models }
k2-past-the-end = { $operand } is past the end of the { $area } area on { $model } (last { $size ->
        [bit] bit
        [byte] byte
        [word] word
        [dword] double word
        [group] group
       *[element] element
    } is { $last })
k2-area-too-small = { $operand } does not fit the { $area } area on { $model }: it has { $bits } bits, fewer than one { $size ->
        [bit] bit
        [byte] byte
        [word] word
        [dword] double word
        [group] group
       *[element] element
    } needs
k2-bit-and-byte-past-the-end = { $operand }: bit { $bit } does not exist (bits are 0…7), and byte { $byte } is past the end of the { $area } area on { $model } (last bit is { $last })
k2-hint-area-bits = { $meaning } on { $model }: { $first } … { $last }

## Links: no reply, timeouts, ports (core::link, k2::driver)

link-no-reply = the device did not answer: no reply from unit { $unit } within { $timeout }
link-no-valid-reply = unit { $unit } sent no valid reply within { $timeout }: { $what }
link-closed = the PLC closed the connection instead of replying
link-failed = the link failed
link-attempts = { $message } ({ $attempts ->
        [one] { $attempts } attempt
       *[other] { $attempts } attempts
    })
k2-hint-no-reply = { $link ->
    [tcp] check the unit id (unit=), that HOST:PORT is the PLC (a K204ET answers Modbus TCP on port 502) and that it is powered and reachable (ping)
    [rtu] check the unit id (unit= is the PLC port's station number), the wiring (RS485 A/B, ground), the port settings (baud=, parity=, stop=) against the PLC port's, and the port path
    [gateway] check the unit id (unit=), the gateway's address and port, and that its serial settings (baud, parity, stop bits) match the PLC port's
    [rfc2217] check the unit id (unit=), the device server's address and port, and the line settings (baud=, parity=, stop=) against the PLC port's
   *[stream] check the unit id and what is at the other end of the stream
}
k2-hint-garbled = { $link ->
    [rtu] check the port settings (baud=, parity=, stop=) against the PLC port's, the wiring (RS485 A/B, ground, termination at both ends of a long line), and that no other master or device talks on the line
    [gateway] check the gateway's serial settings (baud, parity, stop bits) against the PLC port's, the wiring from the gateway to the PLC, and that the gateway is in transparent (RTU) mode, not Modbus TCP
    [rfc2217] check the line settings (baud=, parity=, stop=) against the PLC port's and the wiring from the device server to the PLC
    [tcp] check that HOST:PORT speaks Modbus TCP (an RTU gateway needs rtu+tcp://)
   *[stream] check what is at the other end of the stream
}
k2-hint-damaged = { $link ->
    [rtu] the bytes were damaged on the way; check the port settings (baud=, parity=, stop=) against the PLC port's, the wiring (RS485 A/B, ground, termination at both ends of a long line), and that no other master or device talks on the line; plcsh retries (retries=)
    [gateway] the bytes were damaged on the way; check the gateway's serial settings (baud, parity, stop bits) against the PLC port's, the wiring from the gateway to the PLC, and that the gateway is in transparent (RTU) mode, not Modbus TCP; plcsh retries (retries=)
    [rfc2217] the bytes were damaged on the way; check the line settings (baud=, parity=, stop=) against the PLC port's and the wiring from the device server to the PLC; plcsh retries (retries=)
    [tcp] the bytes were damaged on the way; check that HOST:PORT speaks Modbus TCP (an RTU gateway needs rtu+tcp://); plcsh retries (retries=)
   *[stream] the bytes were damaged on the way; check what is at the other end of the stream; plcsh retries (retries=)
}
k2-hint-closed = plcsh reconnects and retries (retries=); if it keeps happening, check the PLC's limit on Modbus TCP connections and whether another client or a gateway takes the connection over
link-cannot-connect = cannot connect to { $addr }
link-name-not-looked-up = cannot connect to { $addr }: the name was not looked up within { $ms } ms
link-hint-name-server = use the IP address, or check the name server
link-connect-timeout = cannot connect to { $addr }: no answer within { $ms } ms
link-cannot-listen = cannot listen on { $addr }
link-hint-listen = choose another port (0 picks a free one); ports below 1024 need privileges
link-cannot-open-port = cannot open the serial port { $port }
link-cannot-use-port = cannot use the serial port { $port }
link-hint-open-port = `plcsh ports` lists this computer's serial ports and their USB adapters; check the name ({ $examples }), that no other program (KincoBuilder, a terminal program) holds the port
link-hint-open-port-group = `plcsh ports` lists this computer's serial ports and their USB adapters; check the name ({ $examples }), that no other program (KincoBuilder, a terminal program) holds the port, and that you may open it (the dialout group: sudo usermod -aG dialout $USER, then log in again)
link-not-host-port = `{ $target }` in { $url } is not HOST:PORT
link-hint-host-port = give the device server's address and the TCP port of its serial channel, e.g. 192.168.127.254:4001
link-no-address = the name resolves to no address
link-hint-server = check the device server's address and the TCP port of this serial channel, that it is in raw TCP server mode (or RFC 2217 for +rfc2217://), that no other client holds the channel, and that no firewall blocks the port
link-connection-closed = the connection closed
link-cannot-start-thread = cannot start the accepting thread
link-no-port-named = { $url } names no serial port
link-hint-port-example = e.g. { $example } (`plcsh ports` lists this computer's serial ports)
link-unknown-carrier = `+{ $carrier }` in { $url } is not a way to reach a serial line
link-hint-carriers = use +tcp://HOST:PORT (a device server's raw TCP port) or +rfc2217://HOST:PORT
link-cannot-list-ports = cannot list the serial ports
link-hint-list-ports-dev = ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id shows the ports the kernel has
link-hint-list-ports-device-manager = Device Manager → Ports (COM & LPT) shows the ports Windows has
k2-no-option = K2 wire devices have no option `{ $key }`
k2-hint-options = options: word_order (high-first, low-first), timeout, retries, agent
k2-retries-not-number = `retries={ $value }` is not a number
k2-not-scheme = `{ $scheme }:` is not a K2 wire scheme
k2-cannot-start-runtime = cannot start a runtime for the attached stream
k2-attached-failed = the attached stream failed and cannot be reopened by plcsh
k2-hint-reopen = { $hint }; the next command opens it again once it is back
k2-reply-too-short = the reply to a read of { $span } was too short
k2-request = { $doing ->
        [reading] reading
       *[writing] writing
    } { $operand }{ $more ->
        [0] {""}
       *[other] {" "}and { $more } more
    } ({ $span }, FC { $fc })
k2-while = { $what }: { $message }
k2-refused = the PLC refused { $what }: { $exception } (Modbus exception { $code })
k2-hint-exception-1 = this PLC does not support that function code over this port
k2-hint-exception-2 = the address is outside the PLC's Modbus map; check that model={ $model } matches the PLC
k2-hint-exception-3 = the PLC refused the request's size or value (limits: 1600 bits or 100 registers read, 800 bits or 100 registers written)
k2-hint-exception = see the PLC's diagnostics
k2-hint-connect = check that HOST:PORT is the PLC or gateway (a K204ET answers Modbus TCP on port 502), that it is powered and reachable (ping), and that no firewall blocks the port
k2-writes-before = { $message }; the { $sent } write request(s) before it were sent
link-not-parity = `parity={ $parity }` in { $url } is not a parity
link-hint-parity = use parity=none, parity=even or parity=odd
link-not-stop-bits = `stop={ $stop }` in { $url } is not 1 or 2
link-baud-zero = `baud=0` in { $url } is not a baud rate
link-not-unit-id = `unit={ $unit }` in { $url } is not a Modbus unit id
link-hint-unit-id = unit ids are 1…247 (0 is broadcast, which gets no reply)
link-cannot-use-connection = cannot use the connection to { $addr }

## The command line (cli)

# `--help` and the man page (cli::localise): the same texts as the doc comments of cli::Cli,
# without the full stop clap leaves out (a test holds them together).
cli-about = A shell for commissioning and debugging Kinco K2 PLCs and servo drives
cli-opt-command = Run these commands (separated by `;`) and exit
cli-opt-json = Print one JSON object per command result
cli-opt-verbose = Show more: each frame sent and received in hex with timing, request counts, sample rates
cli-opt-model = Model of the default simulated PLC
cli-opt-device = Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable
cli-opt-time = Simulator time: follow the wall clock, or move only when stepped
cli-opt-config = Device profile file (default: PLCSH_CONFIG, else { $file }).
cli-opt-state = Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user's data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE
cli-opt-record = Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)
cli-opt-bench = Open a simulated machine described by a bench file (devices, wiring, initial values)
cli-opt-read-only = Refuse every change to every device (writes, instructions, servo commands): inspect a live machine
cli-opt-fleet = Run -c's commands (or `run`'s script) on every device of this fleet from the profile file, at once (docs/fleets.md)
cli-opt-jobs = With --fleet: how many devices are worked on at once
cli-opt-lang = The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system's; English when neither names one of these)
cli-opt-device-timeout = With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)
cli-opt-tags = A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable
cli-sub-models = List the K2 model catalogue; `models MODEL` shows one in full (areas, counters, manual notes)
cli-sub-devices = List open devices and the device profiles (devices.toml), with problems in that file
cli-sub-ports = List the serial ports present, with USB adapter (VID:PID, product, serial number)
cli-sub-paths = Print where every file lives: profiles, Lua modules, state, history, snapshots, UMPK flash, recordings
cli-sub-man = Print the manual page (roff) made from these flags and the shell's commands: plcsh man > plcsh.1
cli-sub-completions = Print a shell completion script (bash, zsh, fish, powershell), or write them all
cli-sub-sim = Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives { $served ->
        [tcp] on a TCP port (raw or RFC 2217, which a COM port pair such as com0com's can reach)
       *[pty] on a pty or a TCP port (raw or RFC 2217)
    }.
cli-sub-agent = The PLC-side helper program that gives plcsh SM registers and instructions on a real K2
cli-sub-probe = What a K2 answers over Modbus before the helper is in it: areas and their last addresses, the models that fit, response time; reads only (docs/reference/first-connection.md)
cli-sub-run = Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]
cli-sub-record = Recordings made with --record: `record show FILE` prints the decoded timeline
cli-sub-replay = Replay a recording's requests against a simulator and report every reply that differs
cli-sub-lab = Teaching labs: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (sandboxed, in parallel)
cli-sub-publish = Poll operands on a device or a fleet and publish them to an MQTT broker (docs/fleets.md)
cli-sub-tags = Tag tables (docs/tags.md): `tags FILE` lists the names, `tags check FILE` checks them, `tags export FILE --to csv|iec` writes them in another form
cli-lab-new = Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME
cli-lab-new-name = The new lab's folder
cli-lab-check = Check a lab: its lab.toml, files and start state, and the grader on the reference solution
cli-lab-arg-lab = The lab folder (or its lab.toml)
cli-lab-grade = Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker
cli-lab-grade-submissions = Submission files or folders
cli-lab-grade-jobs = Worker processes at a time (default: one per core)
cli-lab-grade-junit = Also write the results as JUnit XML to FILE
cli-lab-grade-show-output = Show what each submission printed (stdout and stderr, the first 64 KiB of each); `--json` always carries them as `stdout` and `stderr`
cli-heading-usage = Usage:
cli-heading-commands = Commands
cli-heading-arguments = Arguments
cli-heading-options = Options
cli-heading-global = Global options
cli-help-flag = Print help
cli-version-flag = Print version
cli-hint-shell-command = `{ $line }` is a shell command: plcsh -c '{ $line }'

## Help and the command card (shell::commands::help): what each command does, the help screens

# What a command does: `help`'s and the completion menu's line, the command card, the man page.
summary-get = read operands (ranges and device: prefixes allowed)
summary-set = write operands in order; the whole line is checked before anything is written
summary-read = read a range as a table: value, hex and binary
summary-use = make DEVICE the one operands without a prefix go to
summary-devices = list open devices and device profiles
summary-connect = open a device under a name, or a device profile from devices.toml
summary-close = close a device
summary-sim = the simulator's clock (show, step and keep stepped, follow the wall clock), input signals for the counters, retained ranges, the CPU running an IL program, wiring between simulated devices, snapshots of the simulated state, injected faults
summary-watch = a live table of operands, refreshed in place until Ctrl-C or count=N; changes highlighted
summary-trace = record operands over time (for `plot`), optionally into a CSV file
summary-plot = draw the last trace in the terminal, and as a PNG or SVG picture with to= (a pulse output as its frequency)
summary-servo = Kinco servo helpers: DS402 state machine, moves, jog, homing, waits, units, raw frames
summary-umpk = UMPK8/UMPK16 teaching PLCs: controller and program info, error history, timing, reset, echo, real-time monitor, Intel HEX programming
summary-pls = run the PLS instruction on pulse channel N (0 = Q0.0, 1 = Q0.1, 2 = Q0.4, 3 = Q0.5 on K209M)
summary-pstop = emergency-stop pulse channel N (latches SM201.7 …; clear it with set SM201.7=0)
summary-pto = start a single-segment pulse train (writes SMB67, SMW68, SMD72, then PLS), or decode its status
summary-pwm = start PWM on channel N (writes SMB67=16#D3, SMW68, SMW70, then PLS)
summary-profile = multi-segment PTO from a profile table (writes the table, SMW168, SMB67=16#A0, then PLS); `plan` only draws the frequency over time
summary-hdef = run the HDEF instruction: give counter HSC N its mode (§3.3.1)
summary-hsc = run the HSC instruction; with options, write the counter's registers first (then HDEF, HSC); or decode its status
summary-events = show the interrupt events raised so far with their virtual times, and clear the log (`keep` leaves it)
summary-wait = block until the device raises an interrupt event (taken from the log); stepped time jumps ahead
summary-rtc = read the PLC's real-time clock, set it, or set it from the host's local time
summary-eeprom = save or load the E2PROM backup area (VB3648…) as a binary file; show write counts; set where the area ends
summary-data = data sets: save operands' typed values to a file, compare a file with the device or another file, load only what differs
summary-lua = run Lua in the session's Lua state (devices are globals: plc.VW100 = 5)
summary-agent = check the PLC-side helper that reaches SM registers and instructions over Modbus (docs/agent.md)
summary-lab = teaching labs: write an example lab, check a lab against its reference solution, grade submissions (sandboxed, in parallel)
summary-models = the K2 model catalogue; one model in full (areas, counters, pulse outputs, manual notes)
summary-ports = the serial ports present, with USB adapter (VID:PID, product, serial number)
summary-paths = where every file lives: profiles, Lua modules, state, history, snapshots
summary-help = list commands, or explain one command (its full usage) or operand
summary-quit = leave the shell

# `help`: the groups of commands, by their key in shell::commands::help::GROUPS.
help-groups-heading = commands by group (`help all` lists each with what it does):
help-group = { $group ->
    [io] read and write
    [devices] devices
    [simulator] simulator
    [pulse] pulse outputs
    [counters] counters
    [interrupts] interrupts
    [plc] PLC
    [servo] servo, UMPK
    [scripts] scripts, labs
   *[shell] this shell
}
# Wrapped to the terminal's 80 columns.
help-footer = `help COMMAND`: its forms (`help pto`); `help sim step`: a sub-command's forms. `help VW100`, `help SMB67`: what an operand is. Tab completes commands, operands and options (`pto 0 fr` ⇥ `freq=`).
help-all-heading = commands (`help COMMAND` shows its forms and sub-commands):
help-all-footer = operands: `help VW100`, `help SMB67` explain one; Tab completes them
help-sub-commands = sub-commands: { $list }
help-no-topic = no command or operand `{ $topic }`
help-extra-word = help takes a command and one sub-command (got `{ $word }` after them)
help-no-sub-command = `{ $command }` has no sub-command `{ $sub }`
shell-takes-nothing = { $command } takes nothing after it (got `{ $word }`)
# The man page's section of shell commands (cli::man): its heading and first paragraph.
man-shell-commands = SHELL COMMANDS
man-shell-commands-intro = Typed at the plcsh> prompt, given to -c (several separated by ;) or run from Lua with plcsh.exec. help lists them by group, help COMMAND shows a command's forms.

## Labs (lab): the grade's and the check's lines, tables and verdicts, in the lab's `language`

lab-new-wrote = wrote { $dir } ({ $files }); check it with: plcsh lab check { $dir }
lab-grade-head = { $lab }: { $count } submission(s), { $passed } passed every criterion
lab-duplicate-student = warning: { $count } submissions have the student name { $student }: { $files }
# The columns of `lab grade`'s table, `|` between them.
lab-grade-columns = student | points | passed | failed | verdict | simulated time
lab-check-columns = criterion | points | result
lab-verdict = { $verdict ->
        [passed] passed
       *[failed] failed
    }
lab-criterion-ok = ok
lab-not-reached = not reached
lab-expected = expected { $expected }, got { $got }
lab-expected-at = expected { $expected }, got { $got } at { $at } s
lab-expected-what = { $what }: expected { $expected }, got { $got }
lab-expected-what-at = { $what }: expected { $expected }, got { $got } at { $at } s
lab-error-at = { $error } at { $at } s
lab-free-points-starter = the starter { $file } earns { $points }/{ $max } points ({ $criteria }): a criterion a program passes without doing the task checks nothing the task asks
lab-free-points-empty = an empty program earns { $points }/{ $max } points ({ $criteria }): a criterion a program passes without doing the task checks nothing the task asks
lab-points-no-criterion = { $file }: [points] "{ $key }" names no criterion the grader defines (on the reference solution)
lab-hint-did-you-mean-criterion = did you mean "{ $near }"? the grader defines: { $criteria }
lab-hint-no-criteria = the grader defines no criterion (lab.criterion(name, points, fn))
lab-hint-criteria = the grader defines: { $criteria }
lab-check-passed = { $lab }: the reference solution gets { $points }/{ $max } points in { $time } simulated s
lab-check-failed = { $lab }: the reference solution gets { $points }/{ $max } points ({ $verdict }): the grader or the reference needs fixing

## Probe (k2::probe, cli::probe): what a K2 answers before the helper is in it

probe-head = probe of { $url }: { $requests } read requests, no writes
probe-serial-answered = serial settings that answered: { $settings }
probe-serial-tried = serial settings tried without an answer: { $settings }
probe-columns = table | FC | area | first | last | units | reads | result
probe-models = models that fit: { $models }
probe-models-none = models that fit: none
probe-verdict = { $ok ->
        [ok] ok
       *[failed] FAILED
    }: { $what }
probe-what-to-do = what to do: { $todo }
probe-result-answers = answers
probe-result-no-end = answers up to the next area: no end found
probe-result-absent = absent (exception 02 at its first address)
probe-result-refused = exception { $code } ({ $name }) at { $address }
probe-result-no-reply = no reply at { $address }
probe-no-answer = the PLC did not answer a read of { $table } { $address }: { $message }
probe-refused = { $table } { $address } ({ $area }, FC { $fc }) was refused with exception { $code } ({ $name })
probe-no-reply = { $table } { $address } ({ $area }, FC { $fc }) got no reply: { $message }
probe-todo-link-again = { $hint }; then probe again
probe-no-model = no catalogue model has these area sizes ({ $sizes })
probe-todo-no-model = connect with the closest model= (plcsh models lists them) and attach this report (--report FILE) when asking: plcsh's catalogue may lack this PLC
probe-models-fit = area sizes fit { $count ->
        [one] model
       *[other] models
    } { $models }
probe-todo-same-areas = these models have the same Modbus areas: give the one on the PLC's label as model=
probe-no-mailbox = V as holding registers does not answer up to register { $register } (VB{ $first } … VB{ $last }, the helper's default mailbox)
probe-todo-mailbox = SM registers and instructions need the helper's mailbox in V: choose a base the PLC answers (plcsh agent il --base VB…)
probe-timed-failed = { $failed } of { $reads } timed reads of { $what } got no reply or an exception
probe-todo-link-slow = { $hint }; a line that loses replies makes every command slow (plcsh retries)
probe-timed = { $reads } reads of { $what }: p50 { $p50 } ms, p99 { $p99 } ms
probe-todo-exception-01 = the port does not take this read function code: check that it is the PLC's Modbus port (PORT1/PORT2 set to Modbus RTU slave in KincoBuilder, or Modbus TCP on a K204ET) and not a programming or free-protocol port
probe-todo-exception-04 = the PLC reports a device failure: check its error LED and diagnostics in KincoBuilder, then probe again
probe-todo-exception-06 = the PLC is busy: probe again; if it stays busy, something else keeps it busy (another master, a download)
probe-todo-gateway = a gateway answered for the PLC: check the gateway's route to the PLC (unit id, serial settings, wiring)
probe-todo-attach = attach this report when asking about it: plcsh probe … --report FILE

## The REPL (shell::repl): its first lines
repl-banner = plcsh { $version } — `help` lists commands, `quit` leaves.
repl-devices = Devices: { $devices }
repl-device-simulated = { $name } ({ $model } simulated)
repl-no-line-editor = cannot start the line editor: { $error }
repl-input-error = input error: { $error }

## Snapshots of the simulated state (shell::commands::snapshot)
snapshot-list-sandboxed = `sim snapshots` lists the user's data directory: not in a sandboxed run
snapshot-hint-sandboxed = a sandboxed run keeps snapshots as files under its write directory
snapshot-none = no saved snapshots (sim snapshot save NAME)
snapshot-columns = snapshot | file
snapshot-one-name = `sim snapshot { $verb }` takes one name or file, not { $count } words
snapshot-hint-quotes = a path with spaces goes in quotes: sim snapshot { $verb } { $path }
snapshot-needs-verb = `sim snapshot` needs save or restore and a name: { $usage }
snapshot-saved = saved { $devices } at { $time } to { $file }
snapshot-restored = restored { $devices } to { $time }
snapshot-unknown = unknown `sim snapshot { $verb }`

## The shell (shell)

shell-unknown-command = unknown command `{ $name }`
shell-hint-did-you-mean = did you mean `{ $name }`? `help` lists the commands
shell-hint-help = `help` lists the commands
shell-hint-subcommand = did you mean `{ $command } { $near }`? `help { $command }` shows its usage

## Servo parameter sets (servo::params, servo params)

servo-params-cannot-read = cannot read { $file }
servo-params-bad-file = { $file } is not a parameter set file: { $reason }
servo-params-other-drive = { $file } holds the parameters of a { $kind } drive and this drive is a { $expected }: a set loads only onto the drive type it was read from
servo-params-unknown-object = { $file } lists parameter { $name } as { $object }/{ $dtype }, which is not a parameter of this drive's object dictionary: the file comes from another drive type or was edited
servo-params-duplicate = { $file } lists parameter { $name } twice
servo-params-out-of-range = { $file }: { $value } is out of range for { $name }
servo-params-unknown-group = unknown parameter group `{ $group }`; the groups are { $groups }
servo-params-read-back = { $name } ({ $object }) reads back { $back } after { $value } was written; the load stopped there
servo-params-stopped = the load stopped at { $name } ({ $object }) after { $written ->
        [one] one write
       *[other] { $written } writes
    }: { $reason }
servo-params-usage = usage: servo params save FILE [group…] | servo params diff FILE [FILE2] | servo params diff --with DRIVE | servo params load FILE [--store]
servo-params-saved = saved { $count ->
        [one] one parameter
       *[other] { $count } parameters
    } to { $file }; { $refused } refused or missing
servo-params-same = no differences
servo-params-loaded = wrote { $written ->
        [one] one parameter
       *[other] { $written } parameters
    }, each read back; { $unchanged } unchanged
servo-params-loaded-stored = wrote { $written ->
        [one] one parameter
       *[other] { $written } parameters
    }, each read back; { $unchanged } unchanged; stored in the drive's memory (2FF0.01 = 1)

## Injected faults of the simulators, shared by the K2, UMPK and FX simulators (core::sim_faults, k2::sim::control)

sim-fault-describe = fault { $id }: { $what } from { $from } s until cleared
sim-fault-describe-until = fault { $id }: { $what } from { $from } s until { $until } s
sim-control-words-hint = control words: { $words }
sim-not-level = `{ $value }` is not a level (1, 0, on, off)
sim-not-option-here = `{ $word }` is not an option here (for=DURATION)
sim-word-takes-nothing = `{ $word }` takes nothing after it (got `{ $rest }`)
sim-no-faults = no injected faults
sim-no-fault-acted = no injected fault has acted
sim-fault-acted = { $seconds } s: fault { $id } ({ $name }) acted
sim-not-fault-id = `{ $text }` is not a fault id
sim-no-such-fault = there is no fault { $id }
sim-no-such-fault-hint = `faults` lists them
sim-faults-cleared = cleared { $n } fault(s)
sim-stuck-needs-input = fault stuck needs an input and a level: stuck IN=1
sim-stuck-shape = `{ $spec }`: write stuck { $spec }=1 or stuck { $spec }=0
sim-not-fault-here = `{ $kind }` is not a fault here (no-reply, stuck)
sim-which-fault = which fault? fault no-reply | fault stuck IN=1

## Files (core::durable)

file-cannot-create = cannot create { $path }
file-cannot-open = cannot open { $path }
file-cannot-write = cannot write { $path }

## Device profiles and fleets (profile, profile::fleet)

profile-cannot-read = cannot read: { $error }
profile-file-not-loaded = { $error } (no profile from this file is loaded)
profile-skipped = profile `{ $name }` skipped: { $reason }
profile-unknown = `{ $name }` is neither a device URL nor a profile
profile-unknown-define-hint = give a URL (sim:MODEL, tcp://HOST:PORT …) or define { $section } in { $file }
profile-unknown-list-hint = profiles in { $file }: { $list }
profile-name-letters = a profile name is Latin letters A-Z a-z, digits, _ and - only (it becomes a device name, typed before operands: press1:VW0)
profile-url-not-string = `url` must be a string
profile-url-missing = `url` is missing (e.g. { $example })
profile-read-only-bool = `read_only` must be true or false
profile-allow-list = `allow` must be a list of operands, e.g. { $example }
profile-option-scalar = option `{ $key }` must be a string, number or boolean
profile-options-table = `options` must be a table
profile-key-scalar = `{ $key }` must be a string, number or boolean
profile-unknown-scheme = unknown device scheme `{ $scheme }:` in { $url }
profile-known-schemes-hint = known schemes: { $list }
profile-allow-item = profile `{ $name }` ({ $origin }): allow item `{ $item }`: { $reason }
profile-allow-item-hint = allow items are operands or ranges of this device, e.g. "VW100..VW120"
# `what` is the instruction or action (`PLS 0`), or `none` for a plain write.
profile-read-only-refused = { $what ->
    [none] write refused: profile `{ $profile }` is read_only ({ $origin })
   *[other] { $what } refused (it changes { $name }): profile `{ $profile }` is read_only ({ $origin })
}
profile-read-only-refused-hint = reading works; to write, remove `read_only = true` from the profile
profile-allow-refused = { $what ->
    [none] write refused: { $name } is not in profile `{ $profile }`'s allow list [{ $list }] ({ $origin })
   *[other] { $what } refused (it changes { $name }): { $name } is not in profile `{ $profile }`'s allow list [{ $list }] ({ $origin })
}
profile-allow-refused-hint = writes are allowed only to the operands listed, with the same size
profile-summary-read-only = read only
profile-summary-allow = allow { $list }
fleet-needs-range = a URL fleet needs one range such as { $example } in its url
fleet-unclosed-brace = `{"{"}` without `{"}"}` in the url
fleet-one-range = only one { $form } range is allowed in a fleet's url
fleet-not-range = `{ $range }` is not a range (write { $form })
fleet-not-number = `{ $text }` in `{ $range }` is not a number
fleet-backwards = the range { $range } runs backwards
fleet-too-many = the range { $range } names { $n } devices; a fleet has at most { $max }
fleet-devices-or-url = give `devices` or `url`, not both
fleet-needs-devices = a fleet needs `{ $devices }` or `{ $url }`
fleet-devices-list = `devices` must be a list of profile names or URLs
fleet-devices-empty = `devices` is empty
fleet-devices-rules = `{ $key }`: a `devices` fleet takes its rules from each profile
fleet-listed-twice = `{ $name }` is listed twice
fleet-lists-unknown = fleet `{ $name }` ({ $origin }) lists `{ $profile }`, which is no loaded profile
fleet-unknown = no fleet named `{ $name }`
fleet-unknown-define-hint = define { $section } with { $devices } or { $url } in { $file }
fleet-unknown-list-hint = fleets in { $file }: { $list }
fleet-name-letters = a fleet name is Latin letters A-Z a-z, digits, _ and - only
fleet-skipped = fleet `{ $name }` skipped: { $reason }

## Device URLs and files (schemes, paths, pending)

schemes-known-hint = known schemes: sim:MODEL, tcp://HOST:PORT, rtu:PORT, kinco:PORT?id=1, sim-servo:?id=1, fx:PORT, fxlink:PORT, sim-fx:FX2N, umpk:PORT, sim-umpk:UMPK16 (PORT: COM3, /dev/ttyUSB0; a serial device server: rtu+tcp://HOST:PORT, kinco+rfc2217://HOST:PORT, …)
pending-not-connected = cannot read `{ $operand }` yet: the device is not connected
pending-not-connected-hint = check the link (`plcsh ports`, the cable, the power); the next command tries to connect again

## Device URLs, text files, options (core::url, core::encoding, core::device, core::signal)

url-not-url = `{ $text }` is not a device URL
url-not-url-hint = use sim:MODEL, tcp://HOST:PORT?unit=1, { $rtu }, rtu+tcp://HOST:PORT, { $kinco } or sim-servo:?id=1
url-param-too-large = `{ $param }` in { $url } is too large: at most { $max }
url-param-not-number = `{ $param }` in { $url } is not a whole number
url-unknown-param = unknown parameter `{ $key }` in { $url }
url-known-params-hint = known: { $list }
# What a UTF-16 text file is, named in the two messages after it.
encoding-utf16-kind = { $kind ->
    [bom-le] UTF-16 text (byte-order mark FF FE)
    [bom-be] UTF-16 text (byte-order mark FE FF)
    [le] UTF-16 little-endian text without a byte-order mark (a NUL after each ASCII character)
   *[be] UTF-16 big-endian text without a byte-order mark (a NUL before each ASCII character)
}
encoding-utf16-odd = { $what } ends in the middle of a character at byte { $byte } (save the file as UTF-8)
encoding-utf16-surrogate = { $what }: invalid UTF-16 at byte { $byte }: lone surrogate { $surrogate } (save the file as UTF-8)
device-no-option = { $family } devices have no option `{ $key }`
signal-freq-positive = pulse frequency { $freq } Hz must be positive
