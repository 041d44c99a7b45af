-- Memory layout and bit groups on the simulated K2 (k2.md §2): S7 byte order, bit
-- addressing, K-groups, views, and the three ways to write a batch.
-- Run: plcsh --time stepped run scripts/memory_bits.lua

local plc = plcsh.device("plc")

-- S7 byte order: VW100's high byte is VB100.
plc.VW100 = 0x1234
plcsh.assert_eq(plc.VB100, 0x12, "VW100 high byte is VB100")
plcsh.assert_eq(plc.VB101, 0x34, "VW100 low byte is VB101")
plc.VD200 = 0x01020304
plcsh.assert_eq({ plc:get("VB200..VB203") }, { 1, 2, 3, 4 }, "VD200 bytes, most significant first")

-- Bits and bit groups: K4M0 is M0.0 … M1.7 (16 bits).
plc["K4M0"] = 0
plc["M0.0"] = true
plc["M0.3"] = 1
plcsh.assert_eq(plc.MB0, 0x09, "M0.0 and M0.3 set")
plcsh.assert_eq(plc.K1M0, 0x9, "K1M0 holds M0.0–M0.3")
plc.K4M0 = 0xA5F0
plcsh.assert_eq({ plc["M0.3"], plc["M0.4"], plc["M1.0"], plc["M1.1"] }, { false, true, true, false })
plcsh.assert_eq({ plc.MB0, plc.MB1 }, { 0xF0, 0xA5 }, "K4M0 fills M0 from its low bits")

-- Views: the same bytes as another type.
plc.VW300 = 0xFFFF
plcsh.assert_eq(plc["VW300/INT"], -1, "WORD 16#FFFF read as INT")
plc["VD304/REAL"] = 2.5
plcsh.assert_near(plc["VD304/REAL"], 2.5, 1e-6, "REAL round trip")

-- Batches: keyed (name order), pairs (given order), alternating, and the shell's syntax.
plc:set{ SMB67 = 0x85, SMW68 = 500, SMD72 = 1000 }
plcsh.assert_eq({ plc:get("SMB67", "SMW68", "SMD72") }, { 133, 500, 1000 })
plc:set({ "VW0", 1 }, { "VW0", 2 })
plcsh.assert_eq(plc.VW0, 2, "pairs are written in the order given")
plc:set("VW2", 7, "VW4", 8)
plc:set("VW6=16#85, VW8=INT#-3")
plcsh.assert_eq({ plc:get("VW2", "VW4", "VW6", "VW8/INT") }, { 7, 8, 0x85, -3 })

-- A bad batch writes nothing and names the operand.
local ok, err = pcall(plc.set, plc, { "VW10", 1 }, { "VB12", 300 })
plcsh.check(not ok, "300 does not fit a byte")
local info = plcsh.errinfo(err)
plcsh.assert_eq({ info.kind, info.device, info.operand }, { "value", "plc", "VB12" })
plcsh.assert_eq(plc.VW10, 0, "nothing was written")

-- The command language gives the same data as --json.
local set, get = plcsh.exec("set VW20=5, VW22=6; get VW20 VW22")
plcsh.assert_eq(#set.writes, 2)
plcsh.assert_eq(get.values[2], { operand = "VW22", value = 6, type = "WORD" })

print(string.format("memory_bits: %d checks passed", plcsh.checks))
