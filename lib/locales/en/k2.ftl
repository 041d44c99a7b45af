# plcsh messages (en): k2 — the K2's driver, simulator, helpers, wiring and snapshots. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Pulse outputs: pto, pwm, profile (k2::helpers::pto; manual §3.4)

k2-pto-rounded = { $hz } Hz is not a whole number of µs: cycle { $us } µs = { $actual } Hz
k2-pto-relay-model = { $model } has relay outputs: no PTO/PWM (manual §2.2.6)
k2-pto-relay-model-hint = pulse outputs need a transistor-output model, e.g. K205-16DT
k2-pto-no-channel = { $model } has no pulse channel { $channel }
k2-pto-no-channel-hint = pulse channels: { $list }
k2-pto-cycle-register = { $us } µs does not fit a cycle register: up to 65 535 µs, or whole milliseconds up to 65 535 ms
k2-pto-cycle-below-minimum = a cycle of { $us } µs is below the minimum of 2 (§3.4.2.2)
k2-pto-cycle-too-short = a cycle of { $us } µs is too short for { $output }: its shortest cycle is { $shortest } µs ({ $max } Hz, manual §3.4)
k2-pto-cycle-too-short-hint = cycle={ $shortest }us or longer; cycle= is in µs unless a unit is given (cycle=1ms)
k2-pto-freq-too-high = { $hz } Hz is above { $output }'s limit of { $max } Hz (manual §3.4)
k2-pto-freq-too-high-hint = the shortest cycle on { $output } is { $shortest } µs
k2-pto-count-range = count={ $count }: a PTO needs 2 … 4 294 967 295 pulses (§3.4.2.1)
k2-pto-ms-base = cycle { $us } µs uses the 1 ms time base (SM{ $control }.3 = 1)
k2-pwm-width-whole-ms = width={ $width } µs: with a { $cycle } µs cycle the time base is 1 ms, so the width must be whole ms
k2-pwm-always-on = width ≥ cycle: 100 % duty, the output stays on (§3.4.2.1)
k2-pwm-always-off = width 0: 0 % duty, the output stays off (§3.4.2.1)
k2-table-odd-hint = e.g. at VB{ $at }
k2-profile-even = VB{ $at } is even: a profile table must start at an odd V address (§3.4.2.1)
k2-profile-segments = { $n } segments: a profile has 1 … { $max }
k2-profile-past-v = the table VB{ $at }…VB{ $last } runs past the V area of { $model } (VB{ $top })
k2-profile-backup = the table VB{ $at }…VB{ $last } overlaps the E2PROM backup area VB{ $first }…VB{ $end } (§2.2.8): every write wears it
k2-table-backup-hint = move the table below VB3648, or add `force`
k2-profile-segment = segment { $n }
k2-profile-segment-count = segment { $n }: count={ $count } (1 … 4 294 967 295)
k2-profile-segment-error = segment { $n }: { $message }
k2-profile-ms-base = the profile uses the 1 ms time base (SM{ $control }.3 = 1)
k2-profile-mixed-base = one time base serves all segments (§3.4.2.1): some cycles need 1 ms units (> 65 535 µs) but others are not whole ms
# The meanings of a PTO control byte's bits (§3.4.2.2), listed by `pto N status`.
k2-pto-control-bit = { $bit ->
    [enabled] enabled
    [disabled] disabled
    [sync] synchronous update
    [async] asynchronous update
    [multi] multi-segment
    [single] single segment
    [base-ms] 1 ms time base
    [base-us] 1 µs time base
    [cycle] update cycle
    [width] update width
   *[count] update count
}
# The meanings of a PTO status byte's bits (§3.4.2.2).
k2-pto-status-bit = { $bit ->
    [pto-idle] PTO idle
    [pto-busy] PTO busy
    [pwm-idle] PWM idle
    [pwm-running] PWM running
    [invalid] cycle or count invalid
   *[aborted] aborted by user command
}
k2-pto-status-control = control: { $words }
k2-pto-status-position = position { $pulses } pulses
k2-pto-status-estop = emergency stop latched (SM{ $byte }.7)
k2-pto-status-dir-off = direction output disabled (SM{ $byte }.3)
k2-pto-busy = PTO{ $channel } is still sending a pulse train (SM{ $byte }.7 PTO idle = 0)
k2-pwm-busy = PWM{ $channel } is running (SM{ $byte }.3 PWM idle = 0)

## High-speed counters: hsc (k2::helpers::hsc; manual §3.3)

