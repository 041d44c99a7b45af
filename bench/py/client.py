"""pymodbus clients for the benchmark: read REGS holding registers from address 100 (VW0
on a K2), one request in flight, COUNT times or for SECONDS; print one JSON line of figures.

    python3 client.py sync|async tcp HOST:PORT REGS COUNT SECONDS
    python3 client.py sync|async rtu PATH REGS COUNT SECONDS
    python3 client.py once tcp HOST:PORT          (read 10 registers and exit)
"""
import asyncio
import json
import sys
import time

from pymodbus.client import AsyncModbusSerialClient, AsyncModbusTcpClient, ModbusSerialClient, ModbusTcpClient


def figures(lat, secs):
    lat.sort()
    n = len(lat)
    return {
        "n": n,
        "secs": secs,
        "p50_us": lat[n // 2] * 1e6,
        "p90_us": lat[n * 9 // 10] * 1e6,
        "p99_us": lat[n * 99 // 100] * 1e6,
        "max_us": lat[-1] * 1e6,
    }


def make(kind, link, target):
    if link == "tcp":
        host, port = target.rsplit(":", 1)
        return (ModbusTcpClient if kind != "async" else AsyncModbusTcpClient)(host, port=int(port))
    cls = ModbusSerialClient if kind != "async" else AsyncModbusSerialClient
    return cls(target, baudrate=115200)


def run_sync(client, regs, count, secs):
    client.connect()
    lat = []
    start = t = time.perf_counter()
    while len(lat) < count and t - start < secs:
        t0 = time.perf_counter()
        r = client.read_holding_registers(100, count=regs, device_id=1)
        if r.isError():
            sys.exit(f"read: {r}")
        t = time.perf_counter()
        lat.append(t - t0)
    client.close()
    return figures(lat, t - start)


async def run_async(kind, link, target, regs, count, secs):
    client = make(kind, link, target)  # async clients need the running loop
    await client.connect()
    lat = []
    start = t = time.perf_counter()
    while len(lat) < count and t - start < secs:
        t0 = time.perf_counter()
        r = await client.read_holding_registers(100, count=regs, device_id=1)
        if r.isError():
            sys.exit(f"read: {r}")
        t = time.perf_counter()
        lat.append(t - t0)
    client.close()
    return figures(lat, t - start)


def main():
    kind, link, target = sys.argv[1:4]
    if kind == "once":
        client = make(kind, link, target)
        client.connect()
        r = client.read_holding_registers(100, count=10, device_id=1)
        print(" ".join(str(v) for v in r.registers))
        client.close()
        return
    regs, count, secs = int(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6])
    if kind == "sync":
        out = run_sync(make(kind, link, target), regs, count, secs)
    else:
        out = asyncio.run(run_async(kind, link, target, regs, count, secs))
    print(json.dumps(out), flush=True)


if __name__ == "__main__":
    main()
