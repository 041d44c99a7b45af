-- The grader is not a module of the submission.
require("grade")
