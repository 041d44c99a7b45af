"""Minimal pymodbus server for the benchmark, shaped like a K2's map (holding/input
registers 0…2147, coils/discrete inputs 0…8511, unit 1).

    python3 server.py tcp      prints {"tcp":"127.0.0.1:PORT"} once listening
"""
import asyncio
import json
import socket
import sys

from pymodbus.datastore import ModbusDeviceContext, ModbusSequentialDataBlock, ModbusServerContext
from pymodbus.server import ModbusTcpServer


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


async def main() -> None:
    dev = ModbusDeviceContext(
        co=ModbusSequentialDataBlock(1, [False] * 8513),
        di=ModbusSequentialDataBlock(1, [False] * 8513),
        hr=ModbusSequentialDataBlock(1, [0] * 2149),
        ir=ModbusSequentialDataBlock(1, [0] * 2149),
    )
    ctx = ModbusServerContext(devices={1: dev}, single=False)
    port = free_port()
    server = ModbusTcpServer(ctx, address=("127.0.0.1", port))
    await server.serve_forever(background=True)
    print(json.dumps({"tcp": f"127.0.0.1:{port}"}), flush=True)
    await server.serving


if __name__ == "__main__":
    if sys.argv[1:] != ["tcp"]:
        sys.exit("usage: server.py tcp")
    asyncio.run(main())
