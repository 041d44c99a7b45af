"""A Modbus TCP client that is not plcsh: runs requests with pymodbus and prints one JSON line
per request with what the client saw, so a test can check the served K2's Modbus map the way
a third-party master addresses it. Usage: modbus_map_probe.py HOST PORT; requests arrive on
standard input, one JSON object a line:
  {"op": "rc"|"rdi"|"rhr"|"rir", "a": ADDRESS, "n": COUNT}
  {"op": "wc", "a": ADDRESS, "v": [bools]}   {"op": "wr", "a": ADDRESS, "v": [words]}
  {"op": "until_hr"|"until_c", "a": ADDRESS, "v": VALUE}  (polls up to 10 s for VALUE)"""

import json
import sys
import time

from pymodbus.client import ModbusTcpClient
from pymodbus.pdu import ExceptionResponse

host, port = sys.argv[1], int(sys.argv[2])
client = ModbusTcpClient(host, port=port, timeout=2, retries=0)
client.connect()


def answer(rr, bits=None, n=0):
    if isinstance(rr, ExceptionResponse):
        return {"result": "exception", "code": rr.exception_code}
    if rr.isError():
        return {"result": "error", "text": str(rr)}
    if bits is True:
        return {"result": "ok", "values": [bool(b) for b in rr.bits[:n]]}
    if bits is False:
        return {"result": "ok", "values": list(rr.registers)}
    return {"result": "ok"}


for line in sys.stdin:
    q = json.loads(line)
    op, a = q["op"], q["a"]
    try:
        if op == "rc":
            out = answer(client.read_coils(a, q["n"], slave=1), True, q["n"])
        elif op == "rdi":
            out = answer(client.read_discrete_inputs(a, q["n"], slave=1), True, q["n"])
        elif op == "rhr":
            out = answer(client.read_holding_registers(a, q["n"], slave=1), False)
        elif op == "rir":
            out = answer(client.read_input_registers(a, q["n"], slave=1), False)
        elif op == "wc":
            out = answer(client.write_coils(a, q["v"], slave=1))
        elif op == "wr":
            out = answer(client.write_registers(a, q["v"], slave=1))
        elif op in ("until_hr", "until_c"):
            end = time.monotonic() + 10
            out = {"result": "timeout"}
            while time.monotonic() < end:
                if op == "until_hr":
                    rr = client.read_holding_registers(a, 1, slave=1)
                    got = None if rr.isError() else rr.registers[0]
                else:
                    rr = client.read_coils(a, 1, slave=1)
                    got = None if rr.isError() else bool(rr.bits[0])
                if got == q["v"]:
                    out = {"result": "ok", "values": [got]}
                    break
                time.sleep(0.01)
        else:
            out = {"result": "error", "text": "unknown op " + op}
    except Exception as e:  # what the client saw
        out = {"result": "error", "text": type(e).__name__ + ": " + str(e)}
    print(json.dumps(out), flush=True)
