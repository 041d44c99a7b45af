# plcsh messages (en): lab — labs, scripts and recordings. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Limits of a graded run (core::budget): the verdict names the limit passed.
budget-exceeded-minutes = exceeded { $n ->
    [one] { $n } simulated minute
   *[other] { $n } simulated minutes
}
budget-exceeded-seconds = exceeded { $n ->
    [one] { $n } simulated second
   *[other] { $n } simulated seconds
}
budget-exceeded-instructions = exceeded { $count } Lua instructions
budget-exceeded-memory = exceeded { $size } of Lua memory
budget-size-mib = { $n } MiB
budget-size-bytes = { $n } bytes

## Verdicts of a graded submission (lab::grader, lab::runner).
lab-grader-error = grader error: { $error }
lab-runtime-error = runtime error: { $error }
lab-exceeded-write = exceeded { $size } in the write directory
lab-exceeded-wall = exceeded the wall-clock safety net of { $seconds } s
lab-not-graded = not graded: stopped by { $cause }
lab-refused-link = refused: { $file } is a symbolic link: a submission is its own files, never a link (hand in the file itself)
lab-refused-size = refused: the submission is { $n } bytes, more than the lab's { $cap } ([budget] submission in lab.toml)
lab-not-submission-kind = not a submission: give a .lua script or an .il program
lab-not-submission-missing = not a submission: no such file
lab-not-accepted = not accepted: this lab accepts { $kinds } submissions
lab-plc-stopped = { $file }:{ $line }: the PLC stopped: { $error }
lab-plc-fault-code-at = { $place }: the PLC stopped on fault { $code } ({ $kind }): { $error } at `{ $at }`
lab-plc-fault-code = { $place }: the PLC stopped on fault { $code } ({ $kind }): { $error }
lab-plc-fault-at = { $place }: the PLC stopped on ({ $kind }): { $error } at `{ $at }`
lab-plc-fault = { $place }: the PLC stopped on ({ $kind }): { $error }
lab-device-replaced = { $file }: the submission closed or replaced the lab's device `{ $device }`
lab-cannot-read = cannot read { $file }: { $error }
lab-cannot-start-lua = cannot start Lua: { $error }
lab-opening-devices = opening the lab's devices
lab-view = the submission's own files, the lab's shared and starter files and the write directory
lab-write-dir-role = the write directory
lab-cannot-create-write-dir = cannot create a write directory for the run
lab-write-dir-not-own = the write directory given is not a folder of the grader's own
lab-cannot-create-report-dir = cannot create a folder for the report: { $error }
lab-cannot-create-write-dir-error = cannot create the write directory: { $error }
lab-cannot-start-worker = cannot start a worker: { $error }
lab-worker-no-report = the worker ended ({ $status }) without a report
lab-worker-error = plcsh lab worker: { $error }
lab-worker-cannot-write = plcsh lab worker: cannot write { $file }: { $error }
lab-workers-running = workers still running
lab-no-executable = cannot find the plcsh executable
lab-bytes-more = … { $n } bytes more

## `lab grade`, `lab new`, `lab check` (lab::runner, lab, cli::lab, shell::commands::lab).
lab-cannot-list = cannot list { $dir }
lab-no-such-submission = { $file }: no such file or folder
lab-hint-submissions = give submission files (.lua, .il) or folders of them
lab-no-submissions = no submissions found (.lua or .il files)
lab-grade-stopped = lab grade stopped by { $cause } before every submission was graded ({ $done } graded)
lab-hint-grade-again = run it again to grade every submission
lab-cannot-write = cannot write { $file }
lab-new-exists = { $dir } already exists
lab-hint-new-name = give a new folder name: plcsh lab new NAME
lab-cannot-create = cannot create { $dir }
lab-cannot-create-empty-dir = cannot create a folder for the empty program
lab-cannot-write-empty = cannot write the empty program
lab-not-in-sandbox = `lab` is not available in a sandboxed run (it starts processes and writes folders)
lab-not-in-this-run = `lab` is not available in this run
lab-hint-check-table = the table from `plcsh lab check` names each criterion's result
lab-bad-jobs = jobs={ $jobs }: a number of workers ≥ 1
lab-needs-sub = `lab` needs new, check or grade with its arguments

