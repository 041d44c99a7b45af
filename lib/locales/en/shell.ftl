# plcsh messages (en): shell — the commands and options of the shell and the command line. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## The command line's own errors (cli::clap_error): what clap found, in clap's layout

# The first line of a command-line error.
cli-error = error: { $message }
cli-error-unknown-argument = unexpected argument '{ $arg }' found
cli-error-unknown-subcommand = unrecognized subcommand '{ $subcommand }'
cli-error-invalid-value = invalid value '{ $value }' for '{ $arg }'
cli-error-value-missing = a value is required for '{ $arg }' but none was supplied
# Under an invalid value: the values the option takes.
cli-error-possible-values = [possible values: { $values }]
# A value the option's parser refused, with its reason.
cli-error-value-refused = invalid value '{ $value }' for '{ $arg }': { $reason }
cli-error-no-equals = equal sign is needed when assigning values to '{ $arg }'
cli-error-too-many-values = unexpected value '{ $value }' for '{ $arg }' found; no more were expected
cli-error-too-few-values = { $min } values required by '{ $arg }'; only { $given } { $given ->
    [one] was
   *[other] were
} provided
cli-error-wrong-number-of-values = { $expected } values required for '{ $arg }' but { $given } { $given ->
    [one] was
   *[other] were
} provided
# Followed by the missing arguments, one a line.
cli-error-missing-arguments = the following required { $count ->
    [one] argument was
   *[other] arguments were
} not provided:
cli-error-missing-subcommand = '{ $command }' requires a subcommand but one was not provided
cli-error-subcommands = [subcommands: { $values }]
cli-error-used-twice = the argument '{ $arg }' cannot be used multiple times
cli-error-conflict = the argument '{ $arg }' cannot be used with { $other }
cli-error-conflict-others = the argument '{ $arg }' cannot be used with one or more of the other specified arguments
cli-error-invalid-utf8 = invalid UTF-8 was found in one or more arguments
# "Did you mean": the names clap found close to what was typed.
cli-error-similar-subcommand = tip: { $count ->
    [one] a similar subcommand exists
   *[other] some similar subcommands exist
}: { $names }
cli-error-similar-argument = tip: { $count ->
    [one] a similar argument exists
   *[other] some similar arguments exist
}: { $names }
cli-error-similar-value = tip: { $count ->
    [one] a similar value exists
   *[other] some similar values exist
}: { $names }
cli-error-pass-as-value = tip: to pass '{ $arg }' as a value, use '{ $example }'
cli-error-remove-dashes = tip: subcommand '{ $subcommand }' exists; to use it, remove the '--' before it
cli-error-tip = tip: { $tip }
cli-error-more = For more information, try '{ $help }'.
# plcsh's own answer to a subcommand the command line does not have (`plcsh agent status`).
cli-no-such-subcommand = plcsh: `{ $command }` has no subcommand `{ $subcommand }`; its subcommands: { $subcommands }
cli-help-describes-each = `{ $command } --help` describes each

## The subcommands' own subcommands and options (`plcsh sim serve --help`; cli::localise)

