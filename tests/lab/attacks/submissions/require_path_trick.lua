-- A module name that is a path: refused like any path.
require("../lab/reference")
