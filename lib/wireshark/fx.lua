-- Wireshark dissectors for the FX protocols, as plcsh records them (docs/recording.md):
-- a 4-byte header [direction, protocol, 0, 0], then the bytes as on the line.
--
-- fx_port, LINKTYPE_USER4 (151): the FX programming port (src/fx/port.rs).
--   ENQ; STX cmd addr(4 hex) count(2 hex) [data] ETX sum(2 hex), commands 0 read, 1 write;
--   STX 7|8 force-address(4 hex, low byte first) ETX sum; replies ACK, NAK, STX data ETX sum.
--   Sum check: the ASCII codes after STX through ETX, the low two hex digits.
-- fx_link, LINKTYPE_USER5 (152): the FX dedicated computer link, format 1 or 4 (src/fx/link.rs).
--   ENQ station(2) pc(2) cmd(2) wait(1) data [sum(2)] [CR LF]; replies
--   STX station pc data ETX [sum], ACK station pc, NAK station pc code(2).
--   Sum check: the ASCII codes from the station through the last data character (ETX in
--   replies), the low two hex digits; a PLC set up without sum check sends none.
--
--   tshark -X lua_script:lib/wireshark/fx.lua -r fx.pcapng -V

local ENQ, ACK, NAK, STX, ETX = 0x05, 0x06, 0x15, 0x02, 0x03
local dirs = { [0] = "sent by plcsh", [1] = "received by plcsh" }

local function sum_of(buf, from, to)
    local s = 0
    for k = from, to do s = s + buf(k, 1):uint() end
    return s % 256
end

local function hex_at(buf, at, n)
    if at + n > buf:len() then return nil end
    return tonumber(buf(at, n):string(), 16)
end

local function sum_status(t, field, range, got, want)
    local item = t:add(field, range, got == want and "good" or "bad")
    if got ~= want then
        item:add_expert_info(PI_CHECKSUM, PI_ERROR, string.format("sum check %02X, want %02X", got or 0, want))
        return " [bad sum check]"
    end
    return ""
end

-- The programming port.
local port = Proto("fx_port", "FX programming port")
local port_cmds = { ["0"] = "read", ["1"] = "write", ["7"] = "force on", ["8"] = "force off" }
local pf = {
    direction = ProtoField.uint8("fx_port.direction", "Direction", base.DEC, dirs),
    control = ProtoField.string("fx_port.control", "Control character"),
    command = ProtoField.string("fx_port.command", "Command"),
    address = ProtoField.uint16("fx_port.address", "Address", base.HEX),
    count = ProtoField.uint8("fx_port.count", "Byte count", base.DEC),
    data = ProtoField.string("fx_port.data", "Data (hex)"),
    sum = ProtoField.uint8("fx_port.sum", "Sum check", base.HEX),
    sum_status = ProtoField.string("fx_port.sum.status", "Sum check status"),
}
port.fields = pf

function port.dissector(buf, pinfo, tree)
    if buf:len() < 4 then return 0 end
    pinfo.cols.protocol = "FX"
    local t = tree:add(port, buf(), "FX programming port")
    t:add(pf.direction, buf(0, 1))
    local n = buf:len()
    -- Skip noise before the frame.
    local at = 4
    while at < n and buf(at, 1):uint() ~= STX and buf(at, 1):uint() ~= ENQ and buf(at, 1):uint() ~= ACK
        and buf(at, 1):uint() ~= NAK do
        at = at + 1
    end
    if at >= n then return n end
    local c = buf(at, 1):uint()
    if c ~= STX then
        local name = ({ [ENQ] = "ENQ", [ACK] = "ACK", [NAK] = "NAK" })[c]
        t:add(pf.control, buf(at, 1), name)
        pinfo.cols.info = name
        return n
    end
    local etx = nil
    for k = at + 1, n - 1 do
        if buf(k, 1):uint() == ETX then etx = k break end
    end
    if not etx then
        pinfo.cols.info = "STX without ETX"
        t:add_expert_info(PI_MALFORMED, PI_ERROR, "no ETX")
        return n
    end
    local info
    if buf(0, 1):uint() == 0 then
        local cmd = buf(at + 1, 1):string()
        t:add(pf.command, buf(at + 1, 1), cmd .. " (" .. (port_cmds[cmd] or "unknown") .. ")")
        if cmd == "7" or cmd == "8" then
            local lo, hi = hex_at(buf, at + 2, 2), hex_at(buf, at + 4, 2)
            if lo and hi then t:add(pf.address, buf(at + 2, 4), hi * 256 + lo) end
            info = string.format("%s %04X", port_cmds[cmd], (hi or 0) * 256 + (lo or 0))
        else
            local addr, count = hex_at(buf, at + 2, 4), hex_at(buf, at + 6, 2)
            if addr then t:add(pf.address, buf(at + 2, 4), addr) end
            if count then t:add(pf.count, buf(at + 6, 2), count) end
            if etx > at + 8 then t:add(pf.data, buf(at + 8, etx - at - 8), buf(at + 8, etx - at - 8):string()) end
            info = string.format("%s %04X x%d", port_cmds[cmd] or ("command " .. cmd), addr or 0, count or 0)
        end
    else
        if etx > at + 1 then t:add(pf.data, buf(at + 1, etx - at - 1), buf(at + 1, etx - at - 1):string()) end
        info = string.format("data %s", etx > at + 1 and buf(at + 1, etx - at - 1):string() or "")
    end
    local got = hex_at(buf, etx + 1, 2)
    if got then
        t:add(pf.sum, buf(etx + 1, 2), got)
        info = info .. sum_status(t, pf.sum_status, buf(etx + 1, 2), got, sum_of(buf, at + 1, etx))
    end
    pinfo.cols.info = info
    return n
