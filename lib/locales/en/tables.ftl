# plcsh messages (en): tables — descriptions of SM bytes, servo objects, instructions and elements. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## K2 special memory (src/k2/sm_map.rs; K2 manual §3.3.2, §3.3.3, §3.4.2.2, §3.4.3.1)

tbl-sm-pos-cv-read-only = SMD{ $cv } is the read-only current value of position channel { $n } (manual §3.4.3.1)
tbl-sm-pos-cv-overlap = { $written } overlaps SMD{ $cv }, the read-only current value of position channel { $n } (manual §3.4.3.1)
tbl-sm-pos-cv-read-only-hint = load a new value through SMD{ $new } and SM{ $control }.4 (set SMD{ $new }=100, SM{ $control }.4=1), or clear it with SM{ $control }.6
tbl-sm-pls-did-nothing = PLS { $n } did nothing: the enable bit SM{ $control }.7 of the control byte SMB{ $control } is clear and PTO{ $n } is idle
tbl-sm-pls-did-nothing-hint = set SMB{ $control }=16#85 (enable, PTO, update cycle and count), SMW{ $cycle } and SMD{ $count }, then PLS { $n }
tbl-sm-smb0-read-only = { $written } holds the system status bits and is read-only
tbl-sm-smb0-read-only-hint = SM0.0 is always on, SM0.1 marks the first scan, SM0.5 is the 1-second clock
tbl-hsc-mode-0-0 = count I0.1, direction by SM37.3
tbl-hsc-mode-0-1 = count I0.1, reset I0.0, direction by SM37.3
tbl-hsc-mode-0-2 = count I0.1, reset I0.0, start I0.5, direction by SM37.3
tbl-hsc-mode-0-3 = count I0.1, direction input I0.5
tbl-hsc-mode-0-4 = count I0.1, direction input I0.5, reset I0.0
tbl-hsc-mode-0-6 = up I0.0 / down I0.1 (two-pulse)
tbl-hsc-mode-0-9 = A/B quadrature, A = I0.1, B = I0.0
tbl-hsc-mode-1-0 = count I0.3, direction by SM47.3
tbl-hsc-mode-1-1 = count I0.3, reset I0.4, direction by SM47.3
tbl-hsc-mode-1-2 = count I0.3, reset I0.4, start I0.6, direction by SM47.3
tbl-hsc-mode-1-3 = count I0.3, direction input I0.2
tbl-hsc-mode-1-4 = count I0.3, direction input I0.2, reset I0.4
tbl-hsc-mode-1-6 = up I0.2 / down I0.3 (two-pulse)
tbl-hsc-mode-1-7 = up I0.2 / down I0.3 (two-pulse), reset I0.4
tbl-hsc-mode-1-9 = A/B quadrature, A = I0.3, B = I0.2
tbl-hsc-mode-1-10 = A/B quadrature, A = I0.3, B = I0.2, reset I0.4
tbl-hsc-mode-2-0 = count I0.5, direction by SM57.3
tbl-hsc-mode-2-9 = A/B quadrature, A = I0.4, B = I0.5
tbl-hsc-mode-3-0 = count I0.7, direction by SM127.3
tbl-hsc-mode-3-9 = A/B quadrature, A = I0.6, B = I0.7
tbl-sm-smb0 = system status bits (read-only)
tbl-sm-sm0-0 = always on
tbl-sm-sm0-1 = on during the first scan only
tbl-sm-sm0-5 = 1-second clock (0.5 s on, 0.5 s off)
tbl-sm-sm0-6 = toggles every scan
tbl-sm-pto-control = PTO{ $n }/PWM{ $n } ({ $q }) control byte
tbl-sm-pto-control-0 = PTO{ $n } control: update cycle time
tbl-sm-pto-control-1 = PTO{ $n } control: update pulse width (PWM)
tbl-sm-pto-control-2 = PTO{ $n } control: update pulse count (PTO)
tbl-sm-pto-control-3 = PTO{ $n } control: time base: 0 = 1 µs, 1 = 1 ms
tbl-sm-pto-control-4 = PTO{ $n } control: PWM update: 0 async, 1 sync
tbl-sm-pto-control-5 = PTO{ $n } control: PTO mode: 0 single, 1 multi-segment
tbl-sm-pto-control-6 = PTO{ $n } control: function: 0 PTO, 1 PWM
tbl-sm-pto-control-7 = PTO{ $n } control: enable
tbl-sm-pto-status = PTO{ $n }/PWM{ $n } ({ $q }) status byte
tbl-sm-pto-status-3 = PTO{ $n } status: PWM idle
tbl-sm-pto-status-4 = PTO{ $n } status: cycle time or pulse count invalid (must be > 1)
tbl-sm-pto-status-5 = PTO{ $n } status: profile aborted by user command
tbl-sm-pto-status-7 = PTO{ $n } status: PTO idle
tbl-sm-pto-cycle = PTO{ $n }/PWM{ $n } cycle time (2…65535, in the time base)
tbl-sm-pwm-width = PWM{ $n } pulse width (0…65535, in the time base)
tbl-sm-pto-count = PTO{ $n } pulse count (≥ 2)
tbl-sm-pto-profile = PTO{ $n } multi-segment profile table start (odd V offset)
tbl-sm-pos-cv = position channel { $n } current value, pulses (read-only)
tbl-sm-pos-new-cv = position channel { $n } new current value (loaded by bit 4 of SMB{ $control })
tbl-sm-pos-control = position channel { $n } control byte
tbl-sm-pos-control-7 = position channel { $n } control: emergency stop latched (set by PSTOP)
tbl-sm-pos-control-6 = position channel { $n } control: clear current value
tbl-sm-pos-control-4 = position channel { $n } control: load the new current value
tbl-sm-pos-control-3 = position channel { $n } control: direction output disable
tbl-sm-hsc-control = HSC{ $n } control byte
tbl-sm-hsc-control-0 = HSC{ $n } control: reset active level (0 high, 1 low)
tbl-sm-hsc-control-1 = HSC{ $n } control: start active level (0 high, 1 low)
tbl-sm-hsc-control-2 = HSC{ $n } control: quadrature rate (0 = 1x, 1 = 4x)
tbl-sm-hsc-control-3 = HSC{ $n } control: count direction (0 down, 1 up)
tbl-sm-hsc-control-4 = HSC{ $n } control: write the count direction
tbl-sm-hsc-control-5 = HSC{ $n } control: write the new preset value
tbl-sm-hsc-control-6 = HSC{ $n } control: write the new current value
tbl-sm-hsc-control-7 = HSC{ $n } control: enable
tbl-sm-hsc-status = HSC{ $n } status byte
tbl-sm-hsc-status-3 = HSC{ $n } status: multi-PV table fault
tbl-sm-hsc-status-5 = HSC{ $n } status: current direction (1 up)
tbl-sm-hsc-status-6 = HSC{ $n } status: CV = PV
tbl-sm-hsc-status-7 = HSC{ $n } status: CV > PV
tbl-sm-hsc-cv = HSC{ $n } current value (CV)
tbl-sm-hsc-pv = HSC{ $n } preset value (PV, single-PV mode)
tbl-sm-hsc-mpv-control = HSC{ $n } multi-PV control byte
tbl-sm-hsc-mpv-control-0 = HSC{ $n } multi-PV control: use multiple PVs
tbl-sm-hsc-mpv-control-1 = HSC{ $n } multi-PV control: PV type (0 absolute, 1 relative)
tbl-sm-hsc-mpv-control-2 = HSC{ $n } multi-PV control: cyclic CV=PV interrupts (relative only)
tbl-sm-hsc-mpv-control-4 = HSC{ $n } multi-PV control: load the PV table
tbl-sm-hsc-mpv-control-5 = HSC{ $n } multi-PV control: reset interrupt variable (0 yes, 1 no)
tbl-sm-hsc-table = HSC{ $n } PV table start (odd V offset)
tbl-sm-hsc-segment = HSC{ $n } current PV segment number (from 0)

