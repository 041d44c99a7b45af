-- The parts of the plcsh Lua API that read best in Lua: print through the shell's output,
-- checks that make scripts double as tests, and small conveniences over plcsh.exec.
-- Loaded once per Lua state, after the Rust modules (src/script/mod.rs).

local plcsh = plcsh
local write, select, tostring, type, error = plcsh._write, select, tostring, type, error

-- Ctrl-C must reach the top even through pcall: a protected call that failed while the
-- script is being interrupted re-raises (the hook would otherwise be caught forever).
-- A caught error is explained as at top level (`plc.get(…)` with a dot: use a colon).
local rawpcall, rawxpcall, rawresume, stopping = pcall, xpcall, coroutine.resume, plcsh._interrupted
local explain = plcsh._explain
local function pass(ok, ...)
  if not ok and stopping() then error((...), 0) end
  if not ok then return ok, explain((...)), select(2, ...) end
  return ok, ...
end
function pcall(f, ...) return pass(rawpcall(f, ...)) end
function xpcall(f, handler, ...)
  return pass(rawxpcall(f, function(e) return handler(explain(e)) end, ...))
end
function coroutine.resume(co, ...) return pass(rawresume(co, ...)) end

local show

-- A table without its own __tostring prints its contents ({1, 2, a=3}), not table: 0x….
local function text(v)
  if type(v) == "table" and not (getmetatable(v) and getmetatable(v).__tostring) then
    return show(v)
  end
  return tostring(v)
end

-- print goes through the shell's output (a JSON line under --json).
function print(...)
  local n = select("#", ...)
  local parts = {}
  for i = 1, n do
    parts[i] = text((select(i, ...)))
  end
  write(table.concat(parts, "\t"))
end

-- plcsh.log(...): printed like print, with the wall time and the session time in front, and
-- appended to the file plcsh.log_to(path) chose (the run's record for the commissioning file).
local log_file
function plcsh.log_to(path)
  if log_file then log_file:close() end
  -- Binary: the same bytes (LF line ends) on every system, for the tools that read the file.
  log_file = assert(io.open(path, "ab"))
  return path
end
function plcsh.log(...)
  local parts = {}
  for i = 1, select("#", ...) do
    parts[i] = text((select(i, ...)))
  end
  local line = string.format("%s t=%.3fs %s", os.date("%Y-%m-%d %H:%M:%S"), plcsh.now() / 1000,
    table.concat(parts, "\t"))
  if log_file then
    log_file:write(line, "\n")
    log_file:flush()
  end
  write(line)
end

show = function(v, depth)
  depth = depth or 0
  if type(v) == "string" then
    return string.format("%q", v)
  elseif type(v) ~= "table" or depth > 3 then
    return tostring(v)
  end
  -- The sequence 1..n first, in order; then the other keys sorted, numbers as [k]=.
  local parts, n = {}, 0
  while rawget(v, n + 1) ~= nil do
    n = n + 1
    parts[n] = show(v[n], depth + 1)
  end
  local keys = {}
  for k in pairs(v) do
    if not (math.type(k) == "integer" and k >= 1 and k <= n) then keys[#keys + 1] = k end
  end
  table.sort(keys, function(a, b)
    if type(a) == type(b) and type(a) ~= "table" and type(a) ~= "boolean" then return a < b end
    return type(a) < type(b)
  end)
  for _, k in ipairs(keys) do
    local name = (type(k) == "string" and k:match("^[%a_][%w_]*$")) and k or ("[" .. show(k, depth + 1) .. "]")
    parts[#parts + 1] = name .. "=" .. show(v[k], depth + 1)
  end
  return "{" .. table.concat(parts, ", ") .. "}"
end
plcsh.show = show

local function equal(a, b)
  if a == b then return true end
  if type(a) == "number" and type(b) == "number" then return a == b end
  if type(a) ~= "table" or type(b) ~= "table" then return false end
  for k, v in pairs(a) do
    if not equal(v, b[k]) then return false end
  end
  for k in pairs(b) do
    if a[k] == nil then return false end
  end
  return true
end

plcsh.checks = 0
plcsh.checks_failed = 0

local function fail(what, msg, detail)
  plcsh.checks_failed = plcsh.checks_failed + 1
  local text = what .. " failed" .. (msg and (": " .. tostring(msg)) or "")
  if detail then text = text .. "\n" .. detail end
  error(text, 3)
end

-- plcsh.assert_eq(actual, expected, msg): deep equality; the error shows both values.
function plcsh.assert_eq(actual, expected, msg)
  plcsh.checks = plcsh.checks + 1
  if not equal(actual, expected) then
    fail("assert_eq", msg, "  actual:   " .. show(actual) .. "\n  expected: " .. show(expected))
  end
  return actual
end

-- plcsh.assert_near(actual, expected, tolerance, msg): |actual - expected| <= tolerance.
function plcsh.assert_near(actual, expected, tolerance, msg)
  plcsh.checks = plcsh.checks + 1
  if type(actual) ~= "number" or math.abs(actual - expected) > tolerance then
    fail("assert_near", msg, "  actual:   " .. show(actual) .. "\n  expected: " .. show(expected)
      .. " ± " .. tostring(tolerance))
  end
  return actual
end

-- plcsh.check(condition, msg): like assert, counted, reported at the caller's line.
function plcsh.check(cond, msg, ...)
  plcsh.checks = plcsh.checks + 1
  if not cond then
    fail("check", msg, select("#", ...) > 0 and ("  values: " .. show({...})) or nil)
  end
  return cond
end

-- plcsh.devices(): the open devices ({name, family, model, url, simulated, current}).
function plcsh.devices()
  return plcsh.exec("devices").devices
end
