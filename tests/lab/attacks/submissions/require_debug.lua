-- require('debug') gives no hooks.
require("debug").sethook()
