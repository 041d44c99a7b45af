-- The grader's lab table is not in the submission.
lab.criterion = function() return true end