k2-hsc-no-counter = { $model } has no high-speed counter HSC{ $n }
k2-hsc-no-counter-hint = counters on { $model }: { $list }
k2-hsc-no-mode = HSC{ $n } has no mode { $mode } (manual §3.3.1)
k2-hsc-no-mode-hint = HSC{ $n }'s modes: { $list }
k2-hsc-rate-4x = rate=4x applies to the A/B modes (9, 10), not mode { $mode }
k2-hsc-dir = mode { $mode } takes its direction from its inputs; dir= applies to modes 0–2 (§3.3.2)
k2-hsc-no-reset = mode { $mode } has no reset input
k2-hsc-no-start = mode { $mode } has no start input
k2-hsc-cyclic-relative = cyclic CV = PV interrupts need relative PVs (§3.3.2: SM141.2 acts only with SM141.1)
k2-hsc-table-needs-at = a PV table (several PVs, relative or cyclic) needs a V address: add `at VB3009`
k2-hsc-at-needs-pv = `at` needs PVs: pv=[100,200,300]
k2-hsc-even = VB{ $at } is even: the PV table starts at an odd V address (§3.3.2)
k2-hsc-too-many-pvs = { $n } PVs: a counter has at most { $max } (§3.3.3)
k2-hsc-past-v = the PV table VB{ $at }…VB{ $last } runs past the V area of { $model } (VB{ $top })
k2-hsc-backup = the PV table VB{ $at }…VB{ $last } overlaps the E2PROM backup area VB{ $first }…VB{ $end } (§2.2.8)
k2-hsc-pv-ends-table = PV{ $index } = { $pv } would end the table there (§3.3.3: relative |PV| > 1, absolute neighbours differ by > 1)
k2-hsc-events = CV = PV events { $first }…{ $last } (§3.3.4)
# The meanings of an HSC status byte's bits (§3.3.2), and of its control byte's enable bit.
k2-hsc-status-bit = { $bit ->
    [up] counting up
    [down] counting down
    [equal] CV = PV
    [greater] CV > PV
    [fault] PV table fault
    [enabled] enabled
   *[disabled] disabled
}
k2-hsc-status-cv = CV { $cv }
k2-hsc-status-written-cv = SMD{ $smd } holds { $value }, written: a new CV, loaded by the next HSC { $n } with SM{ $control }.6 set (§3.3.2)
k2-hsc-status-multi-pv = { $kind ->
    [relative] multi-PV relative, segment { $segment }
    [relative-cyclic] multi-PV relative cyclic, segment { $segment }
    [absolute-cyclic] multi-PV absolute cyclic, segment { $segment }
   *[absolute] multi-PV absolute, segment { $segment }
}
k2-hsc-status-single-pv = single PV { $pv }

## Running a helper's plan (k2::helpers)

k2-not-a-k2 = this device is not a K2 PLC
k2-duration-not-positive = `{ $text }` is not a positive duration

## Operands: what an operand is, `help OPERAND`, completion (k2::space)

k2-describe-overlaps = overlaps { $names }
k2-describe-pulse-output = digital output; PTO{ $channel }/PWM{ $channel } pulse output (max { $khz } kHz)
k2-describe-direction-output = digital output; direction output of position channel { $channel }
k2-describe-v-backup = variable memory, in the E2PROM backup area (VB3648–VB4095, §2.2.8)
k2-help-type = type { $dtype } ({ $bits } bits), range { $range }
k2-help-area = { $unit ->
    [elements] area { $area } ({ $meaning }): { $n } elements on { $model }
   *[bytes] area { $area } ({ $meaning }): { $n } bytes on { $model }
}
k2-help-manual = manual { $section }
k2-help-source = source: { $source }
k2-help-written-as = written as the manual and KincoBuilder write operands (S7-200 style)
# What each operand form is, in the completion menu.
k2-complete-form = { $form ->
    [I] input bit I0.0
    [IB] input byte
    [Q] output bit Q0.0
    [QB] output byte
    [M] memory bit M0.0
    [MB] memory byte
    [MW] memory word
    [MD] memory double word
    [V] V bit V0.0
    [VB] V byte
    [VW] V word
    [VD] V double word
    [SM] special memory
    [AIW] analog input word
    [AQW] analog output word
    [T] timer
    [C] counter
   *[K4M] 16-bit group of M bits
}

## Snapshots of the simulators (snapshot)

