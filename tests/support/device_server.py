"""A serial device server for plcsh's tests, built on pyserial (an independent RFC 2217
implementation): it opens a serial port (a served simulator's pty) and offers it on a TCP
port, either as RFC 2217 (pyserial's serial.rfc2217.PortManager does the Telnet and COM-PORT
option work) or as a raw byte relay. It binds 127.0.0.1 port 0 and prints one JSON line with
the port (readiness), then, for RFC 2217, one JSON line each time the client changes the
port's settings, so the test can see what plcsh asked for.

Usage: device_server.py rfc2217|raw SERIAL_PATH
"""
import json
import select
import socket
import sys
import termios

import serial
import serial.rfc2217


class PtySerial(serial.Serial):
    """A pty has no modem lines (TIOCMGET/TIOCMSET fail): report them as a null-modem cable
    with the lines held high, as a device server with only TX/RX/GND wired does."""

    def _reconfigure_port(self, force_update=False):
        # Linux refuses some settings (parity) on a pty; a pty carries bytes at any setting,
        # and the setting asked for is kept in this object, which is what the test checks.
        try:
            super()._reconfigure_port(force_update)
        except termios.error:
            pass

    def _update_rts_state(self):
        pass

    def _update_dtr_state(self):
        pass

    @property
    def cts(self):
        return True

    @property
    def dsr(self):
        return True

    @property
    def ri(self):
        return False

    @property
    def cd(self):
        return True


class Connection:
    """What PortManager writes its Telnet answers to."""

    def __init__(self, sock):
        self.sock = sock

    def write(self, data):
        self.sock.sendall(data)


def say(**kw):
    print(json.dumps(kw), flush=True)


def main():
    mode, path = sys.argv[1], sys.argv[2]
    port = PtySerial(path, baudrate=9600, timeout=0)
    srv = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    srv.bind(("127.0.0.1", 0))
    srv.listen(1)
    say(ready=True, port=srv.getsockname()[1], mode=mode)
    while True:
        conn, _ = srv.accept()
        conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        manager = serial.rfc2217.PortManager(port, Connection(conn)) if mode == "rfc2217" else None
        seen = None
        try:
            while True:
                r, _, _ = select.select([conn, port.fileno()], [], [], 0.05)
                if conn in r:
                    data = conn.recv(1024)
                    if not data:
                        break
                    if manager:
                        port.write(b"".join(manager.filter(data)))
                    else:
                        port.write(data)
                if port.fileno() in r:
                    data = port.read(1024)
                    if data:
                        conn.sendall(b"".join(manager.escape(data)) if manager else data)
                now = (port.baudrate, port.bytesize, port.parity, port.stopbits)
                if manager and now != seen:
                    seen = now
                    say(baud=port.baudrate, bits=port.bytesize, parity=port.parity, stop=port.stopbits)
        except OSError as e:
            print(json.dumps({"closed": str(e)}), file=sys.stderr, flush=True)
        conn.close()


if __name__ == "__main__":
    main()
