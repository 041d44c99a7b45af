-- commission.lua — a commissioning step runner with a printed checklist and a report.
--
--   local commission = require("commission")
--   local c = commission.new("Axis X, cabinet 3", {report = "axis-x.html", operator = "A. Petrov", site = "Line 2"})
--   c:attach_params(servo, "axis-x-reference.toml")   -- the drive's differences from a reference set
--   c:step("PTO0 configured", function()
--     plc:set("SMB67=16#85, SMW68=500, SMD72=1000")
--     plcsh.assert_eq(plc.SMB67, 0x85)
--     c:measure("SMW68", plc.SMW68, "us")   -- a value measured, shown in the report
--     c:note("cycle from the drawing E-12")  -- a remark on this step
--     return "SMB67 = 16#85"                 -- an optional note (a table: values measured)
--   end)
--   c:step("Move", function() c:trace{plc, "SMD38", "servo:position_actual", every = 10, ["for"] = 500} end)
--   c:step("Limit switch wired", function() ... end, {optional = true})
--   c:run()                             -- prints the checklist, writes the report; raises if a step failed
--
-- A failed step stops the run (later steps are shown as skipped) unless the step is
-- optional or the runner was made with {keep_going = true}. A step's time is virtual time
-- (plcsh.now), so on a stepped simulator it shows machine time, not wall time.
-- Ctrl-C is not a failure: it goes straight through to the script's plcsh.on_abort handlers.
--
-- The report (docs/commissioning.md): with `report = FILE` (or `plcsh run --report FILE`,
-- which wins), run() writes FILE (HTML) and its JSON twin. Everything it holds is recorded
-- here as data — steps, notes, measured values, command results (`c:record`), parameter sets
-- (`c:attach_params`, `c:params_save`, `c:params_load`) and curves (`c:trace`) — and the
-- devices and the log of every write plcsh made come from the session (`plcsh.report`).

local M = {}
M.__index = M