snapshot-cannot-encode = cannot encode the snapshot
snapshot-section-invalid = `{ $device }`'s { $section } section in the snapshot is not valid
snapshot-section-invalid-at = `{ $device }`'s { $section } section in the snapshot is not valid at `{ $at }`
snapshot-file-damaged = the file may be damaged
snapshot-wire-of = a wire of `{ $name }` in the snapshot
snapshot-cannot-snapshot = cannot snapshot `{ $name }`: { $why }
snapshot-all-or-none = a snapshot holds every simulated device or none
snapshot-family-not-kept = cannot snapshot `{ $name }`: a simulated { $family } device's state is not kept in snapshots
snapshot-family-not-kept-hint = close it before saving, or save without it
snapshot-nothing = no simulated device is open: nothing to snapshot
snapshot-nothing-hint = snapshots hold simulator state (sim:MODEL, sim-servo:, sim-fx:, sim-umpk:); a real device's state is its own
snapshot-has-device = the snapshot has this device
snapshot-not-simulated = `{ $name }` is not a simulated { $family } device, as it was when the snapshot was saved
snapshot-not-simulated-hint = open the same simulators under the same names (e.g. --device plc=sim:MODEL)
# `article` is the English article the model name takes: `a` (K205-16DT) or `an` (FX2N).
snapshot-model-differs = { $article ->
    [an] cannot restore `{ $name }`: the snapshot is of an { $saved }, this simulator is an { $model }
   *[a] cannot restore `{ $name }`: the snapshot is of a { $saved }, this simulator is a { $model }
}
snapshot-open-as = open it as { $name }={ $scheme }:{ $model }
snapshot-restoring-wire = restoring `{ $name }`'s wire `{ $wire }`
snapshot-cannot-restore = cannot restore `{ $name }`: { $why }
snapshot-wires-not-back = restoring `{ $name }`: its wires did not come back as saved
snapshot-not-format = not a plcsh snapshot (format `{ $format }`)
snapshot-newer-version = the snapshot is version { $version }, this plcsh reads up to version { $max }
snapshot-newer-version-hint = restore it with the newer plcsh that saved it
snapshot-unknown-section = the snapshot's `{ $name }` has a `{ $section }` section this plcsh cannot restore
snapshot-unknown-section-hint = it was saved by a newer plcsh; restoring without it would not give the same state
snapshot-save-refused = cannot save the snapshot: { $why }
snapshot-save-refused-hint = nothing was written: the file would not restore. This is a fault in plcsh; please report it with the commands that led here
snapshot-does-not-read-back = it does not read back ({ $error })
snapshot-section-changes = `{ $name }`'s { $section } section does not read back as saved: `{ $at }` changes
snapshot-cannot-read = cannot read the snapshot { $path }
snapshot-cannot-read-hint = list saved snapshots with `sim snapshots`
snapshot-not-snapshot = { $path } is not a plcsh snapshot
snapshot-no-k2 = the snapshot holds no simulated K2

## Wires between simulated devices (core::wiring, wiring)

