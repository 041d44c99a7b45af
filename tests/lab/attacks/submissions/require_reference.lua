-- The reference solution is not a module.
require("reference")
