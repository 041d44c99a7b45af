"""The independent subscriber of bench/fleet.sh: a bare MQTT 3.1.1 client on a raw socket
(paho's per-message callback would cost more than the publishers measured), subscribed to
plcsh/GROUP/#. During the window it keeps each received chunk with its arrival time and
parses afterwards, so its own cost per message is a few microseconds.

    python3 fleet_sub.py PORT GROUP START_EPOCH SECONDS DEVICES REGS RATE_HZ

Prints one JSON line: messages in the window, rate per device, poll->broker->subscriber
latency p50/p99/max (arrival minus the payload's `ts`), readings missing by `seq`
(a poll whose number never arrived for a device and operand: skipped, merged or dropped), and
messages misattributed: a value whose payload names another device or operand than its
topic (plcsh/GROUP/DEVICE/OPERAND), checked for every message received, in the window or not.
"""
import json
import socket
import struct
import sys
import time


def connect(port, cid):
    s = socket.create_connection(("127.0.0.1", port))
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 8 << 20)
    var = b"\x00\x04MQTT\x04\x02\x00\x3c"
    payload = struct.pack("!H", len(cid)) + cid
    body = var + payload
    s.sendall(b"\x10" + bytes([len(body)]) + body)
    return s


def varint(n):
    out = b""
    while True:
        b = n % 128
        n //= 128
        out += bytes([b | (0x80 if n else 0)])
        if not n:
            return out


def main():
    port, group, start, secs, devices, regs, rate = sys.argv[1:8]
    port, start, secs, devices, regs, rate = int(port), float(start), float(secs), int(devices), int(regs), float(rate)
    s = connect(port, b"fleet-sub-%d" % int(time.time() * 1000 % 1e9))
    topic = ("plcsh/%s/#" % group).encode()
    body = struct.pack("!H", 1) + struct.pack("!H", len(topic)) + topic + b"\x00"
    s.sendall(b"\x82" + varint(len(body)) + body)
    end = start + secs
    chunks = []
    s.settimeout(0.5)
    while True:
        now = time.time()
        if now >= end:
            break
        try:
            c = s.recv(1 << 20)
        except socket.timeout:
            continue
        if not c:
            break
        chunks.append((time.time(), c))
    s.close()
    # Parse: the stream is packets back to back; a packet's arrival is its chunk's (the
    # chunk in which its last byte came).
    buf = b""
    lat = []
    n = 0
    seqs = {}
    devs = set()
    misattributed = 0
    checked = 0
    for t, c in chunks:
        buf += c
        i = 0
        while True:
            if len(buf) - i < 2:
                break
            h = buf[i]
            mult, rl, j = 1, 0, i + 1
            while j < len(buf):
                b = buf[j]
                rl += (b & 0x7F) * mult
                mult *= 128
                j += 1
                if not b & 0x80:
                    break
            else:
                break
            if j + rl > len(buf):
                break
            pkt = buf[j : j + rl]
            i = j + rl
            if h >> 4 != 3 or h & 1:  # PUBLISH, not a retained replay
                continue
            tl = struct.unpack("!H", pkt[:2])[0]
            tp = pkt[2 : 2 + tl]
            off = 2 + tl + (2 if (h >> 1) & 3 else 0)
            if tp.endswith(b"/status") or tp.endswith(b"/stats") or b"/_publisher/" in tp:
                continue
            try:
                p = json.loads(pkt[off:])
            except ValueError:
                continue
            levels = tp.decode(errors="replace").split("/")
            checked += 1
            if len(levels) != 4 or p.get("device") != levels[2] or p.get("operand", "").replace("/", "_") != levels[3]:
                misattributed += 1
            if not (start <= t < end):
                continue
            n += 1
            lat.append(t * 1000 - p["ts"])
            devs.add(p["device"])
            seqs.setdefault((p["device"], p["operand"]), []).append(p["seq"])
        buf = buf[i:]
    lat.sort()
    missing = 0
    for v in seqs.values():
        v.sort()
        missing += (v[-1] - v[0] + 1) - len(set(v))
    q = lambda f: round(lat[min(len(lat) - 1, int(len(lat) * f))], 1) if lat else None
    print(json.dumps({
        "group": group, "messages": n, "devices_seen": len(devs),
        "rate_hz": round(n / max(1, devices * regs) / secs, 2),
        "offered": int(devices * regs * rate * secs),
        "latency_ms": {"p50": q(0.5), "p99": q(0.99), "max": round(lat[-1], 1) if lat else None},
        "missing_by_seq": missing,
        "checked": checked, "misattributed": misattributed,
    }))


main()