end

-- The computer link.
local link = Proto("fx_link", "FX computer link")
local link_cmds = {
    BR = "read bits", WR = "read words", BW = "write bits", WW = "write words",
    WT = "write words at devices", RR = "remote run", RS = "remote stop", PC = "read PLC type",
    GW = "global", TT = "loopback test",
}
local lf = {
    direction = ProtoField.uint8("fx_link.direction", "Direction", base.DEC, dirs),
    control = ProtoField.string("fx_link.control", "Control character"),
    station = ProtoField.uint8("fx_link.station", "Station", base.HEX),
    pc = ProtoField.uint8("fx_link.pc", "PC number", base.HEX),
    command = ProtoField.string("fx_link.command", "Command"),
    wait = ProtoField.uint8("fx_link.wait", "Wait (x10 ms)", base.DEC),
    device = ProtoField.string("fx_link.device", "Device"),
    count = ProtoField.uint8("fx_link.count", "Points", base.DEC),
    data = ProtoField.string("fx_link.data", "Data"),
    nak = ProtoField.uint8("fx_link.nak_code", "NAK error code", base.HEX),
    sum = ProtoField.uint8("fx_link.sum", "Sum check", base.HEX),
    sum_status = ProtoField.string("fx_link.sum.status", "Sum check status"),
}
link.fields = lf

function link.dissector(buf, pinfo, tree)
    if buf:len() < 4 then return 0 end
    pinfo.cols.protocol = "FX-LINK"
    local t = tree:add(link, buf(), "FX computer link")
    t:add(lf.direction, buf(0, 1))
    local n = buf:len()
    -- Format 4 ends every message in CR LF.
    if n >= 6 and buf(n - 2, 2):uint() == 0x0D0A then n = n - 2 end
    local at = 4
    while at < n and ({ [ENQ] = 1, [ACK] = 1, [NAK] = 1, [STX] = 1 })[buf(at, 1):uint()] == nil do at = at + 1 end
    if at + 5 > n then return buf:len() end
    local c = buf(at, 1):uint()
    local name = ({ [ENQ] = "ENQ", [ACK] = "ACK", [NAK] = "NAK", [STX] = "STX" })[c]
    t:add(lf.control, buf(at, 1), name)
    local station, pc = hex_at(buf, at + 1, 2), hex_at(buf, at + 3, 2)
    if station then t:add(lf.station, buf(at + 1, 2), station) end
    if pc then t:add(lf.pc, buf(at + 3, 2), pc) end
    local info = string.format("%s station %02X", name, station or 0)
    if c == ENQ and at + 8 <= n then
        local cmd = buf(at + 5, 2):string()
        t:add(lf.command, buf(at + 5, 2), cmd .. " (" .. (link_cmds[cmd] or "unknown") .. ")")
        t:add(lf.wait, buf(at + 7, 1), hex_at(buf, at + 7, 1) or 0)
        info = info .. " " .. cmd .. " (" .. (link_cmds[cmd] or "unknown") .. ")"
        local body_end = n -- exclusive
        -- A sum check is there when the last two characters are the sum of the rest.
        local got = hex_at(buf, n - 2, 2)
        local want = sum_of(buf, at + 1, n - 3)
        local has_sum = got ~= nil and n - 2 > at + 8 and got == want
        if has_sum then body_end = n - 2 end
        if (cmd == "BR" or cmd == "WR" or cmd == "BW" or cmd == "WW") and at + 15 <= body_end then
            t:add(lf.device, buf(at + 8, 5), buf(at + 8, 5):string())
            t:add(lf.count, buf(at + 13, 2), hex_at(buf, at + 13, 2) or 0)
            info = info .. " " .. buf(at + 8, 5):string() .. " x" .. (hex_at(buf, at + 13, 2) or 0)
            if body_end > at + 15 then t:add(lf.data, buf(at + 15, body_end - at - 15), buf(at + 15, body_end - at - 15):string()) end
        elseif body_end > at + 8 then
            t:add(lf.data, buf(at + 8, body_end - at - 8), buf(at + 8, body_end - at - 8):string())
        end
        if has_sum then
            t:add(lf.sum, buf(n - 2, 2), got)
            t:add(lf.sum_status, buf(n - 2, 2), "good")
        else
            t:add(lf.sum_status, buf(at, n - at), "absent or bad")
        end
    elseif c == STX then
        local etx = nil
        for k = at + 5, n - 1 do
            if buf(k, 1):uint() == ETX then etx = k break end
        end
        if etx then
            if etx > at + 5 then t:add(lf.data, buf(at + 5, etx - at - 5), buf(at + 5, etx - at - 5):string()) end
            info = info .. " data " .. (etx > at + 5 and buf(at + 5, etx - at - 5):string() or "")
            local got = hex_at(buf, etx + 1, 2)
            if got then
                t:add(lf.sum, buf(etx + 1, 2), got)
                info = info .. sum_status(t, lf.sum_status, buf(etx + 1, 2), got, sum_of(buf, at + 1, etx))
            end
        end
    elseif c == NAK then
        local code = hex_at(buf, at + 5, 2)
        if code then
            t:add(lf.nak, buf(at + 5, 2), code)
            info = info .. string.format(" error %02X", code)
        end
    end
    pinfo.cols.info = info
    return buf:len()
end

local encap = DissectorTable.get("wtap_encap")
encap:add(wtap_encaps.USER4, port)
encap:add(wtap_encaps.USER5, link)
