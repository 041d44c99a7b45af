-- The message of a missing module names no folder outside the submission's view.
require("nothing_here")