wire-not-terminal = `{ $text }` is not a terminal: write DEVICE:TERMINAL
wire-no-device-or-terminal = `{ $text }` names no device or no terminal
wire-not-wire = `{ $text }` is not a wire: write FROM -> TO
wire-not-wire-hint = e.g. sim wire plc:Q0.0 -> servo:pulse
wire-no-destination = the wire has no destination after `->`
wire-options-key-value = `{ $word }`: wire options are key=value
wire-options-short-hint = options: lines=N (encoder), delay=D (loopback)
wire-lines-positive = lines={ $value }: lines per revolution must be a positive whole number
wire-delay-negative = delay={ $value } is negative
wire-delay-too-long = delay={ $value } is longer than a wire holds: at most { $max } µs (about 584 years)
wire-no-option = wires have no option `{ $key }`
wire-options-hint = options: lines=N (encoder output), delay=D (output to input)
wire-cannot-join = { $from } cannot be wired to { $to }
wire-cannot-join-hint = wires that work: PLC pulse output -> servo:pulse; servo:encoder -> two PLC inputs (A,B); servo:target_reached|fault|enabled -> PLC input; servo:home@POS|limit+@POS|limit-@POS -> PLC input; PLC output -> PLC input [delay=D]
wire-lines-encoder-only = lines= applies to an encoder output (servo:encoder -> …)
wire-delay-loop-only = delay= applies to a PLC output wired back to a PLC input
wire-not-position = { $terminal }: `{ $text }` is not a position in increments
wire-only-switches-at = { $terminal }: only home, limit+ and limit- switches take @POS
wire-unknown-drive-terminal = drive terminal `{ $name }` is unknown ({ $terminal })
wire-drive-terminals-hint = drive terminals: pulse, encoder, target_reached, fault, enabled, home@POS, limit+@POS, limit-@POS
wire-describe-pulses = PTO{ $channel } pulses (with its direction output) to the pulse input
wire-describe-encoder-lines = encoder A/B, { $lines } lines (A/B periods) per revolution
wire-describe-encoder = encoder A/B, a quarter period per increment
wire-describe-drive-output = { $output ->
    [target-reached] drive output target reached (statusword bit 10)
    [fault] drive output fault
   *[enabled] drive output operation enabled
}
wire-describe-switch = { $switch } switch at { $position } increments (also the drive's own input)
wire-describe-loop = output to input, delay { $delay } µs
wire-describe-pulse-loop = PTO{ $channel } output (pulses and level) to input, delay { $delay } µs
wire-real-plc = { $name } is a real PLC: wires join simulated devices
wire-real-plc-hint = open a simulator, e.g. connect plc sim:K205-16DT
wire-real-drive = { $name } is a real drive: wires join simulated devices
wire-real-drive-hint = open a simulated drive, e.g. connect servo sim-servo:?id=1
wire-cannot-wire = { $name } cannot be wired (only simulated K2 PLCs and drives can)
wire-two-plcs = { $wire }: wires between two PLCs are not simulated; a PLC output wires back to its own inputs
wire-two-drives = { $wire }: drive-to-drive wiring is not simulated
wire-two-drives-hint = wire drives to a simulated PLC
wire-nothing = nothing is wired
wire-nothing-hint = sim wire FROM -> TO adds a wire, e.g. sim wire plc:Q0.0 -> servo:pulse

## Benches: a simulated machine from a file (wiring::bench)

bench-no-faults = { $device } takes no injected faults (only simulated K2 PLCs and drives do)
bench-shape-hint = a bench has [devices] NAME = "URL", and optional wires = ["A -> B"], init = ["DEV:OP=VALUE"], [programs], [tags], [[faults]]
bench-no-devices = bench { $file }: [devices] is empty
bench-cannot-read = cannot read the bench file { $file }
bench-not-simulator = bench { $file }: device { $name } = { $url } is not a simulator
bench-not-simulator-hint = a bench file describes a simulated machine: use sim:MODEL and sim-servo:?id=N
# Where in a bench an error arose; the error's own message follows after `: `.
bench-at-device = bench { $file }, device { $name }
bench-at-wire = bench { $file }, wire { $n } `{ $wire }`
bench-at-init = bench { $file }, init { $n } `{ $item }`
bench-at-fault = bench { $file }, fault { $n } `{ $fault }`
bench-at-program = bench { $file }, program for { $device }
bench-init-shape = bench { $file }, init { $n }: `{ $item }` is not DEVICE:OPERAND=VALUE
bench-fault-on = fault on { $device }: { $what }
bench-program-missing = bench { $file }: the program { $program } for { $device } does not exist
bench-program-unreadable = bench { $file }: cannot read the program { $program }: { $error }
bench-program-not-k2 = bench { $file }: a program runs in a simulated K2, and { $device } is not one
bench-program-not-k2-hint = give programs for sim:MODEL devices only
bench-opened = bench { $name }: { $devices } device(s), { $wires } wire(s), { $values } value(s)
bench-second-plc = bench { $file }: { $name } is a second PLC; sim serve serves one PLC
bench-second-line = bench { $file }: { $name } is on a second drive line; sim serve serves one line
bench-second-line-hint = put the drives on one line: sim-servo:axis?id=1 and sim-servo:axis?id=2

## PLS in the simulator: what it starts and why it refuses (k2::sim::pto; manual §3.4.2)

# A PLS refusal: `reason` is one of the k2-pls-… reasons below.
k2-pls-refused = PLS { $channel }: { $reason }; status bit SM{ $byte }.4 set
k2-pls-pwm-cycle-below-two = PWM cycle time { $cycle } is below 2
k2-pls-pwm-cycle-below-two-hint = set SMW{ $register } (2…65535) and the update bit SM{ $control }.0, then PLS again
k2-pls-cycle-below-two = cycle time { $cycle } is below 2 (cycle and count must both be > 1, §3.4.2.2)
k2-pls-cycle-below-two-hint = load SMW{ $register } with SM{ $control }.0 set (e.g. SMB{ $control }=16#85), then PLS again
k2-pls-count-below-two = pulse count { $count } is below 2 (cycle and count must both be > 1, §3.4.2.2)
k2-pls-count-below-two-hint = load SMD{ $register } with SM{ $control }.2 set (e.g. SMB{ $control }=16#85), then PLS again
k2-pls-what-cycle = cycle { $cycle } { $unit }
k2-pls-what-segment-cycle = segment { $n } cycle { $cycle } { $unit }
k2-pls-too-fast = { $what } is { $hz } Hz, above { $output }'s limit of { $max } Hz on this model (manual §3.4)
k2-pls-did-nothing = PLS { $channel } did nothing: the control byte SMB{ $control } = 16#{ $value } has the enable bit SM{ $control }.7 clear and PTO{ $channel } ({ $output }) is idle
k2-pls-stopped = { $name } stopped ({ $what }; enable bit SM{ $control }.7 is 0)
k2-pls-pwm-started = { $update ->
    [sync] { $name }: PWM cycle { $cycle } { $unit }, width { $width } { $unit } ({ $duty } %), synchronous update
   *[async] { $name }: PWM cycle { $cycle } { $unit }, width { $width } { $unit } ({ $duty } %)
}
k2-pls-pto-started = { $segments ->
    [one] { $name }: { $pulses } pulses in { $segments } segment, { $seconds } s
   *[other] { $name }: { $pulses } pulses in { $segments } segments, { $seconds } s
}
k2-pls-table-even = the profile table start SMW{ $register } = { $start } is even
k2-pls-table-even-hint = the table must start at an odd V address, e.g. SMW{ $register }=3001 for VB3001 (§3.4.2.1)
k2-pls-table-past-v = the profile table start VB{ $start } is past the V area (VB{ $top })
k2-pls-table-past-v-hint = point it at an odd address inside V
k2-pls-table-segments = the profile table at VB{ $start } holds { $n } segments (1–{ $max } allowed)
k2-pls-table-segments-hint = write the segment count into the table's first byte
k2-pls-table-runs-past = the profile table VB{ $start }…VB{ $last } runs past the V area
k2-pls-table-runs-past-hint = move the table or use fewer segments
k2-pls-segment-cycle = segment { $n } cycle time VW{ $word } = { $cycle } is below 2
k2-pls-segment-cycle-hint = cycles are 2…65535 in the channel's time base
k2-pls-segment-count = segment { $n } pulse count VD{ $dword } is 0
k2-pls-segment-count-hint = every segment needs at least 1 pulse
k2-pls-other-channel-hint = SMB{ $control } = 16#{ $value } is set: that is PTO{ $channel }'s control byte ({ $output }) — did you mean PLS { $channel }?
k2-pls-set-control-hint = set the control byte first, e.g. set SMB{ $control }=16#85, SMW{ $cycle }=500, SMD{ $count }=1000
k2-pstop = { $what ->
    [none] PSTOP { $channel }: nothing was running; emergency-stop latch SM{ $byte }.7 = 1 (clear it with set SM{ $byte }.7=0)
   *[other] PSTOP { $channel }: { $what } stopped; emergency-stop latch SM{ $byte }.7 = 1 (clear it with set SM{ $byte }.7=0)
}

## The K2 simulator: inputs, retention, options, injected faults (k2::sim)

k2-input-driven = { $pin } is driven by a simulated signal ({ $source })
k2-input-driven-by-wire-hint = a wire drives it: sim unwire plc:{ $pin }
k2-input-driven-hint = stop it first: sim input { $pin } off
k2-input-counted-by = counted by HSC{ $n } (mode { $mode })
k2-input-above-hsc-limit = warning: above HSC{ $n }'s { $max } Hz limit on { $model } (§3.3): a real PLC would miss counts
k2-input-no-source = no simulated signal drives { $pin }
k2-input-no-source-hint = `sim inputs` lists the sources
k2-retain-area = { $part }: only V, M and C ranges can be retained
k2-retain-area-hint = e.g. sim retain VB0..VB99 MB0[16] C0..C15
k2-retain-too-much = { $bytes } retained bytes asked for; { $model } retains at most { $room } (manual §2.1.2)
k2-retain-too-much-hint = retain fewer or shorter ranges (a counter takes 2 bytes)
k2-state-not-saved = the simulator state was not saved: { $error }
k2-fault-exception = the PLC refused the request: Modbus exception { $code } { $name } (injected fault { $id })
k2-fault-no-power = no reply from the PLC: it has no power (injected fault { $id })
k2-fault-no-power-hint = sim faults shows when power returns; sim fault clear restores it now
k2-fault-no-reply = no reply from the PLC (injected fault { $id }: { $name })
k2-fault-no-reply-hint = sim faults lists the injected faults; sim fault clear removes them
k2-option-backup-last = backup_last={ $value } is not a V byte address
k2-option-program-unreadable = cannot read the program { $file }: { $error }
k2-option-unknown = K2 simulators have no option `{ $key }`
k2-sim-relay-model = { $model } has relay outputs: no PTO/PWM pulse outputs (manual §2.2.6)
k2-sim-no-pulse-channel-q05 = { $model } has no pulse channel { $channel } (Q0.5 is a pulse output only on K209M-56DT)
k2-sim-pulse-channels-hint = pulse channels on { $model }: { $list }

## Injected faults of the K2 simulator (k2::sim::fault, k2::sim::control)

k2-fault-negative = { $key }={ $value }: must not be negative
k2-fault-not-input = `{ $text }` is not an input bit (e.g. I0.1)
k2-fault-which = which fault? { $usage }
k2-fault-needs-code = `{ $kind }` needs a code (1…255, e.g. 2 for illegal data address)
k2-fault-not-code = `{ $code }` is not a Modbus exception code (1…255)
k2-fault-needs-delay = `{ $kind }` needs a delay (e.g. late 300ms)
k2-fault-needs-input-level = `{ $kind }` needs an input and level (stuck I0.1=1)
k2-fault-stuck-shape = `{ $word }`: write stuck I0.1=1 or stuck I0.1=0
k2-fault-not-level = `{ $value }` is not a level (0 or 1)
k2-fault-needs-input = `{ $kind }` needs an input (noisy I0.1 freq=5kHz)
k2-fault-not-kind = `{ $kind }` is not a fault kind; { $usage }
k2-fault-on-needs-operands = `on` needs operands, e.g. on VW100..VW110
k2-fault-spans-areas = `{ $operands }` spans areas: give one area's range
k2-fault-not-option = `{ $word }` is not an option; { $usage }
k2-fault-times = times={ $value }: a count from 1
k2-fault-freq-noisy-only = freq= is for noisy inputs
k2-fault-unknown-option = unknown option `{ $key }=`; { $usage }
k2-fault-noisy-needs-freq = a noisy input needs freq= (how many random levels per second), e.g. freq=5kHz
k2-fault-at-or-after = give at= or after=, not both
k2-fault-power-loss-needs-for = a power loss needs its length: power-loss for=5s (the PLC is back after it)
k2-fault-power-loss-options = a power loss takes at=, after= and for= (it acts on the whole PLC)
k2-fault-on-request-only = `on` is for request faults; { $kind } names its input
k2-control-words-hint = control words: { $words }; faults: { $usage }
k2-control-acts-when-served = (acts when the simulator is served: sim serve --fault …, or its control channel)
k2-control-empty = an empty control line
k2-control-unknown-word = `{ $word }` is not a control word of a simulated K2

## The K2's wire driver: Modbus replies and the helper mailbox (k2::driver)

k2-reply-bad-crc = a reply with an invalid CRC arrived: { $frame } (CRC { $got }, its bytes need { $want })
k2-reply-bad-crc-received = a reply with an invalid CRC arrived: { $frame } (CRC { $got }, its bytes need { $want }); received: { $received }
k2-reply-no-frame = { $n } byte(s) arrived but no valid reply frame; received: { $received }
k2-not-k2-request = { $request } is not a K2 request
k2-reply-function-code = a reply with function code { $got } to a request with { $want }
k2-reply-unit = a reply from unit { $got } to a request for unit { $want }
k2-reply-not-tcp = a reply header that is not Modbus TCP: { $header }
k2-reply-transaction = a reply for transaction { $tid }, unit { $unit } to transaction { $want_tid }, unit { $want_unit }
k2-no-more-replies = no more replies
k2-reply-malformed = a malformed reply to { $request }: { $data }
k2-reply-read-short = the reply to a read of { $table } { $addr } was too short
k2-mailbox-refused = { $doing ->
    [reading] the PLC refused reading the helper mailbox: { $name } (Modbus exception { $code })
   *[writing] the PLC refused writing the helper mailbox: { $name } (Modbus exception { $code })
}
k2-mailbox-refused-hint-2 = check that agent=VB… lies inside the V area of this model
k2-mailbox-refused-hint-4 = the PLC reports a device failure: check its error LED and diagnostics, then try again
k2-mailbox-refused-hint = check that this is the PLC's Modbus port and unit (plcsh probe URL says what it answers)
k2-mailbox-unexpected-reply = unexpected reply { $reply } reading the helper mailbox
k2-needs-helper = { $what } needs the plcsh helper program in the PLC; this device has none configured
k2-needs-helper-hint = install lib/k2_agent.il (docs/agent.md) and connect with …&agent=VB3400
k2-no-helper = no helper configured on this device
k2-no-helper-hint = connect with …&agent=VB3400
k2-helper-status = helper protocol { $version } at VB{ $base }, heartbeat { $heartbeat }, last command { $seq } (result { $result })
k2-done-by-helper = { $what }: done by the helper
k2-rtc-reply-short = the helper's READ_RTC reply is shorter than 8 bytes
k2-rtc-reads-as = the PLC clock reads as { $value }

## High-speed counters in the simulator: HDEF, HSC, PV tables (k2::sim::hsc; manual §3.3)

k2-hsc-table-even = the PV table start { $start } is even (it must be an odd V offset, §3.3.2)
k2-hsc-table-past-v = the PV table start VB{ $start } is past the V area
k2-hsc-table-count = the PV table at VB{ $start } holds { $n } PVs (1–{ $max } allowed)
k2-hsc-table-runs-past = the PV table at VB{ $start } runs past the V area
k2-hsc-table-empty = the PV table at VB{ $start } ends before its first PV (|PV| must be > 1)
k2-hsc-no-mode-yet = HSC{ $n } has no mode yet
k2-hsc-no-mode-yet-hint = run `hdef { $n } MODE` first (HDEF, manual §3.3.5); modes: { $list }
k2-hsc-stopped = HSC{ $n } stopped (enable bit SM{ $control }.7 is 0); CV { $cv }
k2-hsc-table-fault = PV table fault (SM{ $status }.3 = 1): { $reason }
k2-hsc-table-fault-none = PV table fault (SM{ $status }.3 = 1): no table loaded; set SM{ $mpv }.4 to load the table at SMW{ $table }
k2-hsc-counting-table = { $kind ->
    [relative-cyclic] { $n } relative PVs (cyclic), next CV = PV at { $target }
    [relative] { $n } relative PVs, next CV = PV at { $target }
    [absolute-cyclic] { $n } absolute PVs (cyclic), next CV = PV at { $target }
   *[absolute] { $n } absolute PVs, next CV = PV at { $target }
}
k2-hsc-counting-no-table = no PV table
k2-hsc-counting = HSC{ $n } counting in mode { $mode } from CV { $cv }; { $compare }

## The simulator's state file (k2::sim::state)

k2-backup-end = the E2PROM backup area ends at VB{ $default } (default) … VB{ $max }, not VB{ $last }
k2-backup-end-hint = manual §2.2.8: VB3648–VB3902 by default, extensible to VB4095
k2-state-invalid = the state file { $file } is not valid
k2-state-invalid-hint = move it away to start from a fresh state
k2-state-unreadable = cannot read the state file { $file }
k2-state-cannot-encode = cannot encode the state
k2-state-in-use = the state file { $file } is in use by another process
k2-state-in-use-by = the state file { $file } is in use by process { $pid }
k2-state-in-use-hint = one plcsh per state file: give this one its own (--state FILE) or none (--state none), or stop the other

## Wires at the PLC's terminals, breakpoints (k2::sim::wired, k2::sim::program::debug)

wire-not-plc-terminal = { $model }: `{ $terminal }` is not a PLC terminal
wire-plc-terminals-hint = PLC terminals: Q0.0 (output), Q0.0,Q0.2 (pulses + direction), I0.3 (input), I0.1,I0.0 (A,B)
wire-no-pulse-output = { $model } has no pulse output on { $pin }
wire-no-pulse-output-hint = a pulse + direction pair starts with a PTO output (Q0.0 PTO0, Q0.1 PTO1 …)
wire-a-b-same = A and B are both { $pin }
wire-ends = { $wire }: both ends are on one device or neither is the PLC
wire-ends-hint = wire a PLC terminal to a drive terminal, or a PLC output to a PLC input
wire-nothing-short-hint = sim wire FROM -> TO adds a wire
wire-none-touches = no wire touches `{ $which }`
wire-list-hint = wires: { $list }
k2-no-program = no program is loaded
k2-no-program-hint = sim program load FILE.il
k2-no-network = { $source } has no network { $n }
k2-no-network-hint = networks are numbered by `(* Network n *)` comments or NETWORK lines
k2-not-breakpoint = `{ $spec }` is not a breakpoint
k2-no-instruction-after = { $source } has no instruction on or after line { $line }
k2-breakpoint-at = breakpoint at { $source }:{ $line }: { $text }

## Events, the clock and operations a connection lacks (k2::instr, k2)

k2-event-pto-complete = PTO{ $channel } complete
k2-event-cv-eq-pv-multi = HSC{ $channel } CV = PV{ $k } (multi-PV)
k2-event-cv-eq-pv = HSC{ $channel } CV = PV (single PV)
k2-event-hsc-reset = HSC{ $channel } external reset
k2-event-hsc-direction = { $dir ->
    [up] HSC{ $channel } counting direction changed to up
   *[down] HSC{ $channel } counting direction changed to down
}
k2-event-eeprom-wear = E2PROM byte VB{ $byte } has been written { $writes } times (endurance ~1 000 000, §2.2.8)
k2-event-fault = injected fault { $id } ({ $name }) acted
k2-rtc-not-datetime = `{ $text }` is not a date and time; write it as 2026-11-22T10:00:00
k2-rtc-year = year { $year } is outside 2000–2099 (the clock keeps two digits)
k2-rtc-month = month { $month } is not 1–12
k2-rtc-day = day { $day } is not 1–{ $days } for { $month }
k2-rtc-time = { $time } is not a time of day
k2-rtc-not-bcd = 16#{ $value } is not a BCD byte
k2-what-event-access = event access
k2-what-helper-status = the helper status
k2-not-here = { $what } is not available on this connection
k2-not-here-hint = the simulator runs it; on a real PLC it needs the PLC-side helper program
k2-no-longer-k2 = the device no longer answers as a K2 PLC
snapshot-not-name = `{ $name }` is not a snapshot name (Latin letters A-Z a-z, digits, _ - .)
snapshot-not-name-hint = or give a file path ending in .json
snapshot-no-data-dir = no data directory for snapshots
snapshot-no-data-dir-hint = give a file path ending in .json

## Operands and instructions of an IL program in the K2 simulator (k2::sim::program)

k2-program-one-location = a program operand is one location, not a range
k2-program-bit-group = { $operand } is a bit group; programs address bytes, words and bits
k2-program-bit-group-hint = use MW/VW words or M/V bits in programs
k2-program-not-element = { $what ->
    [timer] { $operand } is not a timer
   *[counter] { $operand } is not a counter
}
k2-program-timers-hint = timers are T0…T255
k2-program-counters-hint = counters are C0…C255
k2-program-clock-buffer = an 8-byte clock buffer does not fit there
k2-program-unknown-instruction = unknown family instruction { $id }

## Restoring a K2 simulator from a snapshot (k2::sim::snapshot)

k2-snapshot-model = the snapshot is of a { $saved }, this simulator is a { $model }
k2-snapshot-area-hex = area { $area } is not hex
k2-snapshot-area-size = area { $area } has { $n } bytes, the { $model } has { $want }
k2-snapshot-element-counts = timer or counter counts differ from the model's
k2-snapshot-channel-counts = pulse output or counter counts differ from the model's
k2-snapshot-no-area = no area { $area }
k2-snapshot-helper-program = the helper program: { $error }
k2-snapshot-program = the snapshot's program { $source }: { $error }
k2-snapshot-halt = the snapshot's DEBUG halt is at instruction { $at }, the program has { $n }
k2-snapshot-breakpoint = the snapshot's breakpoint is at instruction { $at }, the program has { $n }

## Simulated input signals, the helper's mailbox, the served simulator (k2::sim)

k2-hsc-snapshot-mode = HSC{ $n } has no mode { $mode }
k2-source-square = { $pin } square wave { $freq }
k2-source-quadrature = A/B quadrature { $lead } leads { $lag } at { $freq }
k2-source-train = { $pin } pulse train, { $pulses } pulses of { $cycle } ns
k2-source-encoder = encoder A on { $a }, B on { $b }
k2-helper-mailbox-address = the helper's mailbox needs an even V address with { $size } bytes free up to VB{ $top } (got VB{ $base })
k2-serve-accept-retry = cannot accept a connection now ({ $error }); retrying
k2-serve-stream-closed = the stream closed