# The labels after an option's text in --help: its default, the values it takes.
cli-default = [default: { $value }]
cli-possible-values = [possible values: { $values }]
# The `help` subcommand clap adds (`plcsh help sim`).
cli-help-subcommand = Print this message or the help of the given subcommand(s)
cli-models-name = One model (a unique prefix is enough: K209EA)
cli-completions-shell = The shell to print the script for
cli-completions-write = Write every script into DIR (plcsh.bash, _plcsh, plcsh.fish, _plcsh.ps1)
cli-sim-serve = Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP
cli-sim-serve-tcp = Modbus TCP on ADDR (`127.0.0.1:5020`, `5020`, `0` for a free port; loopback unless a host is given)
cli-sim-serve-rtu-pty = Modbus RTU on a new pseudo-terminal, with a symlink to its device at LINK
cli-sim-serve-rtu-tcp = Modbus RTU frames over TCP on ADDR (as a serial-to-Ethernet gateway carries them)
cli-sim-serve-unit = Modbus unit id (slave address) the K2 answers to; requests for other ids get no reply
cli-sim-serve-agent = Run the PLC-side helper program (lib/k2_agent.il) with its mailbox at this V address
cli-sim-serve-program = Run this IL program in the served K2 (docs/il.md); load errors stop the server
cli-sim-serve-servo-pty = Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it
cli-sim-serve-servo-tcp = Serve simulated Kinco servo drives on a TCP port, as a serial device server would (kinco+tcp://ADDR)
cli-sim-serve-servo-control = The served drive line's control channel at PATH (default: LINK.ctl beside --servo-pty's link); clients name it with `control=PATH` (e.g. `kinco+tcp://ADDR?control=PATH`)
cli-sim-serve-servo-id = Drive ids on the servo line (several drives share it)
cli-sim-serve-servo-loop = RS232 loop mode: echo every request before the reply (connect with echo=1)
cli-sim-serve-servo-baud = Line timing: replies take the frame time at this baud rate (10 bits a byte)
cli-sim-serve-servo-latency = Line timing: the drive's think-time before it answers (e.g. 1ms, 0)
cli-sim-serve-servo-instant = Answer at once instead of at line speed (benchmarks, CI)
cli-sim-serve-servo-strict = Refuse writes whose size code differs from the object's (abort 0x06070010)
cli-sim-serve-fx-pty = Serve a simulated FX PLC's programming port on a new pseudo-terminal (symlink at LINK)
cli-sim-serve-fx-tcp = Serve the simulated FX PLC's programming port on a TCP port (fx+tcp://ADDR)
cli-sim-serve-fx-link-pty = Serve the same FX PLC's computer link (format 1, sum check on) on another pseudo-terminal
cli-sim-serve-fx-link-tcp = Serve the same FX PLC's computer link on a TCP port (fxlink+tcp://ADDR)
cli-sim-serve-fx-model = The simulated FX PLC's model (FX1S, FX1N, FX2N, FX3U; FX2NC and FX3UC name the FX2N and FX3U)
cli-sim-serve-fx-station = The computer link's station number (0–31)
cli-sim-serve-fx-program = An FX instruction list the simulated FX PLC runs (docs/il.md, "The FX family")
cli-sim-serve-umpk-pty = Serve a simulated UMPK teaching PLC on a new pseudo-terminal; LINK becomes a symlink to it
cli-sim-serve-umpk-tcp = Serve a simulated UMPK teaching PLC on a TCP port (umpk+tcp://ADDR)
cli-sim-serve-umpk-model = The simulated UMPK's model (UMPK8 or UMPK16)
cli-sim-serve-umpk-status-bits = Bit numbers of W,H,R,E,P,T in the UMPK's status word
cli-sim-serve-umpk-flash-fail = Make the simulated UMPK's flash write fail on this 64-byte page (programming gets `W`): 0–31 on the UMPK8, 0–47 on the UMPK16
cli-sim-serve-umpk-state = Where the simulated UMPK keeps its flash, program info and error history (default: one file per model and link in the user's data directory; `none` keeps nothing)
cli-sim-serve-umpk-program = An IL lab program the simulated UMPK runs each 10 ms cycle (docs/il.md, "The UMPK family")
cli-sim-serve-fx-control = The served FX PLC's control channel at PATH (default: LINK.ctl beside --fx-pty's link): X inputs switched, a silent line, stuck inputs while clients use its ports
cli-sim-serve-umpk-control = The served UMPK's control channel at PATH (default: LINK.ctl beside --umpk-pty's link): inputs, square waves and faults while the lab's software uses the line
cli-sim-serve-k2-control = The served K2's control channel at PATH (default: LINK.ctl beside --rtu-pty's link): faults added, listed and cleared and the fault event log read while clients poll (`plcsh sim control PATH …`, or `control=PATH` in the client's URL)
cli-sim-serve-fault = Inject a fault into the served K2, e.g. `--fault "no-reply on VW100 after=2s times=1"` (repeatable; see `help sim`)
cli-sim-serve-max-connections = Network connections served at once (per transport); more are closed on accept
cli-sim-serve-idle-timeout = Close a network connection that sends nothing for this long (`300s`, `2m`, `500ms`)
cli-sim-serve-strict-unit = On Modbus TCP, answer only the --unit id (by default unit 0xFF is this device too, as libmodbus does)
cli-sim-serve-fleet = Serve N simulated K2s, each with its own memory, on N TCP ports (with --tcp: port 0 gives each a free port, port P gives P, P+1, …); the readiness line lists them under `fleet` (docs/fleets.md)
cli-sim-serve-rfc2217 = The serial options' TCP ports (--rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp, --umpk-tcp) speak RFC 2217 (Telnet COM-PORT-OPTION) instead of raw TCP: for FAMILY+rfc2217:// and virtual COM port drivers
cli-sim-control = Send one line to a served simulator's control channel (faults, events) and print the reply
cli-sim-control-path = The control channel (the `k2_control`, `umpk_control` or `servo_control` of the server's readiness line)
cli-sim-control-words = The control line, e.g. `fault no-reply times=2`, `faults`, `events`, `fault clear`
cli-agent-il = Print the helper program (K2 instruction list) for KincoBuilder
cli-agent-il-model = The PLC's model: the helper runs only the pulse outputs, counters and counter modes this model has (default: the default simulated model)
cli-agent-il-base = Mailbox base: an even V byte address below the E2PROM area (VB3648)
cli-agent-check = Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)
cli-agent-check-url = The PLC: tcp://HOST:PORT?agent=VB3400, rtu:PORT?…, or a profile name (agent=VB3400 when the URL has none)
cli-probe-url = The PLC: tcp://HOST:PORT, rtu:PORT?baud=…, rtu+tcp://HOST:PORT, or a profile name
cli-probe-report = Also write the findings as a Markdown report to FILE
cli-probe-reads = Reads timed for the response time (p50, p99)
cli-probe-scan-serial = On a serial line that does not answer, try the common settings (9600…115200 baud, no, even or odd parity) and say which one answered
cli-run-sandbox = Run a script someone else wrote: no os.execute, io.popen, os.remove/rename/exit, C libraries or debug library; files written only under --write-dir
cli-run-write-dir = With --sandbox: the directory the script may write files in (none without it)
cli-run-fleet = Run the script on every device of this fleet at once, each in a Lua state of its own (docs/fleets.md)
cli-run-report = Write a commissioning report: this HTML file and its JSON twin beside it (docs/commissioning.md). The commission runner writes its checklist there; any other script gets the devices and the log of every write it made
cli-run-script = The Lua script
cli-run-args = Arguments for the script (`arg[1]`…, and `...`): everything after the script, even words that look like plcsh flags. Flags for plcsh go before the script
cli-record-show = Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame
cli-record-file = The file written by --record
cli-replay-sim-model = Simulate this K2 model instead of the one each recorded link names
cli-replay-snapshot = Start the simulated K2 from this snapshot (a file, or a name saved with `sim snapshot save`)
cli-replay-agent = Run the PLC-side helper (lib/k2_agent.il) with its mailbox at this V address. Without it, the helper runs when the recording shows its status block being read
cli-publish-broker = The broker: mqtt://HOST:PORT, or mqtts://HOST:PORT for TLS (default: `url` in the profile file's [mqtt])
cli-publish-fleet = Publish every member of this fleet (default: the current device)
cli-publish-every = How often each device is read
cli-publish-qos = MQTT quality of service for values: 0 (at most once) or 1 (at least once)
cli-publish-on-change = Publish a value only when it changed (by more than --deadband); otherwise every poll
cli-publish-deadband = With --on-change: the smallest change published (in the operand's units)
cli-publish-buffer = Readings queued for the broker at most: while it is away the oldest beyond it are dropped; while it is connected but plcsh falls behind, the newest value of a topic replaces the queued one (both counted)
cli-publish-mqtt-version = MQTT protocol version
cli-publish-count = Stop after this many polls of each device (default: until Ctrl-C)
cli-publish-client-id = The MQTT client id (default: plcsh-GROUP-PID)
cli-publish-accept-writes = Take writes from the broker on plcsh/GROUP/DEVICE/set, only to operands on the device profile's allow list (replies on plcsh/GROUP/DEVICE/reply); read-only profiles never accept one
cli-publish-shard = Publish this part of the fleet only (K of N publishers; default: `shard` in the profile file's [mqtt])
cli-publish-operands = The operands to publish (ranges allowed: VW100..VW110)
cli-tags-file = The tag file to list (CSV, TOML `[tags]`, or IEC `VAR_GLOBAL` declarations)
cli-tags-model = The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2's)
cli-tags-format = Read the file as this format instead of telling it by its name and text
cli-tags-check = Check a tag file: one line per problem with file:line:column; exit status 1 when there is any
cli-tags-export = Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output
cli-tags-export-to = The form to write
cli-tags-export-output = Write here instead of standard output (replaced whole, atomically)

## Progress lines and notes on standard error (shell, cli, signals)

# `-v`: how many requests a command sent.
shell-requests-on-wire = { $command }: { $count } request(s) on the wire
# `trace`'s progress line: how many samples so far.
shell-samples = { $count } samples
# `-v` after `watch` and `trace` (times in seconds, rates in Hz, as numbers with their decimals).
shell-sample-report = { $command }: { $samples } samples over { $clock } s of clock time ({ $clock_rate } Hz; asked { $asked_rate } Hz), { $wall } s wall ({ $wall_rate } Hz), { $requests } requests{ $interrupted ->
    [yes] , interrupted
   *[no] { "" }
}
# `umpk program`'s progress line (Intel HEX records sent of all).
shell-umpk-programming = programming { $bar } record { $record }/{ $records }
# A device given with --device that does not answer when the shell starts.
shell-not-connected-yet = plcsh: { $device }: { $reason } — not connected; the next command tries again
# A second interactive shell on the same state file.
shell-state-taken = plcsh: warning: { $reason }: this shell's plc starts fresh and keeps nothing (as with --state none); to keep its own, start it with --state FILE
shell-stop-overdue = plcsh: stopped: the stop did not finish within { $seconds } s (abort handlers still running?)

## Usage errors of the shell's lines (shell::lex, shell::commands::forms)

shell-hint-close-quote = close the quote; inside double quotes write \" for a quote and \\ for a backslash, or use single quotes
shell-hint-one-file = one file only: { $line }
shell-hint-quote-path = a path with spaces goes in quotes: { $line }
shell-one-file-only = { $form } takes one file, not { $count } words (`{ $words }`)
# Commands of the command line typed in the shell: where they belong.
shell-cli-only-run = `run` is a command-line command: plcsh run SCRIPT.lua [ARGS…]; in the shell, lua dofile("SCRIPT.lua")
shell-cli-only-replay = `replay` is a command-line command: plcsh replay FILE.pcapng (it builds its own simulators)
shell-cli-only-record = `record` is a command-line command: plcsh record show FILE.pcapng; to record this session start plcsh with --record FILE
shell-cli-only-completions = `completions` is a command-line command: plcsh completions bash|zsh|fish|powershell
shell-cli-only-serve = serving is a command-line command: plcsh sim serve --tcp 5020 …
shell-no-options = `{ $forms }` takes no options (got `{ $key }=`)
shell-hint-the-form = the form is { $forms }; `help { $command }` shows every form
shell-hint-nothing-after-files = nothing goes after the { $files ->
    [one] file
   *[other] files
}; `{ $help }` shows every form
shell-hint-quote-name = a path or name with spaces goes in quotes: { $line }
shell-unexpected-after = unexpected `{ $extra }` after `{ $typed }`: the form is { $forms }
shell-hint-number-and-unit = a number and its unit are one word: { $line }
shell-no-arguments = unexpected `{ $extra }`: `{ $command }` takes no arguments
shell-hint-nothing-after = nothing goes after it; `{ $help }` shows every form

## Operands, options and devices of a command (shell::commands::io, shell::sample, session, guard)

shell-needs-operand = { $command } needs at least one operand
shell-set-needs-items = set needs OPERAND=VALUE items
shell-set-not-item = `{ $item }` is not OPERAND=VALUE
shell-set-st-assignment = `:=` is the ST assignment; plcsh writes `{ $operand }={ $value }`
shell-set-commas = writes are separated by commas: `set { $line }`
shell-option-positive = { $key } must be more than zero
shell-name-an-operand = name at least one operand
shell-count-not-number = count={ $value } is not a number
shell-count-at-least-one = count must be at least 1
shell-unknown-option = unknown option `{ $key }`
shell-hint-options = options: { $options }; { $usage }
shell-not-traced = `{ $name }` is not in the last trace
shell-hint-traced = traced: { $names }
session-bad-device-name = `{ $name }` is not a device name: Latin letters A-Z a-z, digits, _ and - only
session-hint-device-name = e.g. connect press1 sim:K209EA-50DX (the name is typed before operands: press1:VW0)
session-sandbox-real-profile = `{ $url }` is a profile of a real device: a sandboxed run opens simulated devices only
session-sandbox-not-url = `{ $url }` is not a device URL: a sandboxed run opens simulated devices by URL only
# The cause under an error of a device opened from a profile (its name and where it was read).
session-from-profile = from profile `{ $profile }` ({ $origin })
session-no-device-named = no device named `{ $name }`
session-hint-none-open = no device is open; add one with --device NAME=URL
session-hint-open-devices = open devices: { $names }
session-none-open = no device is open
session-hint-add-device = add one with --device NAME=URL or `connect NAME URL`
guard-read-only-action = { $action } refused (it changes { $name }): the session is read-only (--read-only)
guard-read-only-write = write refused: the session is read-only (--read-only)
guard-hint-read-only = reading works; start plcsh without --read-only to write
cli-config-missing = --config { $file }: no such file
cli-hint-config-missing = give an existing devices.toml, or leave --config out to use the default
cli-fleet-needs-work = --fleet runs -c COMMANDS or run SCRIPT.lua on every device of the fleet
cli-hint-fleet-needs-work = e.g. plcsh -f { $fleet } -c 'get VW100', or plcsh run --fleet { $fleet } check.lua
# A mark in the prompt (`press(not connected)> `): the device has not answered yet.
shell-prompt-not-connected = not connected
# What a completion means, beside it in the completion menu.
shell-complete-operating-mode = operating mode
shell-complete-open-device = open device ({ $profile }); connect NAME URL replaces it

## The K2 commands' channels, options and events (shell::commands::k2cmd, events, trend, models, …)

# `what`: `pulse` (a pulse output's channel) or `counter` (a high-speed counter).
shell-not-a-channel = `{ $num }` is not a { $what ->
    [counter] counter
   *[pulse] pulse channel
} number (0…{ $max })
shell-status-needs-channel = a status form needs a { $what ->
    [counter] counter
   *[pulse] pulse channel
} number, e.g. { $example }
shell-unexpected = unexpected `{ $extra }`
shell-not-a-k2 = { $name } is not a K2 PLC
shell-simulator-only = { $command } is a simulator control; { $name } is not simulated
shell-unknown-key = unknown option `{ $key }=`
shell-hint-option-near = did you mean `{ $near }=`? options: { $options }; usage: { $usage }
shell-hint-option-usage = options: { $options }; usage: { $usage }
shell-cannot-write = cannot write { $file }: { $reason }
shell-plot-not-a-size = { $key }={ $value } is not a size (2…1000 characters)
shell-plot-nothing = nothing to plot yet
shell-hint-plot-nothing = record first, e.g. trace SMD72 every=10ms for=2s
shell-no-events = no events
shell-wait-needs-event = wait needs `event N`
# What `wait event N` waited for: the event's number, name and meaning, when it came, how long the wait took.
shell-wait-event-number = event { $number } { $name } ({ $what }) at { $at } after waiting { $waited }
shell-wait-event = { $name } ({ $what }) at { $at } after waiting { $waited }
shell-wait-interrupted = wait for { $event } interrupted
shell-wait-timeout = no { $event } within { $timeout }
shell-hint-wait-timeout = `events keep` lists what arrived; `pto N status` / `hsc N status` show whether anything runs
shell-ports-no-arguments = ports takes no arguments (got `{ $extra }`)
shell-no-ports = no serial ports found (plug in the USB adapter, then run `ports` again)
shell-lua-cannot-run = Lua cannot run here
shell-hint-lua-nested = a `lua` line inside a running Lua chunk (plcsh.exec) is not allowed; call Lua directly instead
shell-hint-fault-served = a served K2 takes faults on its control channel: open it with control=PATH (the server's readiness line names it)
shell-agent-il-cli = `agent il` is a command-line command: it prints the helper program for KincoBuilder
shell-hint-agent-il-cli = plcsh agent il > k2_agent.il (see plcsh agent il --help)
shell-agent-simulator = simulator: SM registers and instructions are reached directly (no helper needed)
shell-wire-needs-ends = sim wire needs FROM -> TO
shell-nothing-wired = nothing is wired
shell-unwire-needs-terminal = sim unwire needs a terminal or `all`
shell-watch-cannot-write = cannot write the watch output: { $reason }
# The columns of `models` (`|` between them).
shell-models-columns = model | DI/DO/DIO | AI/AO | HSC | pulse outputs | manual notes
shell-models-footer = `models MODEL` shows one model in full (areas, counters, manual notes)
shell-models-no-pulses = none (relay outputs)
# A pulse output of a model: its output and its highest frequency.
shell-models-pto = { $output } up to { $khz } kHz

## Pulse outputs: PLS, PTO, PWM and profiles (shell::commands::pulse; K2 manual §3.4)

shell-pulse-channel-missing = a pulse channel number is missing: { $usage }
shell-pulse-one-channel = { $command } takes one channel number
# `busy`: what runs on the channel now (a sentence of the K2 helpers); `by`: PLS, PTO, PWM.
shell-pulse-busy-strict = { $busy }: { $by } { $channel } would replace it; nothing was written
shell-hint-pulse-busy = wait for it (pto { $channel } status), stop it (pstop { $channel }), or drop `strict` to replace it
shell-pulse-busy-replaced = { $busy }; { $by } { $channel } replaced it (add `strict` to refuse instead)
shell-freq-or-cycle = give freq= or cycle=, not both
shell-too-many-pulses = { $key }={ $value } is too many pulses: a PTO counts up to 4 294 967 295 (§3.4.2.1)
shell-pulses-not-whole = { $key } must be a positive whole number of pulses, 1 … 4 294 967 295 (got { $key }={ $value })
shell-pto-needs-rate = pto needs freq= or cycle=
shell-pto-needs-count = pto needs count=
shell-pwm-needs-cycle = pwm needs cycle= (or freq=)
shell-pwm-needs-width = pwm needs width=
shell-pwm-negative-width = the width cannot be negative
shell-segments-in-brackets = the segment list goes in brackets: [(cycle=500us, count=1000), …]
shell-not-a-segment = `{ $text }` is not a segment: write (cycle=500us, count=1000)
shell-unexpected-in-segment = unexpected `{ $extra }` in a segment
shell-segment-needs-rate = a segment needs cycle= or freq=
shell-segment-needs-count = a segment needs count=
shell-at-needs-address = `at` needs a V address, e.g. at VB3001
shell-not-a-v-byte = `{ $text }` is not a V byte address (e.g. { $example })
shell-profile-needs-at = profile needs `at VBxxxx` (an odd V address)
shell-profile-needs-segments = profile needs a segment list [(cycle=…, count=…), …]
# The name of the frequency curve in `profile … plan`'s picture.
shell-profile-series = PTO{ $channel } frequency
shell-profile-plan-title = PTO{ $channel } profile plan: { $pulses } pulses, { $segments } segments
# One segment of `profile … plan` (times in seconds, frequency in Hz, as numbers with their decimals).
shell-profile-plan-segment = segment { $segment }: { $from }–{ $to } s  { $hz } Hz  { $pulses } pulses
shell-profile-plan-total = total: { $pulses } pulses in { $seconds } s; nothing was written (drop `plan` to run it)

## High-speed counters and the E2PROM backup area (shell::commands::counter, eeprom; K2 manual §3.3, §2.2.8)

# `what`: `mode` (a counter mode), `cv` (a current value) or `pv` (a preset value).
shell-hsc-not-a-number = `{ $text }` is not { $what ->
    [mode] a mode number
    [cv] a DINT current value
   *[pv] a DINT preset value
}
shell-hdef-needs-two = hdef takes a counter and a mode
shell-hsc-needs-counter = hsc needs a counter number
shell-hsc-needs-mode = the hsc helper needs mode=
shell-hsc-dir = dir={ $value }: use up or down
shell-hsc-level = { $key }={ $value }: the active level is high or low
shell-at-needs-v-address = `at` needs a V address
shell-eeprom-saved = saved VB{ $first }…VB{ $last } ({ $bytes } bytes) to { $file }
shell-cannot-read = cannot read { $file }
shell-eeprom-too-big = { $file } holds { $bytes } bytes but the backup area VB{ $first }…VB{ $last } has { $room }
shell-hint-eeprom-area = extend the area first: eeprom area 4095
shell-eeprom-restored = restored { $bytes } bytes into VB{ $first }…VB{ $last } from { $file }
shell-eeprom-area-size = backup area VB{ $first }…VB{ $last } ({ $bytes } bytes)
# The byte of the backup area written most, against the E2PROM's endurance (write cycles).
shell-eeprom-hottest = most-written byte VB{ $byte }: { $writes } writes ({ $share } % of ~{ $endurance })
shell-eeprom-wear = at this session's rate ({ $rate } writes/s of virtual time) it wears out in { $left }
shell-eeprom-wear-warning = this would wear the E2PROM within 10 years; keep frequently changing data out of the backup area (§2.2.8)
shell-eeprom-no-writes = no writes counted
shell-eeprom-area = backup area VB{ $first }…VB{ $last }
shell-one-file-only-plain = { $form } takes one file, not { $count } words
shell-eeprom-unknown = unknown eeprom command

## The simulator's clock, inputs and retained ranges (shell::commands::sim, siminputs)

shell-sim-step-form = sim step DURATION (e.g. sim step 1s, sim step 500ms)
shell-unexpected-after-sim = unexpected `{ $extra }` after `sim { $sub }`
shell-sim-step-needs-duration = sim step needs a duration, e.g. sim step 500ms
shell-sim-time-forward = time only moves forward
shell-sim-step-too-far = sim step { $step } would take the simulated clock past { $latest } s (about 584 years), the latest time it counts
shell-sim-clock-graded = `sim clock real` is not available in a graded run: its clock is simulated
shell-hint-sim-clock-graded = wait with sim step DURATION or plcsh.sleep(ms)
shell-sim-not-clock-mode = `{ $mode }` is not a clock mode
shell-hint-sim-clock-modes = sim clock real (follow the wall clock) | sim clock stepped (move only with sim step)
shell-sim-run-ambiguous = `sim run` is ambiguous: say which runs
# Within 80 columns after `  hint: `.
shell-hint-sim-run-ambiguous = sim clock real: time follows the clock; sim cpu run: the program runs
shell-sim-cli-only = `sim { $sub }` is a command-line command, not a shell command
shell-hint-sim-cli-only = in another terminal: plcsh sim { $sub } … (plcsh sim { $sub } --help lists its options)
shell-hint-fault-clear = sim fault clear (every fault) | sim fault clear 2 (fault 2; `sim faults` lists the ids)
shell-not-a-fault-id = `{ $id }` is not a fault id: the form is { $form }
shell-sim-unknown = unknown `sim { $sub }`
# `sim time`: the simulator's time and how it moves.
shell-sim-time = simulator time { $time } ({ $mode ->
    [stepped] stepped
   *[wall] following the wall clock
})
shell-not-an-input-bit = `{ $text }` is not an input bit (e.g. I0.1)
shell-signal-needs-freq = a signal needs freq=, e.g. freq=1kHz
shell-signal-freq = freq={ $value }: whole Hz up to 10 MHz
shell-sim-inputs-alone = sim inputs takes nothing after it (got `{ $extra }`)
shell-no-input-signals = no simulated input signals
shell-retain-none-alone = `sim retain none` stands alone (got `{ $extra }` beside it)
shell-hint-retain-forms = sim retain none (retain nothing) | sim retain VB0..VB99 MB0[8] (these ranges)
shell-no-retained = no retained ranges
shell-retained = retained: { $ranges }
shell-signal-stopped = stopped: { $signal }
shell-no-direction-input = { $input } has no direction input: dir= applies to I0.1 (direction I0.5) and I0.3 (direction I0.2)
# Added after the signal started by `sim input … dir=`: the direction input set.
shell-direction-input = ; direction input { $input } = { $value }
shell-quad-needs-two = sim quad needs two inputs: A (leading) and B
shell-quad-same-input = A and B must be different inputs
shell-quad-dir = dir={ $value }: use up (A leads) or down (B leads)

## Lists: devices, paths, ports; the command line's run, completions and man (shell::commands, cli)

# The `writes` column of `devices` for a read-only profile or fleet.
shell-devices-read-only = read only
# The `writes` column of a fleet whose members have profiles of their own.
shell-devices-per-profile = per profile
shell-devices-count = { $count } { $count ->
    [one] device
   *[other] devices
}
shell-devices-profile-problem = profile file: { $problem }
# The columns of `paths` (`|` between them).
shell-paths-columns = file | path | set by
# The columns of `ports` (`|` between them).
shell-ports-columns = port | kind | usb id | adapter | serial number
cli-run-no-lua = cannot start Lua: { $reason }
cli-run-no-sandbox = cannot set up the sandbox: { $reason }
cli-completions-cannot-write = plcsh: cannot write completions into { $dir }: { $reason }
cli-completions-name-a-shell = plcsh completions: name a shell (bash, zsh, fish, powershell) or give --write DIR
cli-completions-wrote = wrote { $file }
# The manual's name in the page's header (`plcsh man`).
cli-man-manual = plcsh manual

## The simulated CPU: programs, scans, breakpoints; the FX simulator (shell::commands::simprogram, fxsim)

shell-sim-no-program = { $name }: no program loaded (sim program load FILE.il)
# The simulated K2's CPU mode (RUN, STOP, PAUSE) and its RUN/STOP switch.
shell-sim-cpu = { $name }: CPU { $mode }{ $switch ->
    [stop] { " " }(switch at STOP)
   *[run] { "" }
}
shell-sim-loaded = { $what ->
    [helper] helper
   *[program] program
}: { $source } ({ $instructions } instructions)
# Scan counts and times of the simulated K2 (SMW22/24/26: K2 manual §3.4.2.3).
shell-sim-scans = scans { $scans }; scan time last { $last } ms, min { $min } ms, max { $max } ms (SMW22/24/26); { $instructions } instructions in the last scan; { $interrupts } interrupt routines run
shell-sim-costs = watchdog { $watchdog } ms, minimum scan { $min_scan } ms, overhead { $overhead } ms
shell-sim-stopped-by-program = stopped by the program's STOP instruction (sim cpu run restarts it)
shell-sim-fault = fault at { $at } s: { $fault }
# The K2's Err LED after normal (non-fatal) errors: how many, and the last one.
shell-sim-err-led = Err LED on: { $count } normal { $count ->
    [one] error
   *[other] errors
} (the CPU continues); last at { $at } s: { $error }
shell-sim-cpu-needs-mode = sim cpu needs run, stop or pause
shell-sim-load-needs-file = sim program load needs a file, e.g. { $example }
shell-cannot-read-because = cannot read { $file }: { $reason }
shell-sim-stop-values = STOP values: { $values }
shell-sim-program-unknown = unknown `sim program { $sub }`
shell-sim-switch-form = sim switch run|stop (the simulated RUN/STOP switch)
shell-sim-scan-count = sim scan N: N is a number of scans 1…10000000, not `{ $text }`
shell-sim-no-breakpoints = no breakpoints
shell-sim-breakpoints = { $count ->
   *[other] breakpoints at lines
} { $lines }
shell-sim-breakpoints-cleared = breakpoints cleared
shell-sim-stepi-count = sim stepi N: N is 1…100000, not `{ $text }`
shell-fx-program = { $name }: { $model } { $mode }; program { $program } ({ $instructions } instructions)
shell-fx-no-program = { $name }: { $model } { $mode }; no program (sim program load FILE.il)
# Scan counts and times of the simulated FX PLC (D8010/D8011/D8012).
shell-fx-scans = scans { $scans }; scan time last { $last } ms, min { $min } ms, max { $max } ms (D8010/D8011/D8012); time { $time } s
shell-fx-fault = stopped by a fault: { $fault }
shell-fx-not-simulator = not an FX simulator
shell-fx-real = a real FX runs its own program
shell-fx-loaded = { $file }: { $instructions } instructions loaded; the PLC restarts in RUN
shell-fx-unloaded = program removed: the PLC scans an empty program
shell-fx-program-unknown = unknown `sim program { $sub }` on an FX PLC
shell-fx-no-pause = an FX PLC has RUN and STOP, no PAUSE
shell-fx-cpu-needs-mode = sim cpu needs run or stop
shell-fx-mode = { $model } in { $mode }
shell-fx-sim-unavailable = `sim { $sub }` is not available on an FX PLC

## The UMPK teaching PLC (shell::commands::umpk; UMPK8/16 manual)

shell-umpk-not-umpk = `{ $name }` is not a UMPK
shell-umpk-none-open = no UMPK is open
# `port`: this system's word for a serial port (/dev/ttyUSB0, COM3).
shell-hint-umpk-open = open one with --device lab=umpk:{ $port } or connect lab sim-umpk:UMPK16
shell-umpk-several = several UMPKs are open; name one (umpk NAME info)
shell-umpk-needs-subcommand = umpk needs a subcommand
shell-umpk-program-info-none = program info (22 spaces: no program, Wait mode)
shell-umpk-program-info = program info "{ $info }"
# `umpk timing`: the longest cycle and its parts (manual: T = (LLMM − HHKK) × 0.271 µs).
shell-umpk-timing = longest cycle { $total } µs, firmware { $firmware } µs, program { $program } µs (T = (LLMM − HHKK) × 0.271 µs; HHKK={ $hhkk } LLMM={ $llmm })
shell-umpk-reset = reset: the controller restarted (R received; echo is on)
shell-umpk-unknown = unknown `umpk { $sub }`
shell-umpk-real-program = a real UMPK runs only what is programmed into it (umpk program FILE.hex); IL programs run in the simulator
shell-umpk-il-loaded = { $file }: { $instructions } instructions loaded; runs every { $cycle } ms cycle in Work mode
shell-umpk-sim-program-unknown = unknown `sim program { $sub }` on a UMPK
shell-hint-umpk-sim-program = sim program load FILE.il | sim program
shell-umpk-program-mode = program: { $program }; mode { $mode }
shell-umpk-info-columns = field | value
# The rows of `umpk info`, in this order (`|` between them).
shell-umpk-info-fields = model | firmware | inputs / outputs | mode | status word | microcode | echo | program (simulator)
shell-umpk-no-flag = no flag set
# The UMPK's mode as its manual names it (§3.2).
shell-umpk-mode = { $mode ->
    [Programming] Programming
    [Work] Work
   *[Wait] Wait
}
shell-umpk-errors-cleared = error history cleared
shell-umpk-errors-empty = the error history is empty
shell-umpk-errors-columns = # | code | meaning (newest first; 1–127 user, 128–255 system)
shell-umpk-send-needs = umpk send needs a command or record, e.g. umpk send ?03FD
shell-umpk-sim-needs-simulator = umpk sim works on a simulated UMPK: in-process (sim-umpk:UMPK16), or served by plcsh sim serve --umpk-pty LINK and opened with control=LINK.ctl; a real UMPK's inputs are wired
shell-umpk-reference-in-process = reference programs load into the in-process simulator (sim-umpk:UMPK16)
shell-umpk-no-reference = no reference program `{ $name }`
shell-hint-umpk-references = reference programs: { $names }
shell-umpk-reference-loaded = reference program { $name } loaded ({ $description }); mode { $mode }
shell-umpk-program-needs-file = umpk program needs a HEX file
shell-umpk-program-extra = unexpected `{ $extra }` (only `run` may follow the file)
shell-umpk-info-text = info="{ $info }": 1–22 printable ASCII characters (manual §4.2.4)
shell-hint-umpk-hex = nothing was sent; the { $model } takes records 00/01/02/03 inside 16#0000..16#{ $last }
shell-umpk-programmed-run = reset: the program is enabled (Work mode)
shell-umpk-programmed-stays = the controller stays in Programming mode; `umpk reset` enables the program
# After `umpk program`: what was written and acknowledged; `next` is one of the two messages above.
shell-umpk-programmed = programmed { $bytes } bytes in { $pages } page(s), { $records } records acknowledged{ $named ->
    [yes] , program info "{ $info }"
   *[no] { "" }
}{ $stopped ->
    [yes] ; the controller was in Work mode: its program stopped and its outputs went off when programming began
   *[no] { "" }
}; { $next }
shell-umpk-monitor-stopped = the real-time monitor stream stopped (no packet within the timeout)
shell-umpk-monitor-cannot-write = cannot write the monitor output: { $reason }
shell-umpk-monitor-samples = { $samples } monitor samples from { $packets } packets

## The command line's fleets, probe, recordings and served simulators (cli::fleet, probe, record, serve)

cli-device-timeout-bad = --device-timeout { $value } is not a duration
cli-hint-device-timeout = e.g. 30s, 2m, 500ms; 0 for none
cli-jobs-at-least-one = --jobs must be at least 1
cli-fleet-all-refused = { $message } (every member of fleet `{ $fleet }` refused it; nothing ran)
cli-fleet-no-sandbox = --sandbox runs on simulated devices only, not on a fleet
cli-hint-fleet-no-sandbox = grade submissions with plcsh lab grade, or run the fleet script without --sandbox
cli-fleet-checks = { $passed } checks passed, { $failed } failed
cli-agent-check-read-only = agent check writes the helper's mailbox and the SM bytes of one pulse channel, and --read-only refuses every change
cli-agent-check-profile = agent check writes the helper's mailbox and the SM bytes of one pulse channel, and profile `{ $profile }` ({ $origin }) limits writes
cli-hint-agent-check-writes = run it without --read-only, with the PLC's URL, when the machine is safe to test (docs/reference/first-connection.md lists what it writes)
cli-probe-in-process = { $url } is the in-process simulator: there is nothing on a wire to probe
cli-hint-probe-in-process = serve it and probe that: plcsh sim serve --tcp 127.0.0.1:0 [--agent], then plcsh probe tcp://ADDRESS
cli-probe-not-on-wire = `{ $scheme }:` is not a K2 on a wire
cli-hint-probe-urls = give tcp://HOST:PORT, rtu:PORT?baud=…, rtu+tcp://HOST:PORT or rtu+rfc2217://HOST:PORT
cli-probe-cannot-write-report = cannot write the report to { $file }
cli-replay-bench-options = replay --bench runs the bench's own simulators: --sim-model and --snapshot do not apply
cli-hint-replay-bench-options = change the model or the starting values in the bench file
cli-replay-no-device = replay sends the recorded requests to simulators it builds itself, never to --device
cli-hint-replay-no-device = choose the simulated model with --sim-model and its starting state with --snapshot
cli-replay-no-reply = (no reply)
cli-replay-recorded = recorded: { $reply }
cli-replay-replayed = replayed: { $reply }
cli-replay-skipped = not replayed: { $what }
cli-replay-summary = { $requests } request(s) replayed, { $differences } difference(s)
# `doing`: `showing` (record show) or `replaying` (replay).
cli-record-damaged = plcsh: warning: { $file }: { $doing ->
    [replaying] replaying
   *[showing] showing
} the { $frames } frames read around the damage; exit status 1
cli-record-truncated = plcsh: warning: { $file } ends early ({ $why }); { $doing ->
    [replaying] replaying
   *[showing] showing
} the { $frames } frames before
cli-serve-not-an-address = `{ $text }` is not an address to listen on
cli-hint-serve-address = use HOST:PORT (127.0.0.1:5020, 0.0.0.0:502) or a port (5020; 0 picks a free one)
cli-serve-cannot-listen = cannot listen on { $addr }
cli-hint-serve-port = choose another port (0 picks a free one); ports below 1024 need privileges
# `sim serve -v`: an injected fault acted on the served K2 (its virtual time and what it did).
cli-serve-fault-acted = plcsh sim serve: { $line }
cli-serve-idle-timeout = --idle-timeout { $value } is not a duration
cli-hint-serve-idle-timeout = e.g. 300s, 2m
cli-serve-servo-latency = --servo-latency { $value }: not a duration
cli-hint-serve-servo-latency = e.g. 1ms, 500us, 0
cli-serve-servo-baud = --servo-baud must be positive (e.g. 38400)
cli-serve-servo-line-stopped = the servo line stopped before it was ready
cli-serve-needs-transport = sim serve needs at least one transport
cli-hint-serve-transport = e.g. plcsh sim serve --tcp 127.0.0.1:5020 --rtu-tcp 0 --servo-tcp 0 (on Unix also --rtu-pty /tmp/k2 --servo-pty /tmp/kinco)
cli-serve-agent-needs-k2 = --agent runs in the served K2: give --tcp, --rtu-pty or --rtu-tcp too
cli-serve-no-signals = cannot install signal handlers
cli-serve-no-readiness = cannot print the readiness line
cli-serve-server-stopped = a server stopped
cli-serve-failed = serving failed
cli-serve-no-runtime = cannot start a runtime
cli-serve-fleet-state = --state with --fleet: the simulators would share one state file
cli-hint-serve-fleet-state = leave --state out (a served fleet keeps no state)
cli-serve-fleet-bench = --bench with --fleet: a bench describes one machine
cli-serve-fleet-ports = --tcp { $tcp } --fleet { $count }: the ports run past 65535
cli-serve-fleet-member-stopped = a fleet member's thread stopped
cli-serve-rfc2217-needs-tcp = --rfc2217 is for serial lines served on TCP
cli-hint-serve-rfc2217 = give --rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp or --umpk-tcp too, e.g. --rtu-tcp 0 --rfc2217

## Kinco servo drives (shell::commands::servo; Kinco servo RS232 notes, CiA 402 states)

# A command's form, shown when its words do not fit it (the form stays as typed in every language).
shell-usage-line = usage: { $line }
shell-servo-needs-subcommand = servo needs a subcommand
shell-servo-nothing-after = servo { $sub } takes nothing after it (got `{ $extra }`)
# `operation enabled` is the CiA 402 state's name (it stays as it is).
shell-servo-already-enabled = already in operation enabled
shell-servo-enabled = operation enabled ({ $steps })
shell-servo-mode-needs = servo mode needs a mode: position, velocity, immediate-velocity, homing, torque or pulse
shell-servo-unknown-mode = unknown mode `{ $mode }`
shell-hint-servo-modes = position (1), velocity (3), immediate-velocity (-3), homing (6), torque (4), pulse (-4)
shell-servo-mode-set = operating mode { $number } ({ $name })
shell-servo-halted = halted: braking to a stop and holding (controlword 16#{ $controlword })
shell-servo-halt-released = halt released: the motion resumes (controlword 16#{ $controlword })
shell-servo-homing = homing started (mode 6, controlword 16#000F → 16#001F)
shell-servo-saved = parameters stored (2FF0.01 = 1)
shell-servo-not-servo = `{ $name }` is not a servo drive
shell-servo-none-open = no servo drive is open
# `port`: this system's word for a serial port (/dev/ttyUSB0, COM3).
shell-hint-servo-open = open one with --device ax=kinco:{ $port }?id=1 or connect ax sim-servo:?id=1
shell-servo-several = several servo drives are open; name one
shell-hint-servo-several = servo { $first } status (open: { $names })
shell-servo-not-whole = `{ $key }={ $value }` is not a whole number
shell-hint-servo-options = options: { $options }
# `kind`: `abs` or `rel`; the target in encoder increments.
shell-servo-move = { $kind ->
    [rel] relative
   *[abs] absolute
} move to { $target } inc started
shell-servo-move-speed = { $kind ->
    [rel] relative
   *[abs] absolute
} move to { $target } inc started at { $rpm } rpm ({ $dec } DEC)
shell-servo-jog-usage = usage: servo jog SPEED [acc=… dec=…], e.g. servo jog 300rpm; servo jog 0 stops
shell-servo-jogging = jogging at { $rpm } rpm ({ $dec } DEC, mode 3)
shell-servo-over-max = { $rpm } rpm is above the drive's maximum speed of { $max } rpm (6080.00 max_speed)
shell-hint-servo-max = a speed up to { $max }rpm; the maximum is the drive's setting 6080.00 (servo read max_speed)
shell-hint-servo-wait = servo wait target timeout=5s
shell-servo-target-reached = target reached after { $seconds } s (position_actual { $position } inc)
shell-servo-read-needs = servo read needs objects, e.g. servo read target_velocity position_actual
# The columns of `servo read` (`|` between them).
shell-servo-read-columns = object | index | value | unit | engineering
shell-servo-encoder = encoder resolution { $resolution } inc/rev
shell-servo-not-hex-byte = `{ $text }` is not a hex byte
shell-servo-frame-length = a frame is 9 bytes (checksum added) or 10 bytes, not { $count }
shell-hint-servo-raw = e.g. servo raw 01 40 41 60 00 00 00 00 00
shell-servo-sim-needs = servo sim needs a control
shell-servo-sim-needs-simulator = servo sim works on simulated drives: in-process (sim-servo:), served by plcsh sim serve --servo-pty LINK, or served with --servo-tcp ADDR --servo-control PATH and opened with control=PATH
shell-hint-servo-sim-control = a served drive's control socket is LINK.ctl; give it as control=PATH in the kinco: URL if it is elsewhere
shell-servo-unknown = unknown `servo { $sub }`
