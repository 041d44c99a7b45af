-- Grades UMPK lab 1 through the real-time monitor (manual §4.1.11), in virtual time:
--   start/stop latch: I0 starts, I1 stops → Q0 (and marker M0)
--   on-delay: Q1 follows Q0 after 2.0 s (timer T0, group 1, 20 × 0.1 s)
--   divide-by-4: every 4th pulse on I2 passes to Q2, exactly as long as the input pulse;
--   the stop button resets the counter
-- The program graded is an IL file run by the simulated UMPK16 on the scan engine
-- (default scripts/umpk_lab1.il, a student's file as the first argument), or the
-- simulator's built-in reference solution with the argument `reference`.
-- Run: plcsh --time stepped run scripts/umpk_lab1_grade.lua [FILE.il|reference]

local program = arg[1] or "scripts/umpk_lab1.il"
local lab = plcsh.connect("sim-umpk:UMPK16", "lab")
if program == "reference" then
  lab:umpk_sim_reference("lab1")
else
  lab:program_load(program)
end
print("grading " .. lab:program().program)
local grade = {}
local function criterion(name, ok, detail)
  grade[#grade + 1] = { name = name, ok = ok, detail = detail }
end

-- Watches `ops` for `ms` of cycles while `input` is held at `level` (nil: inputs untouched).
local function watch(ops, ms, input, level)
  if input then lab:umpk_sim_input(("%s=%d"):format(input, level)) end
  local args = { table.unpack(ops) }
  args[#args + 1] = { ms = ms - 10 }
  local m = lab:umpk_monitor(table.unpack(args))
  return m.columns
end

local function count(col, v)
  local n = 0
  for _, x in ipairs(col) do if x == v then n = n + 1 end end
  return n
end

local function rising_edges(col)
  local n, prev = 0, 0
  for _, x in ipairs(col) do
    if x == 1 and prev == 0 then n = n + 1 end
    prev = x
  end
  return n
end

criterion("program loaded, Work mode", lab:umpk_info().mode == "Work")
criterion("outputs off before start", count(watch({ "Q0", "Q1", "Q2" }, 100).Q0, 1) == 0)

-- Start: hold I0 and watch Q0 and Q1 for 2.5 s in one stream; then release it.
local run = watch({ "Q0", "Q1", "M0" }, 2500, "I0", 1)
local function first_on(col)
  for k, x in ipairs(col) do
    if x == 1 then return k end
  end
end
criterion("Q0 switches on in the first cycle of the press", run.Q0[1] == 1, run.Q0[1])
criterion("marker M0 mirrors Q0", count(run.M0, 1) == count(run.Q0, 1))
local delay = first_on(run.Q1) and (first_on(run.Q1) - first_on(run.Q0)) * 10
criterion("Q1 follows Q0 after 2.0 s (T0)", delay == 2000, delay and (delay .. " ms") or "never")
local held = watch({ "Q0", "Q1" }, 200, "I0", 0)
criterion("Q0 latches after the button is released", count(held.Q0, 0) == 0, count(held.Q0, 0))
criterion("Q1 stays on while Q0 is on", count(held.Q1, 0) == 0, count(held.Q1, 0))

-- Divide-by-4: eight 50 ms pulses (10 Hz) on I2.
lab:umpk_sim_input("I2", { freq = "10Hz" })
local div = watch({ "I2", "Q2" }, 800)
lab:umpk_sim_input("I2=0")
criterion("I2 saw eight pulses", rising_edges(div.I2) == 8, rising_edges(div.I2))
-- Which input pulses (numbered from 1) Q2 is on during.
local passed, pulse = {}, 0
for k, i in ipairs(div.I2) do
  if i == 1 and (k == 1 or div.I2[k - 1] == 0) then pulse = pulse + 1 end
  if div.Q2[k] == 1 and passed[#passed] ~= pulse then passed[#passed + 1] = pulse end
end
criterion("Q2 passes the 4th and the 8th input pulse", table.concat(passed, ", ") == "4, 8", table.concat(passed, ", "))
local same = true
for k, q in ipairs(div.Q2) do
  if q == 1 and div.I2[k] ~= 1 then same = false end
end
criterion("each Q2 pulse lasts exactly as long as its input pulse", same and count(div.Q2, 1) == 2 * 5, count(div.Q2, 1))

-- Stop: press I1; Q0 and Q1 drop at once; the counter starts over (3 pulses give nothing).
local stop = watch({ "Q0", "Q1" }, 50, "I1", 1)
lab:umpk_sim_input("I1=0")
criterion("stop drops Q0 and Q1 in the first cycle", stop.Q0[1] == 0 and stop.Q1[1] == 0)
lab:umpk_sim_input("I2", { freq = "10Hz" })
local after = watch({ "I2", "Q2" }, 300)
lab:umpk_sim_input("I2=0")
criterion("stop reset the counter", rising_edges(after.I2) == 3 and count(after.Q2, 1) == 0, count(after.Q2, 1))

local failed = {}
for _, c in ipairs(grade) do
  print(("%s  %s%s"):format(c.ok and "PASS" or "FAIL", c.name, c.detail and ("  (" .. tostring(c.detail) .. ")") or ""))
  if not c.ok then failed[#failed + 1] = c.name end
end
print(("lab 1: %d of %d criteria"):format(#grade - #failed, #grade))
plcsh.assert_eq(failed, {}, "every criterion of lab 1")
