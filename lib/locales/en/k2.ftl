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
