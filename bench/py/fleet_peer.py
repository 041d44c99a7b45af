"""The peer of bench/fleet.sh: what a plant would write without plcsh — pymodbus's asyncio
client, one task per device on one event loop, each reading REGS holding registers in one
request every PERIOD on a fixed-rate schedule (a late poll is skipped), publishing each
register with paho as plcsh does (same topic layout and JSON payload, retained, QoS 0).

    python3 fleet_peer.py BROKER_PORT GROUP PERIOD_S REGS ADDR ADDR …   (ADDR: HOST:PORT)

The address is the holding register of VW100 on a K2 (VW0 is register 100: 150), so the
values are the ones plcsh publishes. Stops on SIGINT/SIGTERM; prints a JSON line of counts.
"""
import asyncio
import json
import signal
import sys
import time

import paho.mqtt.client as mqtt
from pymodbus.client import AsyncModbusTcpClient

FIRST = 150


async def device(i, addr, period, regs, group, mq, stats, stop):
    host, port = addr.rsplit(":", 1)
    c = AsyncModbusTcpClient(host, port=int(port), timeout=1, retries=0)
    await c.connect()
    name = "%s-%d" % (group, i + 1)
    start = time.monotonic()
    k = 0
    seq = 0
    while not stop.is_set():
        seq += 1
        try:
            r = await c.read_holding_registers(FIRST, count=regs, slave=1)
            ts = int(time.time() * 1000)
            for j in range(0, regs):
                op = "VW%d" % (100 + 2 * j)
                p = json.dumps({"value": r.registers[j], "type": "WORD", "ts": ts, "seq": seq, "device": name, "operand": op})
                mq.publish("plcsh/%s/%s/%s" % (group, name, op), p, qos=0, retain=True)
                stats["published"] += 1
        except Exception:
            stats["errors"] += 1
        k += 1
        due = start + k * period
        now = time.monotonic()
        if due < now:
            late = int((now - due) / period) + 1
            stats["skipped"] += late
            k += late
            due = start + k * period
        try:
            await asyncio.wait_for(stop.wait(), due - time.monotonic())
        except asyncio.TimeoutError:
            pass
    c.close()


async def main():
    port, group, period, regs = int(sys.argv[1]), sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
    addrs = sys.argv[5:]
    mq = mqtt.Client(client_id="fleet-peer", protocol=mqtt.MQTTv311)
    mq.max_queued_messages_set(0)
    mq.connect("127.0.0.1", port)
    mq.loop_start()
    stop = asyncio.Event()
    loop = asyncio.get_running_loop()
    for s in (signal.SIGINT, signal.SIGTERM):
        loop.add_signal_handler(s, stop.set)
    stats = {"published": 0, "errors": 0, "skipped": 0}
    await asyncio.gather(*(device(i, a, period, regs, group, mq, stats, stop) for i, a in enumerate(addrs)))
    mq.loop_stop()
    print(json.dumps(stats))


asyncio.run(main())