-- An unknown option key is an error (a misspelt `optional` would otherwise be ignored).
local function check_opts(opts, known, what)
  for k in pairs(opts or {}) do
    if not known[k] then
      local names = {}
      for n in pairs(known) do names[#names + 1] = n end
      table.sort(names)
      error(string.format("%s: unknown option `%s` (options: %s)", what, tostring(k), table.concat(names, ", ")), 3)
    end
  end
end

--- A new checklist. opts: keep_going (run every step even after a failure); report (the HTML
--- file to write, its JSON twin beside it), operator, site (shown in the report).
function M.new(title, opts)
  check_opts(opts, { keep_going = true, report = true, operator = true, site = true }, "commission.new")
  opts = opts or {}
  local self = setmetatable({
    title = title or "commissioning",
    steps = {},
    opts = opts,
    notes = {},
    params = {},
    traces = {},
    references = {},
  }, M)
  local found, report = pcall(function() return plcsh.report end) -- a sandbox may leave it out
  report = found and report or nil
  local asked = report and report.path()
  self.report_path = asked or opts.report
  if self.report_path then
    assert(report, "commission.new: this run cannot write a report (no plcsh.report)")
    if not asked then
      report.begin() -- the write log starts here (with --report it started with the run)
    end
  end
  return self
end

--- Adds a step. fn may return a note (a string or a number) for the checklist, or a table of
--- values it measured ({name = value}).
--- opts: optional (a failure is reported but does not stop the run or fail it).
function M:step(name, fn, opts)
  assert(type(name) == "string", "step name must be a string")
  assert(type(fn) == "function", "step '" .. name .. "' needs a function")
  check_opts(opts, { optional = true }, "step '" .. name .. "'")
  self.steps[#self.steps + 1] = { name = name, fn = fn, opts = opts or {} }
  return self
end

--- A remark: on the step running now, or on the whole run outside a step.
function M:note(text)
  local list = self.current and self.current.notes or self.notes
  list[#list + 1] = tostring(text)
  return self
end

--- A value the running step measured (shown with the step), with an optional unit.
function M:measure(name, value, unit)
  assert(self.current, "c:measure is for use inside a step")
  local v = self.current.values
  v[#v + 1] = { name = tostring(name), value = value, unit = unit }
  return value
end

--- Keeps a command's result (a device method's table: the object --json shows) with the
--- running step; returns it.
function M:record(result)
  assert(self.current, "c:record is for use inside a step")
  local r = self.current.results
  r[#r + 1] = result
  return result
end

local function step_no(self)
  return self.current and self.current.n or nil
end

--- Records a curve: c:trace{dev, "OP1", "OP2", every = 10, ["for"] = 1000, title = …, units = {OP1 = "Hz"}}
--- samples the operands with dev:trace (the `trace` command); c:trace{title = …, samples = r}
--- keeps a trace already taken. Returns the trace's result.
function M:trace(spec)
  assert(type(spec) == "table", "c:trace takes a table: c:trace{plc, \"VW0\", every = 10, [\"for\"] = 1000}")
  check_opts(
    (function()
      local o = {}
      for k in pairs(spec) do
        if type(k) ~= "number" then o[k] = true end
      end
      return o
    end)(),
    { every = true, ["for"] = true, count = true, title = true, units = true, samples = true },
    "c:trace"
  )
  local r = spec.samples
  local ops = {}
  for i = 2, #spec do ops[#ops + 1] = spec[i] end
  if r == nil then
    local dev = spec[1]
    assert(dev ~= nil and #ops > 0, "c:trace{dev, operand…}: a device and at least one operand")
    local o = {}
    if spec.every then o.every = spec.every end
    if spec["for"] then o["for"] = spec["for"] end
    if spec.count then o.count = spec.count end
    ops[#ops + 1] = o
    r = dev:trace(table.unpack(ops))
    ops[#ops] = nil
  end
  local title = spec.title or table.concat(ops, ", ")
  self.traces[#self.traces + 1] = { step = step_no(self), title = title, t_s = r.t_s, series = r.series, units = spec.units or {} }
  return r
end

--- Compares `drive`'s parameters with the set in `reference_file` (`servo params diff`), keeps
--- the differences for the report, and makes the file the reference of the drive's later
--- c:params_save / c:params_load. Returns the command's result.
function M:attach_params(drive, reference_file)
  local name = drive:name()
  self.references[name] = reference_file
  local r = drive:params_diff(reference_file)
  self.params[#self.params + 1] = {
    step = step_no(self),
    device = name,
    action = "compared",
    reference = reference_file,
    differences = r.differences or {},
    result = r,
  }
  return r
end

local function after(self, drive, action, file, r)
  local name = drive:name()
  local ref = self.references[name]
  local diff = ref and drive:params_diff(ref) or nil
  self.params[#self.params + 1] = {
    step = step_no(self),
    device = name,
    action = action,
    file = file,
    reference = ref,
    differences = diff and diff.differences or {},
    result = r,
  }
  return r
end

--- Saves the drive's parameter set to `file` (`servo params save`), with its differences from
--- the drive's reference when one is attached.
function M:params_save(drive, file, ...)
  local args = { file, ... }
  return after(self, drive, "saved", file, drive:params_save(table.concat(args, " ")))
end

--- Loads `file` onto the drive (`servo params load`; opts: store), then compares with the
--- reference when one is attached.
function M:params_load(drive, file, opts)
  return after(self, drive, "loaded", file, drive:params_load(file, opts or {}))
end

--- A failure as one line for the table: a failed check's following lines (`actual: 0`,
--- `expected: 5`) are kept, joined with "; ".
local function one_line(err)
  local parts = {}
  for line in tostring(err):gmatch("[^\n]+") do
    local t = line:match("^%s*(.-)%s*$")
    if t ~= "" and not t:match("^stack traceback") and not t:match("^%[C%]") and not line:match("^\t") then
      parts[#parts + 1] = t
    end
  end
  return table.concat(parts, "; ")
end

--- What a failed check expected and what it measured (plcsh.assert_eq/assert_near's lines).
local function expected_measured(err)
  local text = tostring(err)
  return text:match("\n%s*expected:%s*([^\n]*)"), text:match("\n%s*actual:%s*([^\n]*)")
end

local function sorted_values(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  table.sort(keys, function(a, b) return tostring(a) < tostring(b) end)
  local out = {}
  for _, k in ipairs(keys) do out[#out + 1] = { name = tostring(k), value = t[k] } end
  return out
end

-- What each device reports about itself beyond its model and address: a drive its state
-- (`servo status`). (A K2's clock is left out: a simulated one follows the host's clock, and
-- a rehearsal's report must not change with the second it ran in.)
local function device_reports()
  local out = {}
  for _, info in ipairs(plcsh.devices()) do
    if info.family == "servo" then
      local d = plcsh.device(info.name)
      local ok, r = pcall(d.status, d)
      if ok and type(r) == "table" then out[info.name] = r end
    end
  end
  return out
end

--- Runs the steps in order, prints the checklist and a summary table, and writes the report
--- when one was asked for.
--- Returns the results {name, status = "ok"|"FAILED"|"skipped", note, ms}; raises when a
--- required step failed, so the script (and `plcsh run`'s exit status) fails.
function M:run()
  print("== " .. self.title .. " ==")
  local results, failed, stop = {}, 0, false
  local record = {}
  for i, s in ipairs(self.steps) do
    local r = { step = i, name = s.name }
    local rec = { n = i, name = s.name, optional = s.opts.optional == true, notes = {}, values = {}, results = {} }
    if stop then
      r.status = "skipped"
      rec.result = "skipped"
      print(string.format("[-] %d. %s (skipped)", i, s.name))
    else
      local t0 = plcsh.now()
      self.current = rec
      local ok, note = pcall(s.fn)
      self.current = nil
      r.ms = plcsh.now() - t0
      rec.started_ms, rec.duration_ms = t0, r.ms
      if ok then
        r.status = "ok"
        rec.result = "ok"
        if type(note) == "table" then
          for _, v in ipairs(sorted_values(note)) do rec.values[#rec.values + 1] = v end
          note = nil
        end
        r.note = note ~= nil and tostring(note) or nil
        rec.note = r.note
        print(string.format("[x] %d. %s%s", i, s.name, r.note and (" — " .. r.note) or ""))
      else
        r.status = s.opts.optional and "failed (optional)" or "FAILED"
        rec.result = s.opts.optional and "failed-optional" or "failed"
        r.note = one_line(note)
        r.error = note
        rec.note = r.note
        rec.error = tostring(note)
        rec.expected, rec.measured = expected_measured(note)
        print(string.format("[ ] %d. %s — %s: %s", i, s.name, r.status, tostring(note)))
        if not s.opts.optional then
          failed = failed + 1
          stop = not self.opts.keep_going
        end
      end
    end
    results[#results + 1] = r
    record[#record + 1] = rec
  end
  local rows = {}
  for _, r in ipairs(results) do
    -- Numbers stay numbers (JSON rows keep them): the step and its time in ms to 0.1.
    rows[#rows + 1] = { r.step, r.name, r.status, r.ms and math.floor(r.ms * 10 + 0.5) / 10 or "", r.note or "" }
  end
  plcsh.table(rows, { "#", "step", "status", "ms", "note" })
  local done = 0
  for _, r in ipairs(results) do
    if r.status == "ok" then done = done + 1 end
  end
  print(string.format("%d of %d steps done, %d failed", done, #results, failed))
  self.results = results
  if self.report_path then
    local files = plcsh.report.write({
      title = self.title,
      site = self.opts.site,
      operator = self.opts.operator,
      steps = record,
      notes = self.notes,
      params = self.params,
      traces = self.traces,
      reports = device_reports(),
    }, self.report_path)
    self.report = files
    print("report: " .. files.html .. " (" .. files.json .. ")")
  end
  if failed > 0 then
    error(string.format("%s: %d step(s) failed", self.title, failed), 2)
  end
  return results
end

return M
