-- The grader's `lab` table (plcsh lab check / grade; src/lab/grader.rs). The grader runs in the
-- interpreter's globals, a submission in an environment of its own that has no `lab`: what a
-- submission changes in its `plcsh`, `string` or globals the grader never sees.
local lab, points = ...
-- Everything the grader's API uses is taken now, before any submission runs.
local pcall, xpcall, error, type, tostring, setmetatable, getmetatable, rawget =
  pcall, xpcall, error, type, tostring, setmetatable, getmetatable, rawget
local format, gsub, abs, find, match, sub, gmatch =
  string.format, string.gsub, math.abs, string.find, string.match, string.sub, string.gmatch
local traceback = debug and debug.traceback
local encode, now = plcsh.json.encode, plcsh.now
local results = {}
lab._results = nil
local run_lua, load_il = lab._run_lua, lab._load_il
lab._run_lua, lab._load_il = nil, nil

-- A value as the report shows it (never an address: reports are compared byte for byte).
local function show(v)
  local t = type(v)
  if t == "string" then return format("%q", v) end
  if t == "number" then return v end -- a number stays a number in the report's JSON
  if t == "table" then
    local ok, j = pcall(encode, v)
    return ok and j or "(a table)"
  end
  if t == "number" or t == "boolean" or t == "nil" then return tostring(v) end
  return "(a " .. t .. ")"
end

local function seconds() return now() / 1000 end

local Fail = {}
Fail.__index = Fail
Fail.__tostring = function(f)
  return format("%sexpected %s, got %s", f.what and (f.what .. ": ") or "", f.expected, f.got)
end

-- lab.expect(got, expected [, what]): ends the criterion as failed unless got == expected
-- (tables compared as JSON).
function lab.expect(got, expected, what)
  local same = got == expected
  if not same and type(got) == "table" and type(expected) == "table" then same = show(got) == show(expected) end
  if not same then
    error(setmetatable({ expected = show(expected), got = show(got), what = what, at = seconds() }, Fail), 0)
  end
  return got
end

-- lab.expect_near(got, expected, tolerance [, what])
function lab.expect_near(got, expected, tol, what)
  if type(got) ~= "number" or abs(got - expected) > tol then
    error(setmetatable({ expected = show(expected) .. " ± " .. show(tol), got = show(got), what = what, at = seconds() }, Fail), 0)
  end
  return got
end

-- An error in the grader's own code, as opposed to a check that failed.
local Bug = {}

-- The submission's own chunk (its file name as Lua writes it, maybe shortened to `...tail`).
local function in_submission(src)
  local file = lab.submission
  if src == file then return true end
  if sub(src, 1, 3) == "..." then
    local tail = sub(src, 4)
    return #tail > 0 and sub(file, -#tail) == tail
  end
  return false
end

-- The message handler of a criterion: a grader error is Lua itself stopping the grader's code
-- (calling or indexing a nil, arithmetic on a nil, a library function given a bad argument)
-- in a teacher's file (the grader, the lab's modules). Everything else ends the criterion as
-- failed: lab.expect, error() and assert() (checks the grader makes), an error plcsh raises
-- (a device refusing: it is not a string), and errors in the submission's own code.
local function caught(e)
  if type(e) ~= "string" or not traceback then return e end
  local frames, n = {}, 0
  for line in gmatch(traceback("", 2), "\n%s*([^\n]*)") do
    if line ~= "stack traceback:" then
      n = n + 1
      frames[n] = line
    end
  end
  local top = frames[1]
  if not top then return e end
  if sub(top, 1, 4) == "[C]:" then
    local fn = match(top, "in function '([^']*)'")
    if fn == "error" or fn == "assert" or not find(e, "^bad argument") then return e end
    top = frames[2] -- a library function given a bad argument: its caller decides
    if not top or sub(top, 1, 4) == "[C]:" then return e end
  end
  local src = match(top, "^(.-):%d+:")
  if not src or in_submission(src) then return e end
  return setmetatable({ message = e }, Bug)
end

-- lab.criterion(name, points, fn): runs fn now; it passes when it returns anything but false
-- and raises nothing. `return false, got, expected` or lab.expect(...) say what was wrong.
function lab.criterion(name, pts, fn)
  if type(name) ~= "string" or type(fn) ~= "function" then
    error("lab.criterion(name, points, fn): a name and a function", 2)
  end
  local max = points[name] or pts or 1
  local r = { name = name, max = max, points = 0, passed = false }
  local changed = rawget(lab, "_machine_changed")
  if changed then
    -- The lab's machine is not the one the grader was written for: nothing is graded on it.
    r.error, r.at = changed, seconds()
    results[#results + 1] = r
    return false
  end
  local ok, a, b, c = xpcall(fn, caught)
  if ok and a ~= false then
    r.passed, r.points = true, max
  elseif ok then
    r.got, r.expected = b ~= nil and show(b) or "false", c ~= nil and show(c) or "true"
    r.at = seconds()
  elseif getmetatable(a) == Bug then
    r.grader_error = gsub(a.message, "\nstack traceback:.*", "")
    r.error, r.at = "grader error: " .. r.grader_error, seconds()
  elseif getmetatable(a) == Fail then
    r.got, r.expected, r.what, r.at = a.got, a.expected, a.what, a.at
  else
    r.error, r.at = gsub(tostring(a), "\nstack traceback:.*", ""), seconds()
  end
  results[#results + 1] = r
  return r.passed
end

-- lab.run(): runs the submission (a Lua script in its own environment, or an IL program
-- loaded into lab.device); returns true, or false and the error (file:line: message).
function lab.run()
  if lab.kind == "il" then return load_il(lab.submission, lab.device) end
  return run_lua(lab.submission)
end

function lab._collect() return results end