## lab.toml (lab::config).
lab-cannot-read-file = cannot read { $file }
lab-hint-lab-folder = a lab is a folder with a lab.toml; `plcsh lab new NAME` writes an example
lab-cannot-open = cannot open { $dir }
lab-no-such-file = { $file }: { $key } = "{ $name }": no such file in { $dir }
lab-file-outside = { $file }: { $key } = "{ $name }" is outside the lab folder
lab-hint-files-inside = a lab's files live in its folder, so the lab can be copied whole
lab-devices-one-way = { $file }: give the devices as bench = "FILE" or as a [devices] table (one of the two)
lab-hint-devices-example = e.g. [devices] plc = "sim:K205-16DT"
lab-budget-not-time = { $file }: [budget] { $key } = "{ $text }" is not a time plcsh reads
lab-budget-not-time-why = { $file }: [budget] { $key } = "{ $text }" is not a time plcsh reads: { $error }
lab-hint-write-time = write "{ $time }" (units h, min, s, ms)
lab-hint-write-time-or = write "{ $time }" or "{ $seconds }" (units h, min, s, ms)
lab-hint-time-example = e.g. "10min", "90s", "1h" (units h, min, s, ms)
lab-budget-not-positive = { $file }: [budget] { $key } = "{ $text }" must be more than zero
lab-budget-not-size = { $file }: [budget] { $key } = "{ $text }" is not a size
lab-hint-write-size = write "{ $size }" (units B, KiB, MiB, GiB)
lab-hint-size-example = e.g. "256MiB" (units B, KiB, MiB, GiB)
lab-budget-instructions-zero = { $file }: [budget] instructions must be more than zero
lab-not-a-grant = { $file }: grants = ["{ $grant }"]: not an action a lab grants
lab-hint-did-you-mean-grant = did you mean "{ $near }"? grants: { $grants }
lab-hint-grants = grants: { $grants }
lab-points-negative = { $file }: [points] "{ $key }" = { $value }: points are a number ≥ 0
lab-not-a-device = { $file }: device = "{ $device }" is not a device of the lab
lab-hint-did-you-mean-device = did you mean device = "{ $near }"? the lab's devices: { $devices }
lab-hint-devices = the lab's devices: { $devices }
lab-not-a-kind = { $file }: accepts = ["{ $kind }"]: not a submission kind
lab-hint-kinds = kinds: { $kinds }
lab-shared-not-lua = { $file }: shared = ["{ $name }"]: a shared module is a .lua file
lab-hint-shared-example = e.g. shared = ["helpers.lua"] (a submission then calls require("helpers"))

