-- A module of the lab's own: graders (and submissions) may require it.
local M = {}

-- true when the PLC runs a program, else false, what it runs, and what was expected.
function M.running(plc)
  local p = plc:program()
  if p.mode ~= "RUN" or not p.program then return false, p.program or "no program", "a program in RUN" end
  return true
end

return M