## Servo object dictionary (src/servo/objects.rs; Kinco servo RS232 protocol, CiA 402)

tbl-servo-not-in-table = not in the table
tbl-servo-object-missing = an object is missing (e.g. controlword or 6040.00)
tbl-servo-not-a-type = `/{ $suffix }` is not an object type
tbl-servo-not-a-type-hint = use /u8, /i8, /u16, /i16, /u32 or /i32
tbl-servo-not-an-object = `{ $text }` is not a servo object
tbl-servo-suffix-size = { $name } ({ $address }) is { $bits } bits; /{ $suffix } is { $suffix_bits } bits
tbl-servo-suffix-size-hint = drop the suffix, or use /{ $suffix }
tbl-servo-size-unknown = { $address } is not in the object table, so its size is unknown
tbl-servo-size-unknown-hint = add a type suffix, e.g. { $address }/u16 (u8, i8, u16, i16, u32, i32)
tbl-servo-suggest-none = `help servo` or completion lists the objects; raw objects are written 6040.00
tbl-servo-suggest = did you mean { $names }?
tbl-servo-read-only = { $name } ({ $address }) is read-only
tbl-servo-read-only-hint = read it with get; the drive would answer 0x80 (attempt to write a read-only object)
tbl-servo-far-too-large = { $text } is far too large for { $dtype } ({ $lo }…{ $hi })
tbl-servo-does-not-fit = { $text } = { $raw } does not fit { $dtype } ({ $lo }…{ $hi })
tbl-servo-resolution-hint = encoder resolution is { $resolution } inc/rev
tbl-servo-help-type = type { $dtype } ({ $bits } bits), range { $lo }…{ $hi }
tbl-servo-help-access = access { $access }
tbl-servo-help-access-unit = access { $access }, unit { $unit }
tbl-servo-help-access-unit-example = access { $access }, unit { $unit } (write e.g. { $name }=300{ $eng }; encoder resolution { $resolution } inc/rev)
tbl-servo-help-source = source: { $source }
tbl-servo-controlword = DS402 controlword: 0x06 shutdown, 0x07 switch on, 0x0F enable operation, bit 4 new set-point, bit 5 change set immediately, bit 6 relative, bit 7 fault reset, bit 8 halt, bit 12 Kinco start on target write (0x103F)
tbl-servo-statusword = DS402 statusword: state bits 0-6, bit 10 target reached, bit 11 internal limit, bit 12 set-point ack/homing attained, bit 13 following/homing error, bit 15 Kinco home found
tbl-servo-error-code = last error code (DS402; 0 = no fault)
tbl-servo-quickstop-option = quick stop option code: 0 coast, 1/2 stop on profile/quick-stop deceleration then switch on disabled, 5/6 the same and stay in quick stop active
tbl-servo-shutdown-option = shutdown option code (stored; the simulator stops at once)
tbl-servo-disable-option = disable operation option code (stored; the simulator stops at once)
tbl-servo-halt-option = halt option code: 1 stop on profile deceleration, 2 on quick-stop deceleration
tbl-servo-fault-reaction-option = fault reaction option code (stored; the simulator stops at once)
tbl-servo-operating-mode = operating mode: 1 profile position, 3 profile velocity, -3 immediate velocity, 4 torque, 6 homing, -4 pulse train
tbl-servo-mode-display = operating mode in effect (DS402; uncertain on Kinco)
tbl-servo-position-actual = actual position (Kinco drivers use 6063, not 6064)
tbl-servo-position-actual-value = actual position as DS402 numbers it (the same value as 6063 in the simulator; uncertain on Kinco)
tbl-servo-max-following-error = following error window: a larger following error for longer than 6066.00 faults the drive (0x8611)
tbl-servo-following-error-timeout = following error time-out, ms
tbl-servo-position-window = position window for target reached
tbl-servo-velocity-actual = actual velocity
tbl-servo-target-torque = target torque (unit uncertain)
tbl-servo-max-current = maximal current command (unit uncertain)
tbl-servo-torque-actual = actual torque (unit uncertain)
tbl-servo-current-actual = actual current (unit uncertain)
tbl-servo-target-position = target position for profile position mode
tbl-servo-home-offset = home offset: the position assigned at the home point after homing
tbl-servo-soft-limit-pos = software position limit + (notes and C# client; CiA 402 calls sub 1 the minimum limit - check your drive); limits are off while + <= -
tbl-servo-soft-limit-neg = software position limit - (notes and C# client; CiA 402 calls sub 2 the maximum limit - check your drive)
tbl-servo-polarity = direction: 0 CCW positive, 1 CW positive
tbl-servo-max-speed = maximum speed (unit uncertain)
tbl-servo-profile-velocity = profile (trapezoid) speed for position moves
tbl-servo-profile-acceleration = profile (trapezoid) acceleration
tbl-servo-profile-deceleration = profile (trapezoid) deceleration
tbl-servo-quickstop-deceleration = deceleration used by quick stop
tbl-servo-homing-method = homing method: 17/18 negative/positive limit switch, 19-22 home switch, 33/34 index pulse, 35/37 current position (CiA 402 numbering)
tbl-servo-homing-speed-switch = homing speed while searching the switch
tbl-servo-homing-speed-zero = homing speed while searching zero
tbl-servo-homing-offset-mode = Kinco homing offset mode: 0 home is position 0, 1 home is the offset (stored; uncertain)
tbl-servo-homing-acceleration = homing acceleration
tbl-servo-following-error-actual = actual following error (simulated as velocity x 2 ms)
tbl-servo-digital-inputs = digital inputs: bit 0 negative limit, bit 1 positive limit, bit 2 home, bit 3 hardware lock
tbl-servo-digital-outputs = digital outputs (DS402 physical outputs; stored)
tbl-servo-target-velocity = target speed for velocity modes 3 and -3
tbl-servo-brake-resistor = braking resistor resistance
tbl-servo-brake-resistor-power = braking resistor power
tbl-servo-brake-resistor-time = braking resistor time constant
tbl-servo-velocity-kp = velocity loop proportional gain (stored)
tbl-servo-velocity-ki = velocity loop integral gain (stored)
tbl-servo-position-kp = position loop proportional gain (stored)
tbl-servo-drive-id = RS232 drive id (1 default; takes effect after a restart)
tbl-servo-din-polarity = digital input polarity (stored)
tbl-servo-din-simulate = simulated digital inputs (stored)
tbl-servo-din1-function = DIN1 function (stored; 0x10 positive limit, 0x20 negative limit per a public C++ client - uncertain)
tbl-servo-din2-function = DIN2 function (stored)
tbl-servo-din3-function = DIN3 function (stored)
tbl-servo-din4-function = DIN4 function (stored)
tbl-servo-din-real = digital inputs as wired (the simulator mirrors 60FD.00 bits 0-2)
tbl-servo-dout1-function = DOUT1 function (stored)
tbl-servo-dout2-function = DOUT2 function (stored)
tbl-servo-dout-real = digital outputs as driven
tbl-servo-gear-factor = electronic gear factor (pulse train mode -4)
tbl-servo-gear-divider = electronic gear divider (pulse train mode -4; 0 is refused)
tbl-servo-pulse-mode = pulse input mode: 0 CW/CCW, 1 pulse+direction, 2 A/B (x4, uncertain)
tbl-servo-pulse-filter = pulse input filter (stored)
tbl-servo-pulse-frequency-control = pulse frequency control
tbl-servo-master-speed = pulse input frequency (unit uncertain; the simulator: pulses/ms)
tbl-servo-error-state = Kinco error state (bit meanings uncertain; the simulator sets bit 0 while faulted)
tbl-servo-baud-code = RS232 baud code: 1080 = 9600, 540 = 19200, 270 = 38400 (default), 90 = 115200; after a restart
tbl-servo-store-parameters = write 1 to store all parameters
tbl-servo-store-motor-data = write 1 to store motor data
tbl-servo-display-select = 7-segment display select
tbl-servo-target-speed-rpm = target speed in rpm (the FD5P manual's RS232 example writes 600 here with a 4-byte write and reads it back with a 2-byte reply, 4B; the simulator stores it)
tbl-servo-user-password = user password
tbl-servo-encoder-resolution = encoder (feedback) resolution used by the DEC formulas, increments per revolution

## Servo engineering units (src/servo/units.rs; kinco-servo.md §4)

tbl-unit-bad-resolution = encoder resolution `{ $text }` is not a whole number of increments per revolution in 1…{ $max } (e.g. 10000 or 65536)
tbl-unit-unknown-speed = unit `{ $unit }` is not known here; write rpm or dec (the drive's unit) for a speed: { $number }rpm
tbl-unit-unknown-accel = unit `{ $unit }` is not known here; write rps/s or dec (the drive's unit) for an acceleration: { $number }rps/s
tbl-unit-unknown-position = unit `{ $unit }` is not known here; write rev or inc for a position: { $number }rev
tbl-unit-not-a-number = `{ $number }` is not a number (write e.g. 300{ $suffix })
tbl-unit-takes = this object takes { $raw } or { $eng }, not { $suffix }
tbl-unit-takes-plain = this object takes plain numbers, not { $suffix }
tbl-unit-not-whole = { $number }{ $suffix } is not a whole number of { $suffix }

## K2 model catalogue (src/k2/catalog.rs; K2 manual §1.2, §2.1.2, §2.2.6, §3.4)

tbl-model-unknown = unknown K2 model `{ $name }`
tbl-model-unknown-hint = catalogued models: { $models }
tbl-model-k204et-1-what = HSC2/HSC3 maximum frequency
tbl-model-k204et-1-chosen = 200 kHz single-phase and A/B (§2.2.6)
tbl-model-k204et-1-other = §2.1.2 lists 20 kHz single-phase / 10 kHz A/B in the CPU204 column (that column appears shifted: it matches §2.2.6's CPU209EA row)
tbl-model-k204et-2-what = Q0.4 maximum frequency
tbl-model-k204et-2-chosen = 200 kHz (§2.2.6, §3.4)
tbl-model-k204et-2-other = §2.1.2 lists 10 kHz in the CPU204 column
tbl-model-k209ea-1-what = Q0.4 maximum frequency
tbl-model-k209ea-1-chosen = 10 kHz (§2.2.6, §3.4)
tbl-model-k209ea-1-other = §2.1.2 lists Q0.0, Q0.1, Q0.4 at 200 kHz and a fourth output Q0.5 in the CPU209EA column (apparently CPU209M's entry, shifted)
tbl-model-k209ea-2-what = number of high-speed counters
tbl-model-k209ea-2-chosen = 4 (§2.2.6 gives HSC2/HSC3 frequencies for K209EA)
tbl-model-k209ea-2-other = §2.1.2 prints 2 in the CPU209EA column (apparently CPU209M's entry, shifted)
tbl-model-k205ea-1-what = HSC and pulse output frequencies
tbl-model-k205ea-1-chosen = 200 kHz on all channels (§2.1.2, the only table that lists CPU205EA)
tbl-model-k205ea-1-other = §2.2.6 and §3.4 do not list CPU205EA

## Servo drive state machine (src/servo/ds402.rs; CiA 402 as the Kinco manual follows it). The CiA 402
## state and command names (operation enabled, switch on …) stay as they are: JSON reports carry them.

tbl-ds402-does-not-fit = { $value } does not fit { $name } ({ $lo }…{ $hi })
tbl-ds402-or = { $a } or { $b }
tbl-ds402-step-stuck = { $what } (controlword 16#{ $cw }) did not reach { $want }: statusword 16#{ $sw } = { $state }
tbl-ds402-step-stuck-unknown = { $what } (controlword 16#{ $cw }) did not reach { $want }: statusword 16#{ $sw } = unknown state
tbl-ds402-in-fault-hint = the drive is in fault: run servo fault-reset
tbl-ds402-check-status-hint = check servo status
tbl-ds402-in-fault = the drive is in fault (statusword 16#{ $sw })
tbl-ds402-in-fault-enable-hint = run servo fault-reset, then servo enable
tbl-ds402-mode-readback = operating mode reads back { $got } after writing { $mode }
tbl-ds402-not-enabled = cannot { $what ->
    [release-halt] release halt
   *[other] { $what }
}: the drive is in "{ $state }" (statusword 16#{ $sw })
tbl-ds402-not-enabled-unknown = cannot { $what ->
    [release-halt] release halt
   *[other] { $what }
}: the drive is in "unknown state" (statusword 16#{ $sw })
tbl-ds402-not-enabled-hint = run servo enable first
tbl-ds402-buffer-full = the drive's set-point buffer stayed full for { $seconds } s (statusword 16#{ $sw }, bit 12 high with bit 4 low)
tbl-ds402-buffer-full-hint = wait for the running moves (servo wait target), then move again
tbl-ds402-no-ack = the drive did not acknowledge the set-point (statusword 16#{ $sw }, bit 12 clear)
tbl-ds402-fault-while-waiting = the drive went into fault while waiting (statusword 16#{ $sw })
tbl-ds402-fault-while-waiting-hint = servo status shows the state; servo fault-reset clears it
tbl-ds402-homing-error = homing ended in a homing error (statusword 16#{ $sw }, bit 13)
tbl-ds402-homing-error-hint = check the homing method (6098.00) and the switches; servo status shows the bits
tbl-ds402-target-timeout = target not reached within { $seconds } s (statusword 16#{ $sw })
tbl-ds402-target-timeout-at = target not reached within { $seconds } s (statusword 16#{ $sw }, position_actual { $position })
tbl-ds402-target-timeout-hint = a longer timeout=, or servo status to see why

## The sandbox of graded and confined runs (src/confine.rs): bench actions a lab grants by name, and refusals

tbl-bench-refused = `{ $what }` is not available to a graded submission: it { $why }, which changes the lab's machine rather than drives it
tbl-bench-refused-hint = a submission drives the lab's devices as its program would on the real machine; a lab that needs this grants it in lab.toml: grants = ["{ $what }"]
tbl-bench-other = changes the bench
tbl-confine-no-write = writing { $path } is not allowed in a sandboxed run
tbl-confine-no-write-hint = give the run a directory for its files: plcsh run --sandbox --write-dir DIR
tbl-confine-write-outside = writing { $path } is outside { $dir }
tbl-confine-write-outside-hint = a sandboxed run writes only under its --write-dir
tbl-confine-real-device = { $url } is a real device: a sandboxed run opens simulated devices only
tbl-confine-real-device-hint = in the sandbox use sim:MODEL, sim-servo:, sim-umpk:MODEL or sim-fx:MODEL
tbl-confine-read-outside = reading { $path } is outside the sandbox's folders
tbl-confine-read-outside-hint = a sandboxed run reads files only under { $folders }
tbl-confine-named-snapshot = the named snapshot `{ $name }` lives in the user's data directory, which a sandboxed run may not touch
tbl-confine-named-snapshot-hint = give a file path under the write directory, e.g. out/start.json
tbl-confine-no-folder = no folder
tbl-bench-sim-clock = shows or changes the simulator's clock mode
tbl-bench-sim-input = drives a simulated input signal
tbl-bench-sim-quad = drives a simulated encoder
tbl-bench-sim-inputs = lists the simulated input signals
tbl-bench-sim-retain = changes the battery-retained ranges
tbl-bench-sim-program = loads, unloads or reads the PLC's program
tbl-bench-sim-cpu = runs or stops the PLC's CPU
tbl-bench-sim-stop = stops the PLC's CPU
tbl-bench-sim-pause = pauses the PLC's CPU
tbl-bench-sim-switch = moves the PLC's RUN/STOP switch
tbl-bench-sim-scan = runs PLC scans by hand
tbl-bench-sim-break = sets breakpoints in the PLC's program
tbl-bench-sim-stepi = steps the PLC's program
tbl-bench-sim-stepn = steps the PLC's program
tbl-bench-sim-wire = wires simulated devices together
tbl-bench-sim-wires = lists the wiring
tbl-bench-sim-unwire = removes wiring
tbl-bench-sim-snapshot = restores a saved simulated state
tbl-bench-sim-snapshots = lists the saved states
tbl-bench-sim-fault = injects or clears faults
tbl-bench-sim-faults = lists the injected faults
tbl-bench-servo-sim = controls the simulated drive
tbl-bench-umpk-sim = controls the simulated UMPK
tbl-bench-connect = opens a device
tbl-bench-close = closes a device
tbl-bench-rtc-sync = sets the PLC's clock from the host's
tbl-bench-paths = shows the user's folders

## FX instruction subset and its load errors (src/fx/program.rs; FX programming manual ch. 2, 4, 5)

tbl-fx-unknown = unknown FX instruction { $m }
tbl-fx-foreign-hint = { $m } is not an FX mnemonic: on an FX write { $how } (docs/il.md, The FX family)
tbl-fx-unknown-near = did you mean { $near }? (docs/il.md lists the FX subset)
tbl-fx-unknown-hint = docs/il.md lists the FX instructions the simulator runs
tbl-fx-operand-count = { $m } takes { $want } operand(s), found { $found }
tbl-fx-operand-range = { $m } takes { $lo } to { $hi } operand(s), found { $found }
tbl-fx-needs-preset = OUT { $t } needs a preset: OUT { $t } K10 (a constant) or OUT { $t } D10 (a register)
tbl-fx-bad-preset = { $k }: a preset is a constant K… or a data register D…
tbl-fx-hsc-not-simulated = { $t }: high-speed counters (C235–C255) are not simulated
tbl-fx-hsc-not-simulated-hint = use C0–C199 (16-bit) or C200–C234 (32-bit up/down)
tbl-fx-out-one-operand = OUT { $t } takes one operand (a preset is for timers and counters)
tbl-fx-rst-target = RST { $t }: resets Y, M, S, D, a timer T or a counter C
tbl-fx-input-written = { $m } { $t }: inputs X cannot be written by a program
tbl-fx-input-written-hint = write Y, M, S (as KnY0 …), D, or a timer's or counter's value
tbl-fx-coil-target = { $m } { $t }: a program drives Y, M and S bits here
tbl-fx-coil-target-hint = inputs X come from the field; OUT T0 K10 / OUT C0 K5 drive timers and counters
tbl-fx-system-driven = { $m } { $t }: { $operand } is driven by the PLC
tbl-fx-not-on-model = { $t } is not on an { $model }
tbl-fx-no-blocks = FX lists have no labels or program blocks here
tbl-fx-no-blocks-hint = write one instruction per line: LD X0 / OUT Y0 … END
tbl-fx-element-by-out = { $text }: FX timers and counters are driven by OUT
tbl-fx-element-by-out-hint = OUT T0 K50 (timer), OUT C0 K10 (counter), RST T0 / RST C0
tbl-fx-foreign-ton = the timer as a coil with its preset: LD X0 / OUT T0 K20 (T0–T199 count 100 ms)
tbl-fx-foreign-tof = an off-delay with a timer coil and LDI: LDI X0 / OUT T0 K20 (T0–T199 count 100 ms)
tbl-fx-foreign-tonr = a retentive timer coil: OUT T250 K20 (T250–T255 keep their value; RST T250 clears it)
tbl-fx-foreign-tp = a pulse from a timer coil: OUT T0 K20 with its contact (T0–T199 count 100 ms)
tbl-fx-foreign-ctu = the counter as a coil with its preset: LD X0 / OUT C0 K10 (RST C0 clears it)
tbl-fx-foreign-ctd = a down count with a 32-bit counter: OUT C200 K10 with M8200 on
tbl-fx-foreign-code = { $code }
tbl-fx-ld = start a block with a normally open contact
tbl-fx-ldi = start a block with a normally closed contact
tbl-fx-ldp = start a block: on for one scan when the bit rises
tbl-fx-ldf = start a block: on for one scan when the bit falls
tbl-fx-and = series normally open contact
tbl-fx-ani = series normally closed contact
tbl-fx-andp = series rising-edge contact
tbl-fx-andf = series falling-edge contact
tbl-fx-or = parallel normally open contact
tbl-fx-ori = parallel normally closed contact
tbl-fx-orp = parallel rising-edge contact
tbl-fx-orf = parallel falling-edge contact
tbl-fx-anb = AND the last two blocks
tbl-fx-orb = OR the last two blocks
tbl-fx-mps = push the operation result
tbl-fx-mrd = read the pushed result
tbl-fx-mpp = pop the pushed result
tbl-fx-inv = invert the operation result
tbl-fx-out = OUT Y/M/S: coil := result; OUT Tn K|D: timer coil with preset; OUT Cn K|D: counter coil
tbl-fx-set = if the result is on: set Y/M/S (stays on)
tbl-fx-rst = if the result is on: reset Y/M/S, clear D, clear a timer or counter (value 0, contact off)
tbl-fx-pls = Y/M on for one scan after the result rises
tbl-fx-plf = Y/M on for one scan after the result falls
tbl-fx-mov = MOV S D: D := S (16-bit)
tbl-fx-movp = MOV on the result's rising edge
tbl-fx-dmov = 32-bit MOV (D0 = D0 low, D1 high)
tbl-fx-dmovp = 32-bit MOV on the rising edge
tbl-fx-add = ADD S1 S2 D: D := S1 + S2 (16-bit, wraps)
tbl-fx-addp = ADD on the rising edge
tbl-fx-dadd = 32-bit ADD
tbl-fx-sub = SUB S1 S2 D: D := S1 − S2 (16-bit, wraps)
tbl-fx-subp = SUB on the rising edge
tbl-fx-dsub = 32-bit SUB
tbl-fx-inc = D := D + 1 every scan the result is on
tbl-fx-incp = D := D + 1 on the rising edge
tbl-fx-dec = D := D − 1 every scan the result is on
tbl-fx-decp = D := D − 1 on the rising edge
tbl-fx-ld-eq = start a block: S1 = S2 (16-bit)
tbl-fx-ld-gt = start a block: S1 > S2
tbl-fx-ld-lt = start a block: S1 < S2
tbl-fx-ld-ne = start a block: S1 ≠ S2
tbl-fx-ld-le = start a block: S1 ≤ S2
tbl-fx-ld-ge = start a block: S1 ≥ S2
tbl-fx-and-eq = series contact: S1 = S2
tbl-fx-and-gt = series contact: S1 > S2
tbl-fx-and-lt = series contact: S1 < S2
tbl-fx-and-ne = series contact: S1 ≠ S2
tbl-fx-and-le = series contact: S1 ≤ S2
tbl-fx-and-ge = series contact: S1 ≥ S2
tbl-fx-or-eq = parallel contact: S1 = S2
tbl-fx-or-gt = parallel contact: S1 > S2
tbl-fx-or-lt = parallel contact: S1 < S2
tbl-fx-or-ne = parallel contact: S1 ≠ S2
tbl-fx-or-le = parallel contact: S1 ≤ S2
tbl-fx-or-ge = parallel contact: S1 ≥ S2
tbl-fx-ldd-eq = 32-bit: start a block: S1 = S2
tbl-fx-ldd-gt = 32-bit: start a block: S1 > S2
tbl-fx-ldd-lt = 32-bit: start a block: S1 < S2
tbl-fx-andd-eq = 32-bit series contact: S1 = S2
tbl-fx-ord-eq = 32-bit parallel contact: S1 = S2
tbl-fx-nop = nothing
tbl-fx-end = end of the program: what follows is not scanned

## The K2's Modbus map (src/k2/modbus_map.rs; K2 manual §3.2.1). Modbus table names stay as they are.

tbl-modbus-word-order = `word_order={ $value }` is not a word order
tbl-modbus-word-order-hint = use word_order=high-first (S7 order, the default) or word_order=low-first
tbl-modbus-not-in-map = { $operand } is not in the K2 Modbus map: over Modbus a K2 exposes only I, Q, M, V, AI and AQ (manual §3.2.1); { $area } ({ $meaning }) is not reachable
tbl-modbus-not-in-map-sm-hint = install the plcsh helper program in the PLC (lib/k2_agent.il, docs/agent.md) and connect with …&agent=VB3400; the simulator (sim:MODEL) has SM directly
tbl-modbus-not-in-map-tc-hint = copy timers and counters to V in the PLC program and read the V words; the simulator (sim:MODEL) has T and C directly
tbl-modbus-past-end = { $operand } is past the end of the { $area } area on { $model }
tbl-modbus-read-only = { $operand } is read-only over Modbus ({ $meaning } are { $table }, which Modbus cannot write; manual §3.2.1)
tbl-modbus-read-only-hint = inputs follow the field wiring; write an output (Q, AQ) or memory (M, V) instead

## FX timers and counters by class (src/fx/elements.rs; FX PM "Timers", "Counters")

tbl-element-timer = T{ $n }: { $base } timer (T{ $first }–T{ $last }); contact T{ $n } = TS{ $n }, coil TC{ $n }, current value TN{ $n }; `OUT T{ $n } K50` in a program
tbl-element-timer-retentive = T{ $n }: { $base } timer, retentive (RST clears it) (T{ $first }–T{ $last }); contact T{ $n } = TS{ $n }, coil TC{ $n }, current value TN{ $n }; `OUT T{ $n } K50` in a program
tbl-element-counter = C{ $n }: 16-bit up counter (C0–C199); contact C{ $n } = CS{ $n }, coil CC{ $n }, current value CN{ $n }
tbl-element-counter32 = C{ $n }: 32-bit up/down counter (C200–C234), counts down while M{ $relay } is on; contact C{ $n } = CS{ $n }, current value CN{ $n }
tbl-element-hsc = C{ $n }: high-speed counter (C235–C255; not simulated)

## The core IL instruction set (src/engine/isa.rs; K2 manual §3.4.3.1, K80S CPU chapter, IEC 61131-3, S7-200 convention)

tbl-il-ld = CR := bit (the old CR is pushed)
tbl-il-ldn = CR := NOT bit
tbl-il-and = CR := CR AND bit
tbl-il-a = CR := CR AND bit
tbl-il-andn = CR := CR AND NOT bit
tbl-il-an = CR := CR AND NOT bit
tbl-il-or = CR := CR OR bit
tbl-il-o = CR := CR OR bit
tbl-il-orn = CR := CR OR NOT bit
tbl-il-on = CR := CR OR NOT bit
tbl-il-xor = CR := CR XOR bit
tbl-il-xorn = CR := CR XOR NOT bit
tbl-il-and-paren = open: CR := CR AND ( … )
tbl-il-andn-paren = open: CR := CR AND NOT ( … )
tbl-il-or-paren = open: CR := CR OR ( … )
tbl-il-orn-paren = open: CR := CR OR NOT ( … )
tbl-il-xor-paren = open: CR := CR XOR ( … )
tbl-il-xorn-paren = open: CR := CR XOR NOT ( … )
tbl-il-close = close the innermost parenthesis
tbl-il-not = CR := NOT CR
tbl-il-st = bit := CR
tbl-il-assign = bit := CR
tbl-il-stn = bit := NOT CR
tbl-il-s = if CR: set bit (N bits with `S bit, N`; a T/C is set on)
tbl-il-r = if CR: reset bit (N bits); a timer or counter: value and bit cleared
tbl-il-ald = AND the top two logic-stack levels
tbl-il-old = OR the top two logic-stack levels
tbl-il-lps = push a copy of the CR
tbl-il-lrd = CR := the second stack level
tbl-il-lpp = pop the stack into the CR
tbl-il-r-trig = CR := CR rose since this instruction last ran
tbl-il-eu = rising edge (S7-200 name of R_TRIG)
tbl-il-f-trig = CR := CR fell since this instruction last ran
tbl-il-ed = falling edge (S7-200 name of F_TRIG)
tbl-il-move = if CR: OUT := IN (type of OUT)
tbl-il-movb = byte move
tbl-il-movw = word move
tbl-il-movd = double-word move
tbl-il-movr = REAL move
tbl-il-blkmove = if CR: copy N elements IN… → OUT…
tbl-il-bmb = block move of N bytes
tbl-il-bmw = block move of N words
tbl-il-bmd = block move of N double words
tbl-il-fill = if CR: N words from OUT := IN
tbl-il-add = OUT := OUT + IN, or OUT := IN1 + IN2
tbl-il-sub = OUT := OUT − IN, or IN1 − IN2
tbl-il-mul = OUT := OUT × IN, or IN1 × IN2
tbl-il-div = OUT := OUT ÷ IN, or IN1 ÷ IN2 (÷0: ENO = 0)
tbl-il-mod = remainder
tbl-il-add-i = INT add
tbl-il-sub-i = INT subtract
tbl-il-mul-i = INT multiply
tbl-il-div-i = INT divide
tbl-il-add-d = DINT add
tbl-il-sub-d = DINT subtract
tbl-il-mul-d = DINT multiply
tbl-il-div-d = DINT divide
tbl-il-add-r = REAL add
tbl-il-sub-r = REAL subtract
tbl-il-mul-r = REAL multiply
tbl-il-div-r = REAL divide
tbl-il-inc = if CR: OUT := OUT + 1
tbl-il-dec = if CR: OUT := OUT − 1
tbl-il-shl = OUT := OUT shifted left N bits
tbl-il-shr = OUT := OUT shifted right N bits (logical)
tbl-il-rol = OUT := OUT rotated left N bits
tbl-il-ror = OUT := OUT rotated right N bits
tbl-il-wand = OUT := OUT AND IN (bitwise)
tbl-il-andw = bitwise AND
tbl-il-wor = OUT := OUT OR IN (bitwise)
tbl-il-orw = bitwise OR
tbl-il-wxor = OUT := OUT XOR IN (bitwise)
tbl-il-xorw = bitwise XOR
tbl-il-inv = OUT := NOT OUT (bitwise)
tbl-il-sqrt = if CR: OUT := √IN (REAL); IN < 0 or NaN: ENO = 0, SM1.1, OUT unchanged; +inf: OUT = +inf, ENO = 0
tbl-il-abs = if CR: OUT := |IN| (type of OUT); −32768 / −2³¹ wrap to themselves with SM1.1 and ENO = 0; REAL NaN/inf: ENO = 0
tbl-il-swap = if CR: exchange the high and low byte of a word
tbl-il-for = FOR INDX, INIT, FINAL: if CR, run the instructions up to NEXT with INDX = INIT … FINAL (INT or DINT; INIT > FINAL: none; nesting ≤ 8)
tbl-il-next = end of a FOR loop: INDX + 1, back while INDX ≤ FINAL (FINAL re-read; at the type's maximum the loop ends)
tbl-il-i-di = INT → DINT
tbl-il-int-to-dint = INT → DINT
tbl-il-di-i = DINT → INT (out of range: ENO = 0)
tbl-il-dint-to-int = DINT → INT
tbl-il-b-i = BYTE → INT
tbl-il-i-b = INT → BYTE (out of range: ENO = 0)
tbl-il-di-r = DINT → REAL
tbl-il-round = REAL → DINT, rounded
tbl-il-trunc = REAL → DINT, truncated
tbl-il-i-bcd = INT 0…9999 → BCD (else ENO = 0)
tbl-il-bcd-i = BCD → INT (bad digit: ENO = 0)
tbl-il-jmp = jump to LABEL
tbl-il-jmpc = jump to LABEL if CR
tbl-il-jmpcn = jump to LABEL if NOT CR
tbl-il-cal = call subroutine NAME (if CR, in the K2's EN convention)
tbl-il-calc = call subroutine NAME if CR
tbl-il-calcn = call subroutine NAME if NOT CR
tbl-il-ret = return from this POU
tbl-il-retc = return if CR
tbl-il-retcn = return if NOT CR
tbl-il-cret = conditional return (S7-200 name)
tbl-il-ton = on-delay timer Tn, PT (IN = CR; CR := Q)
tbl-il-tof = off-delay timer Tn, PT
tbl-il-toff = off-delay timer (MASTER-K name)
tbl-il-tp = pulse timer Tn, PT
tbl-il-tmr = accumulating timer Tn, PT [, reset bit]
tbl-il-tonr = accumulating timer (S7-200 name)
tbl-il-tmon = monostable timer Tn, PT
tbl-il-trtg = retriggerable monostable Tn, PT
tbl-il-ctu = up counter Cn, PV [, reset bit] (CU = CR)
tbl-il-ctd = down counter Cn, PV [, load bit] (CD = CR)
tbl-il-ctud = up/down counter Cn, PV, CD bit [, reset bit]
tbl-il-ctr = ring counter Cn, PV [, reset bit]
tbl-il-atch = attach interrupt routine INT_NAME to EVENT
tbl-il-dtch = detach EVENT
tbl-il-eni = enable interrupts
tbl-il-disi = disable interrupts (events wait)
tbl-il-wdt = restart the watchdog count
tbl-il-wdr = restart the watchdog count (S7-200 name)
tbl-il-nop = nothing
tbl-il-compare = compare IN1 with IN2 and load / AND / OR the result into the CR