## Lua scripts (script): errors plcsh raises in Lua code.
script-session-busy = the session is busy: { $error }
script-no-session = no session: Lua runs only inside plcsh
script-device-not-open = device `{ $device }` is not open (closed, or never opened)
script-no-output = no output
script-bad-millis = { $what }: { $ms } is not a duration in milliseconds (a number ≥ 0)
script-json-too-deep = plcsh.json.encode: the value is nested more than { $depth } tables deep (or holds itself)
script-hint-json-tree = JSON holds trees of tables; flatten the value
script-hint-json-split = JSON arrays are lists 1…n without holes; objects have string keys — split the table
script-json-mixed = plcsh.json.encode: { $path } mixes list items and keys
script-json-sparse = plcsh.json.encode: { $path } is a sparse list ({ $items } items, highest index { $max })
script-unknown-option = { $what }: unknown option `{ $key }`
script-hint-did-you-mean-option = did you mean `{ $near }`? { $what } takes { $options }
script-hint-options = { $what } takes { $options }
script-wait-until-options = wait_until's second argument is {"{"}timeout=ms, every=ms{"}"} or a timeout, not a { $kind }
script-wait-until-timeout = wait_until: condition still false after { $time }
script-wait-until-timeout-what = wait_until: condition ({ $what }) still false after { $time }
script-hint-wait-until = raise `timeout`, or check the condition with plcsh.exec/get
script-method-error = { $method }: { $error }
script-hint-runs-command-line = { $method } runs a command line with extra arguments appended
script-hint-runs-template = { $method } runs `{ $template }` with extra arguments appended
script-arg-not-utf8 = argument is not UTF-8 text
script-cannot-pass = cannot pass a Lua { $kind } to a command
script-option-not-utf8 = option name is not UTF-8
script-option-not-string = option names are strings, not { $kind }
script-missing-argument = missing argument for `{ $spec }`
script-command-not-utf8 = command text is not UTF-8
script-nothing-to-run = nothing to run
script-sandbox-refused = { $what } is not available in a sandboxed run (it { $why ->
    [program] runs a program
    [delete] deletes a file
    [rename] renames a file
    [exit] ends plcsh
    [create] creates a file
    [environment] reads the machine's environment
   *[library] loads a C library
})
script-hint-sandbox = the sandbox allows simulated devices, printing, checks and files in the lab's folders
script-lab-frame = (a frame of the lab's)
script-sandbox-terminal = { $function } without a file reads the terminal: not in a sandboxed run
script-module-not-found = module '{ $name }' not found: { $own ->
    [folder] no { $path }.lua in the submission's folder
   *[single] a single-file submission has no modules of its own
}; { $shared ->
    [none] the lab shares no modules
   *[some] the lab shares { $modules }
}
script-require-not-string = bad argument #1 to 'require' (string expected, got { $kind })
script-require-loop = module '{ $name }' requires itself (a loop of require calls)
script-hint-require = a submission requires its own modules and those the lab shares
script-date-field-missing = field '{ $field }' missing in date table
script-cannot-read = cannot read { $file }: { $error }
script-os-exit = the script called os.exit({ $code })
script-tmpname-cannot-create = os.tmpname: cannot create a file in { $dir }: { $error }
script-tmpname-no-name = os.tmpname: no free name in { $dir }
script-no-built-in-module = no module '{ $name }' built into plcsh
script-sandbox-modules = (a sandboxed run loads only plcsh's modules and the lab's own)
script-operand-not-text = operand names are text
script-field-many-operands = `{ $text }` names { $count } operands; a field is one operand
script-hint-read-range = read a range with { $device }:get("{ $text }")
script-hint-methods = methods: { $methods }; operands are fields: { $device }.VW0
script-hint-did-you-mean-method = did you mean { $count ->
    [1] { $a }
    [2] { $a } or { $b }
   *[3] { $a } or { $b } or { $c }
}?
script-no-method = device `{ $device }` has no method or operand `{ $word }`
script-set-pairs-only = set: pass {"{"}"OPERAND", value{"}"} pairs only
script-set-odd-arguments = set: { $count } arguments; pass OPERAND, value, OPERAND, value …
script-set-names-strings = set: operand names are strings
script-set-needs-values = set needs operands and values
script-cannot-write-value = cannot write a Lua { $kind } (use a number, a boolean or a literal such as "16#85")
script-method-dot = `{ $method }` is a method: call it with a colon, `dev:{ $method }(…)`, not a dot `dev.{ $method }(…)`

## `plcsh publish` (cli::publish): readings to an MQTT broker.
publish-needs-broker = publish needs a broker
publish-hint-broker = --broker mqtt://HOST:1883, or url = "mqtt://HOST:1883" under [mqtt] in the profile file
publish-password-without-user = a broker password without a username
publish-hint-username = set username under [mqtt] in the profile file or PLCSH_MQTT_USERNAME
publish-cannot-read-ca = cannot read [mqtt] ca_file { $file }: { $error }
publish-auth-refused = the broker { $broker } refused the credentials ({ $why })
publish-hint-auth = check username under [mqtt] in the profile file (or PLCSH_MQTT_USERNAME) and PLCSH_MQTT_PASSWORD, and that the broker's ACL lets this user connect
publish-tls-failed = TLS with the broker { $broker } failed ({ $why })
publish-hint-tls = the broker's certificate must verify against ca_file under [mqtt] (its CA, PEM) or the system's roots, and name the host in --broker
publish-no-broker = no MQTT broker answered at { $broker } within { $seconds } s of the start ({ $why })
publish-hint-no-broker = is the broker running, and are the host and port in --broker right (mqtt:// 1883, mqtts:// 8883)?
publish-not-an-operand = `{ $operand }` is not an operand of this device: { $error }
publish-hint-fix-operand = nothing was published; fix the operand (plcsh -c 'get OPERAND' shows what the device answers)
publish-not-an-operand-fleet = `{ $operand }` is not an operand of any member of fleet `{ $fleet }`: { $error }
publish-not-an-operand-members = `{ $operand }` is not an operand of { $members }{ $more ->
    [0] {""}
   *[other] {" "}and { $more } more
}: { $error }
publish-hint-fix-operand-fleet = nothing was published; fix the operand (plcsh -f FLEET -c 'get OPERAND' shows what each member answers)
publish-bad-every = --every { $every } is not a duration
publish-hint-every = e.g. 1s, 250ms
publish-no-mqtt-thread = cannot start the MQTT thread
publish-no-poll-threads = cannot start the polling threads
publish-connected = connected to { $broker }
publish-broker-away = broker { $broker } away ({ $why }); readings are kept up to --buffer and sent when it returns
publish-device-back = { $device } answers again
publish-polling-stopped = polling stopped; delivering what is queued (the broker has a few seconds to take it)
publish-summary = published { $published } messages to { $broker } (group { $group }{ $shard ->
    [some] , shard { $shard_of }
   *[none] {""}
}); { $away } dropped while the broker was away, { $behind } dropped and { $skipped } polls skipped because plcsh fell behind, { $undelivered } dropped at the stop (not delivered), { $reconnects } reconnects{ $worst ->
    [some] ; most behind: { $worst_list }
   *[none] {""}
}{ $offline ->
    [some] ; offline: { $offline_list }
   *[none] {""}
}

## `plot` pictures (plot) and fleet runs (fleet).
plot-cannot-draw = cannot draw the plot: { $error }
plot-bad-picture = to={ $path }: pictures are .png or .svg
plot-hint-picture = e.g. to=ramp.png or to=ramp.svg
plot-cannot-write = cannot write { $path }: { $error }
plot-bad-size = size={ $text } is not WIDTHxHEIGHT (e.g. 900x400)
plot-size-range = size={ $text }: each side is { $min }…{ $max } pixels
fleet-internal-error = the work on this device stopped with an internal error
fleet-no-thread = cannot start a worker thread
fleet-timeout = no result within { $seconds } s
fleet-hint-timeout = the device may be off or slow; raise --device-timeout, or check its link alone
fleet-not-started = not started: the fleet run was stopped
fleet-all-ok = fleet { $fleet }: { $count } devices, all ok ({ $ms } ms, { $jobs } at once)
fleet-failed = fleet { $fleet }: { $failed } of { $count } devices failed: { $devices } ({ $ms } ms, { $jobs } at once)

## Recordings (record): --record, `replay`.
record-cannot-read = cannot read the recording { $file }
record-hint-give-file = give the file written by --record FILE
record-not-readable = { $file } is not a readable pcapng recording: { $error }
record-hint-capture = give a file written by plcsh --record FILE, or a pcapng/pcap capture of Modbus TCP taken on an Ethernet or loopback interface (tshark -i lo -f 'tcp port 502' -w FILE.pcapng)
record-snap-length = { $count } packets were cut short by the capture's snap length: frames in them are incomplete (capture again without -s, or with -s 0)
record-no-tcp = its { $count } packets carry no TCP payload (no Modbus TCP traffic was captured)
record-bytes-missing = { $lost } bytes from { $from } to { $to } are missing from the capture (frames around them may show as malformed)
record-cannot-create = cannot create the recording { $file }
record-hint-writable = check that the directory exists and is writable
record-cannot-write = cannot write the recording { $file }
record-incomplete = the recording { $file } is incomplete: { $error }
replay-no-sim-plc = { $link }: the bench has no simulated PLC
replay-no-sim-drive = { $link }: the bench has no simulated drive
replay-other-protocol = { $link }: { $protocol } frames (replay covers Modbus and servo links)
replay-undeclared-protocol = { $link }: frames of an undeclared protocol
replay-helper-cannot-run = { $link }: the helper program cannot run: { $error }
replay-no-reply-recorded = no reply was recorded; the simulator answers
replay-no-reply-replayed = a reply was recorded; the simulator gives none
replay-no-requests = { $file } holds no recorded requests
replay-hint-record = record a session that talks to a device over Modbus or a servo line: plcsh --record FILE --device plc=tcp://…
publish-command-too-big = a command is at most { $max } bytes
publish-command-not-json = not JSON: { $error }
publish-command-not-object = a command is a JSON object {"{"}"operand":…, "value":…{"}"}
publish-command-no-operand = `operand` (a string) is missing
publish-command-no-value = `value` (a number, true/false or a literal such as "16#85") is missing
publish-command-one-write = one operand and one value per command
publish-write-no-allow-list = write refused: `{ $device }` has no allow list: writes from the broker need one in its profile
publish-write-profile-no-allow-list = write refused: `{ $device }`'s profile has no allow list: writes from the broker need one
publish-no-such-member = `{ $device }` is no device of `{ $group }` (members: { $members })
publish-no-such-member-near = `{ $device }` is no device of `{ $group }` (members: { $members }); did you mean { $near }?
publish-no-runtime = cannot start a runtime: { $error }

## Capture files (record::container): pcapng and pcap, as read for `replay` and `decode`.
capture-empty = it is empty (0 bytes)
capture-bad-start = it starts with { $bytes } instead of a pcapng section header (0A 0D 0D 0A) or a pcap file header
capture-damaged-block = bytes { $from }…{ $to } ({ $count } bytes) are damaged ({ $why }); reading on at the block at offset { $next }
capture-no-block = it holds no complete block ({ $size } bytes): { $what ->
    [header] the section header
   *[block] the block
} at offset { $at } is { $state ->
    [cut] cut short
   *[damaged] damaged
} ({ $why })
capture-block-truncated = the block at offset { $at } is { $state ->
    [cut] cut short
   *[damaged] damaged
}: { $why }
capture-bad-magic = its byte-order magic { $magic } is neither 4D 3C 2B 1A nor 1A 2B 3C 4D
capture-short-section = { $left } bytes left, less than a section header's first 12
capture-short-block = { $left } bytes left, less than a block header
capture-unknown-block = unknown block type { $kind }
capture-bad-block-length = block length { $total } is not a multiple of 4 of at least 12
capture-block-past-end = block length { $total } but { $left } bytes left
capture-lengths-differ = its trailing length differs from its leading length
capture-block-short = { $block ->
    [section] section header
    [interface] interface description
    [enhanced] enhanced packet block
    [packet] packet block
   *[simple] simple packet block
} shorter than { $bytes } bytes
capture-packet-past-block = packet length { $length } runs past its block
capture-no-interface = a packet names interface { $id }, which no interface description declared
capture-short-pcap = { $size } bytes: shorter than a pcap file header (24)
capture-short-record = { $left } bytes left, less than a record header
capture-record-past-end = record length { $length } but { $left } bytes left
capture-record-impossible = record lengths { $length }/{ $original } or time fraction impossible
capture-record-unreadable = unreadable record header
capture-damaged-record = bytes { $from }…{ $to } ({ $count } bytes) are damaged ({ $why }); reading on at the record at offset { $next }
capture-record-truncated = the record at offset { $at } is cut short or damaged ({ $why })
