-- Wireshark dissector for the Kinco servo drives' RS232 frames, as plcsh records them
-- (docs/recording.md): LINKTYPE_USER2 (149), a 4-byte header [direction, protocol, 0, 0],
-- then the 10-byte frame: drive id, function, object index (low byte first), sub-index,
-- 4 data bytes (low byte first), checksum = -(byte0 + ... + byte8) & 0xFF
-- (Kinco servo manual, RS232 protocol; src/servo/frame.rs).
--
--   tshark -X lua_script:lib/wireshark/kinco_servo.lua -r servo.pcapng -V

local p = Proto("kinco_servo", "Kinco servo RS232")

local funcs = {
    [0x23] = "write 4 bytes", [0x2B] = "write 2 bytes", [0x2F] = "write 1 byte",
    [0x40] = "read", [0x60] = "write acknowledged",
    [0x43] = "read reply, 4 bytes", [0x4B] = "read reply, 2 bytes", [0x4F] = "read reply, 1 byte",
    [0x80] = "error (abort code in the data)",
}
local sizes = { [0x23] = 4, [0x43] = 4, [0x2B] = 2, [0x4B] = 2, [0x2F] = 1, [0x4F] = 1 }
local dirs = { [0] = "sent by plcsh", [1] = "received by plcsh" }

local f = {
    direction = ProtoField.uint8("kinco_servo.direction", "Direction", base.DEC, dirs),
    id = ProtoField.uint8("kinco_servo.id", "Drive id", base.DEC),
    func = ProtoField.uint8("kinco_servo.func", "Function", base.HEX, funcs),
    index = ProtoField.uint16("kinco_servo.index", "Object index", base.HEX),
    subindex = ProtoField.uint8("kinco_servo.subindex", "Sub-index", base.HEX),
    object = ProtoField.string("kinco_servo.object", "Object"),
    data = ProtoField.uint32("kinco_servo.data", "Data", base.HEX),
    value = ProtoField.int64("kinco_servo.value", "Value", base.DEC),
    checksum = ProtoField.uint8("kinco_servo.checksum", "Checksum", base.HEX),
    checksum_status = ProtoField.string("kinco_servo.checksum.status", "Checksum status"),
}
p.fields = f

function p.dissector(buf, pinfo, tree)
    if buf:len() < 4 then return 0 end
    pinfo.cols.protocol = "KINCO"
    local t = tree:add(p, buf(), "Kinco servo RS232")
    t:add(f.direction, buf(0, 1))
    local fr = buf(4):tvb()
    if fr:len() ~= 10 then
        t:add_expert_info(PI_MALFORMED, PI_ERROR, fr:len() .. " bytes, a frame has 10")
        pinfo.cols.info = "malformed: " .. fr:len() .. " bytes"
        return buf:len()
    end
    local fc = fr(1, 1):uint()
    local index = fr(2, 2):le_uint()
    local sub = fr(4, 1):uint()
    local data = fr(5, 4):le_uint()
    local sum = 0
    for i = 0, 8 do sum = sum + fr(i, 1):uint() end
    local want = (256 - sum % 256) % 256
    local got = fr(9, 1):uint()
    t:add(f.id, fr(0, 1))
    t:add(f.func, fr(1, 1))
    t:add_le(f.index, fr(2, 2))
    t:add(f.subindex, fr(4, 1))
    local obj = string.format("%04X.%02X", index, sub)
    t:add(f.object, fr(2, 3), obj)
    t:add_le(f.data, fr(5, 4))
    local n = sizes[fc]
    local info = string.format("id %d %s %s", fr(0, 1):uint(), funcs[fc] or string.format("function %02X", fc), obj)
    if n then
        local v = data
        if n == 1 then v = data % 0x100 elseif n == 2 then v = data % 0x10000 end
        t:add(f.value, fr(5, n), Int64(v))
        info = info .. " = " .. v
    end
    t:add(f.checksum, fr(9, 1))
    if got == want then
        t:add(f.checksum_status, fr(9, 1), "good")
    else
        t:add(f.checksum_status, fr(9, 1), "bad"):add_expert_info(PI_CHECKSUM, PI_ERROR,
            string.format("checksum %02X, want %02X", got, want))
        info = info .. " [bad checksum]"
    end
    pinfo.cols.info = info
    return buf:len()
end

DissectorTable.get("wtap_encap"):add(wtap_encaps.USER2, p)
