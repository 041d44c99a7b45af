-- Wireshark dissector for the UMPK teaching PLC's terminal protocol, as plcsh records it
-- (docs/recording.md): LINKTYPE_USER3 (150), a 4-byte header [direction, protocol, 0, 0],
-- then the bytes as on the line (UMPK manual §4.1; src/umpk/codec.rs):
--   commands  ?NNCC            NN + CC = 0 mod 256, every byte as two hex digits
--   records   :LLAAAATTDD..CC  Intel HEX while programming (§4.2)
--   replies   R, E, U, C, L, A, W, X; #NN<data>CC packets (the bytes from NN through CC
--             sum to 0 mod 256; a plain sum is accepted too); # and 22 characters of
--             program info; 30-byte monitor packets (0xAA header); the echo of the
--             command and CR LF when echo is on.
--
--   tshark -X lua_script:lib/wireshark/umpk.lua -r umpk.pcapng -V

local p = Proto("umpk", "UMPK terminal protocol")

local commands = {
    [0x00] = "reset", [0x01] = "echo on", [0x02] = "echo off", [0x03] = "controller info",
    [0x04] = "program info", [0x05] = "input states", [0x06] = "output states",
    [0x07] = "error history", [0x08] = "clear error history", [0x09] = "enter programming",
    [0x0A] = "start monitor", [0x0B] = "stop monitor", [0x0C] = "timing figures",
}
local replies = {
    R = "ok", E = "checksum error", U = "unknown command", C = "illegal character",
    L = "data too long", A = "address out of sequence or range", W = "flash error",
    X = "programming not allowed",
}
local dirs = { [0] = "sent by plcsh", [1] = "received by plcsh" }

local f = {
    direction = ProtoField.uint8("umpk.direction", "Direction", base.DEC, dirs),
    command = ProtoField.uint8("umpk.command", "Command", base.HEX, commands),
    echo = ProtoField.string("umpk.echo", "Echo"),
    reply = ProtoField.string("umpk.reply", "Reply"),
    length = ProtoField.uint8("umpk.length", "Data length", base.DEC),
    data = ProtoField.string("umpk.data", "Data (hex)"),
    record_type = ProtoField.uint8("umpk.record_type", "HEX record type", base.DEC),
    address = ProtoField.uint16("umpk.address", "HEX record address", base.HEX),
    info = ProtoField.string("umpk.program_info", "Program info"),
    monitor = ProtoField.bytes("umpk.monitor", "Monitor packet"),
    checksum = ProtoField.uint8("umpk.checksum", "Checksum", base.HEX),
    checksum_status = ProtoField.string("umpk.checksum.status", "Checksum status"),
}
p.fields = f

local function is_hex(s) return s:match("^%x+$") ~= nil end

-- Hex pairs of s as numbers.
local function bytes_of(s)
    local out = {}
    for i = 1, #s - 1, 2 do out[#out + 1] = tonumber(s:sub(i, i + 1), 16) end
    return out
end

local function status(t, range, ok)
    local item = t:add(f.checksum_status, range, ok and "good" or "bad")
    if not ok then item:add_expert_info(PI_CHECKSUM, PI_ERROR, "checksum does not match") end
    return ok and "" or " [bad checksum]"
end

function p.dissector(buf, pinfo, tree)
    if buf:len() < 4 then return 0 end
    pinfo.cols.protocol = "UMPK"
    local t = tree:add(p, buf(), "UMPK terminal protocol")
    t:add(f.direction, buf(0, 1))
    local n = buf:len() - 4
    if n == 0 then return buf:len() end
    local s = buf(4):string()
    local info = {}
    local i = 1
    while i <= n do
        local c = s:sub(i, i)
        local at = 4 + i - 1
        if c == "?" and i + 4 <= n and is_hex(s:sub(i + 1, i + 4)) then
            local nn, cc = tonumber(s:sub(i + 1, i + 2), 16), tonumber(s:sub(i + 3, i + 4), 16)
            local sub = t:add(f.echo, buf(at, 5), s:sub(i, i + 4))
            if buf(0, 1):uint() == 0 then sub = t end
            sub:add(f.command, buf(at + 1, 2), nn)
            sub:add(f.checksum, buf(at + 3, 2), cc)
            local mark = status(sub, buf(at + 3, 2), (nn + cc) % 256 == 0)
            if buf(0, 1):uint() == 0 then
                info[#info + 1] = (commands[nn] or string.format("command %02X", nn)) .. mark
            end
            i = i + 5
        elseif c == ":" then
            local j = i + 1
            while j <= n and s:sub(j, j):match("%x") do j = j + 1 end
            local hex = s:sub(i + 1, j - 1)
            local b = bytes_of(hex)
            if #b >= 5 then
                local sum = 0
                for k = 1, #b do sum = sum + b[k] end
                t:add(f.length, buf(at + 1, 2), b[1])
                t:add(f.address, buf(at + 3, 4), b[2] * 256 + b[3])
                t:add(f.record_type, buf(at + 7, 2), b[4])
                t:add(f.checksum, buf(at + 2 * #b - 1, 2), b[#b])
                info[#info + 1] = string.format("HEX record type %d, %d bytes", b[4], b[1])
                    .. status(t, buf(at + 2 * #b - 1, 2), sum % 256 == 0)
            end
            i = j
        elseif c == "#" then
            local nn = tonumber(s:sub(i + 1, i + 2), 16)
            local want = nn and (i + 2 + 2 * nn + 2) or nil
            if nn and want <= n and is_hex(s:sub(i + 1, want)) then
                local b = bytes_of(s:sub(i + 1, want))
                local sum, plain = 0, 0
                for k = 1, #b do sum = sum + b[k] end
                for k = 2, #b - 1 do plain = plain + b[k] end
                t:add(f.length, buf(at + 1, 2), nn)
                t:add(f.data, buf(at + 3, 2 * nn), s:sub(i + 3, i + 2 + 2 * nn))
                t:add(f.checksum, buf(at + 3 + 2 * nn, 2), b[#b])
                local ok = sum % 256 == 0 or plain % 256 == b[#b] or (plain + nn) % 256 == b[#b]
                info[#info + 1] = string.format("packet, %d bytes", nn) .. status(t, buf(at + 3 + 2 * nn, 2), ok)
                i = want + 1
            else
                local len = math.min(22, n - i)
                t:add(f.info, buf(at + 1, len), s:sub(i + 1, i + len))
                info[#info + 1] = "program info"
                i = i + 1 + len
            end
        elseif buf(at, 1):uint() == 0xAA and i + 29 <= n then
            local sum = 0
            for k = 0, 29 do sum = sum + buf(at + k, 1):uint() end
            t:add(f.monitor, buf(at, 30))
            info[#info + 1] = "monitor packet" .. status(t, buf(at + 29, 1), sum % 256 == 0)
            i = i + 30
        elseif replies[c] then
            t:add(f.reply, buf(at, 1), c .. " (" .. replies[c] .. ")")
            info[#info + 1] = c .. " (" .. replies[c] .. ")"
            i = i + 1
        else
            i = i + 1 -- CR, LF, noise
        end
    end
    pinfo.cols.info = table.concat(info, "; ")
    return buf:len()
end

DissectorTable.get("wtap_encap"):add(wtap_encaps.USER3, p)
