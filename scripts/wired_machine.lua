-- The whole machine, wired: PTO0 drives the servo in pulse-train mode (gear 4:1), the
-- servo's encoder output (1250 lines per revolution = 5000 counts at 10000 increments per
-- revolution) comes back to HSC0 in A/B mode, and HSC0's CV = PV event fires where the
-- plan says. Run: plcsh --time stepped run scripts/wired_machine.lua
local plc = plcsh.device("plc")
local servo = plcsh.device("servo")
plcsh.on_abort(function() pcall(plc.pstop, plc, 0) end)
plcsh.on_abort(function() pcall(plcsh.unwire, "all") end)

local function now_us() return math.floor(plcsh.now() * 1000 + 0.5) end

-- The drive: pulse train through the gear 2508.01 / 2508.02 = 4 / 1.
servo.gear_factor = 4
servo.gear_divider = 1
servo:fault_reset()
plcsh.assert_eq(servo:mode("pulse").mode_name, "pulse")
plcsh.assert_eq(servo:enable().state, "operation enabled")
local p0 = servo.position_actual

plcsh.wire("plc:Q0.0 -> servo:pulse")
plcsh.wire("servo:encoder -> plc:I0.1,I0.0 lines=1250") -- HSC0 mode 9: A = I0.1, B = I0.0
plcsh.wire("servo:target_reached -> plc:I0.5")
plcsh.assert_eq(#plcsh.wires(), 3, "three wires")

-- 10 000 encoder counts = 20 000 increments = 5 000 pulses: 1 000 in the first segment
-- (100 µs each), then 4 000 of the second (50 µs each): 100 ms + 200 ms after the start.
plc:events()
plc:hsc(0, { mode = 9, rate = "4x", pv = 10000, cv = 0 })
plc.SMB201 = 0x40 -- clear the position counter
plc.SMB201 = 0
local t0 = now_us()
plc:profile(0, "VB3001", { { cycle = 100, count = 1000 }, { cycle = 50, count = 6000 }, { cycle = 100, count = 1000 } })
plcsh.assert_eq(plc["I0.5"], false, "moving: target not reached")

local ev = plc:wait_event("hsc0-cv=pv", 2000)
plcsh.assert_eq(ev.event.time_us - t0, 300000, "CV = PV 300 ms after the start")
plcsh.assert_eq(servo.position_actual - p0, 20000, "at the planned position")

plc:wait_event(28, 2000) -- PTO0 done
plcsh.sleep(10)
plcsh.assert_eq(plc.SMD212, 8000, "8000 pulses out")
plcsh.assert_eq(servo.position_actual - p0, 32000, "the drive moved 8000 pulses x gear 4")
plcsh.assert_eq(plc.SMD38, 16000, "HSC0 counted 32000 increments x 5000/10000")
plcsh.assert_eq(plc["I0.5"], true, "target reached, wired to I0.5")
plcsh.unwire("all")
print("wired machine: 8000 pulses -> 32000 increments -> 16000 counts; CV=PV at 300 ms")
