-- require('os') gives nothing more than os.
require("os").execute("echo hi")
