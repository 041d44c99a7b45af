"""A Modbus TCP client that is not plcsh: polls holding registers with pymodbus and prints
one JSON line per poll, so a test can watch what a third-party client sees while the served
simulator's faults change. Usage: modbus_poller.py HOST PORT ADDRESS COUNT INTERVAL_S
Stops when its standard input closes."""

import json
import sys
import threading
import time

from pymodbus.client import ModbusTcpClient
from pymodbus.pdu import ExceptionResponse

host, port, address, count, interval = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5])
done = threading.Event()
threading.Thread(target=lambda: (sys.stdin.read(), done.set()), daemon=True).start()
client = ModbusTcpClient(host, port=port, timeout=1, retries=0)
n = 0
while not done.is_set():
    n += 1
    line = {"n": n}
    try:
        if not client.connected:
            client.connect()
        rr = client.read_holding_registers(address, count, slave=1)
        if isinstance(rr, ExceptionResponse):
            line.update(result="exception", code=rr.exception_code)
        elif rr.isError():
            line.update(result="timeout")
            client.close()
        else:
            line.update(result="ok", values=list(rr.registers))
    except Exception as e:  # a timeout or a closed connection: what the client saw
        line.update(result="timeout", error=type(e).__name__)
        client.close()
    print(json.dumps(line), flush=True)
    time.sleep(interval)
