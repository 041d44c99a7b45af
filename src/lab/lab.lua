-- The grader's `lab` table (plcsh lab check / grade; src/lab/grader.rs). The grader runs in the
-- interpreter's globals, a submission in an environment of its own that has no `lab`: what a
-- submission changes in its `plcsh`, `string` or globals the grader never sees.
local lab, points = ...
-- Everything the grader's API uses is taken now, before any submission runs.
local pcall, error, type, tostring, setmetatable, getmetatable = pcall, error, type, tostring, setmetatable, getmetatable
local format, gsub, abs = string.format, string.gsub, math.abs
local encode, now = plcsh.json.encode, plcsh.now
local results = {}
lab._results = nil
local run_lua, load_il = lab._run_lua, lab._load_il
lab._run_lua, lab._load_il = nil, nil

-- A value as the report shows it (never an address: reports are compared byte for byte).
local function show(v)
  local t = type(v)
  if t == "string" then return format("%q", v) end
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

-- lab.criterion(name, points, fn): runs fn now; it passes when it returns anything but false
-- and raises nothing. `return false, got, expected` or lab.expect(...) say what was wrong.
function lab.criterion(name, pts, fn)
  if type(name) ~= "string" or type(fn) ~= "function" then
    error("lab.criterion(name, points, fn): a name and a function", 2)
  end
  local max = points[name] or pts or 1
  local r = { name = name, max = max, points = 0, passed = false }
  local ok, a, b, c = pcall(fn)
  if ok and a ~= false then
    r.passed, r.points = true, max
  elseif ok then
    r.got, r.expected = b ~= nil and show(b) or "false", c ~= nil and show(c) or "true"
    r.at = seconds()
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
