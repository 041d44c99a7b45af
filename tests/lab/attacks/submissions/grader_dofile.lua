-- Running the teacher's grade.lua (dofile of the grader).
local tries = { "tests/lab/attacks/lab/grade.lua", "../lab/grade.lua", "lab/grade.lua", "../../attacks/lab/grade.lua" }
local last
for _, p in ipairs(tries) do
  local ok, e = pcall(function() dofile(p) end)
  if ok then return end
  last = e
end
error(last, 0)
