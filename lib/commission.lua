-- commission.lua — a commissioning step runner with a printed checklist.
--
--   local commission = require("commission")
--   local c = commission.new("Axis X, cabinet 3")
--   c:step("PTO0 configured", function()
--     plc:set("SMB67=16#85, SMW68=500, SMD72=1000")
--     plcsh.assert_eq(plc.SMB67, 0x85)
--     return "SMB67 = 16#85"            -- an optional note shown in the checklist
--   end)
--   c:step("Limit switch wired", function() ... end, {optional = true})
--   c:run()                             -- prints the checklist; raises if a step failed
--
-- A failed step stops the run (later steps are shown as skipped) unless the step is
-- optional or the runner was made with {keep_going = true}. A step's time is virtual time
-- (plcsh.now), so on a stepped simulator it shows machine time, not wall time.
-- Ctrl-C is not a failure: it goes straight through to the script's plcsh.on_abort handlers.

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

--- A new checklist. opts: keep_going (run every step even after a failure).
function M.new(title, opts)
  check_opts(opts, { keep_going = true }, "commission.new")
  return setmetatable({ title = title or "commissioning", steps = {}, opts = opts or {} }, M)
end

--- Adds a step. fn may return a note (a string or a number) for the checklist.
--- opts: optional (a failure is reported but does not stop the run or fail it).
function M:step(name, fn, opts)
  assert(type(name) == "string", "step name must be a string")
  assert(type(fn) == "function", "step '" .. name .. "' needs a function")
  check_opts(opts, { optional = true }, "step '" .. name .. "'")
  self.steps[#self.steps + 1] = { name = name, fn = fn, opts = opts or {} }
  return self
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

--- Runs the steps in order, prints the checklist and a summary table.
--- Returns the results {name, status = "ok"|"FAILED"|"skipped", note, ms}; raises when a
--- required step failed, so the script (and `plcsh run`'s exit status) fails.
function M:run()
  print("== " .. self.title .. " ==")
  local results, failed, stop = {}, 0, false
  for i, s in ipairs(self.steps) do
    local r = { step = i, name = s.name }
    if stop then
      r.status = "skipped"
      print(string.format("[-] %d. %s (skipped)", i, s.name))
    else
      local t0 = plcsh.now()
      local ok, note = pcall(s.fn)
      r.ms = plcsh.now() - t0
      if ok then
        r.status = "ok"
        r.note = note ~= nil and tostring(note) or nil
        print(string.format("[x] %d. %s%s", i, s.name, r.note and (" — " .. r.note) or ""))
      else
        r.status = s.opts.optional and "failed (optional)" or "FAILED"
        r.note = one_line(note)
        r.error = note
        print(string.format("[ ] %d. %s — %s: %s", i, s.name, r.status, tostring(note)))
        if not s.opts.optional then
          failed = failed + 1
          stop = not self.opts.keep_going
        end
      end
    end
    results[#results + 1] = r
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
  if failed > 0 then
    error(string.format("%s: %d step(s) failed", self.title, failed), 2)
  end
  return results
end

return M
