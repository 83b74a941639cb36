"""A small OSCQuery client with nothing beyond Python's standard library, for the tests: the namespace
over HTTP, OSC over UDP, and the WebSocket (its handshake and frames written here) that streams values
after LISTEN as binary OSC messages."""
import base64
import hashlib
import http.client
import json
import os
import socket
import struct

WEBSOCKET_GUID = b"258EAFA5-E914-47DA-95CA-C5AB0DC85B11"


def _pad(data):
    return data + b"\0" * (4 - len(data) % 4)


def osc_message(address, *args):
    """An OSC message: ints as i, floats as f, strings as s, True/False as T/F, None as N."""
    tags, body = ",", b""
    for arg in args:
        if arg is True or arg is False:
            tags += "T" if arg else "F"
        elif arg is None:
            tags += "N"
        elif isinstance(arg, int):
            tags, body = tags + "i", body + struct.pack(">i", arg)
        elif isinstance(arg, float):
            tags, body = tags + "f", body + struct.pack(">f", arg)
        else:
            tags, body = tags + "s", body + _pad(str(arg).encode())
    return _pad(address.encode()) + _pad(tags.encode()) + body


def _string(data, at):
    end = data.index(b"\0", at)
    return data[at:end].decode(), (end // 4 + 1) * 4


def parse_osc(data):
    """(address, [arguments]) of an OSC message with i f s T F arguments."""
    address, at = _string(data, 0)
    tags, at = _string(data, at)
    args = []
    for tag in tags[1:]:
        if tag == "i":
            args.append(struct.unpack(">i", data[at:at + 4])[0]); at += 4
        elif tag == "f":
            args.append(struct.unpack(">f", data[at:at + 4])[0]); at += 4
        elif tag == "s":
            text, at = _string(data, at); args.append(text)
        elif tag in "TF":
            args.append(tag == "T")
        else:
            raise ValueError(f"unexpected OSC type {tag!r}")
    return address, args


def send_osc(port, message, host="127.0.0.1", source=None):
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        if source:
            sock.bind((source, 0))
        sock.sendto(message, (host, port))


def get(port, target, host="127.0.0.1", headers=None, source=None):
    """(status, body) of GET target; `source` sends from that local address."""
    connection = http.client.HTTPConnection(host, port, timeout=5, source_address=(source, 0) if source else None)
    try:
        connection.request("GET", target, headers=headers or {})
        response = connection.getresponse()
        return response.status, response.read()
    finally:
        connection.close()


def get_json(port, target, **kwargs):
    status, body = get(port, target, **kwargs)
    if status != 200:
        raise AssertionError(f"GET {target}: {status} {body[:200]!r}")
    return json.loads(body)


class WebSocket:
    """A client WebSocket (RFC 6455): masked frames out, unmasked frames in, pings answered."""

    def __init__(self, port, target="/", host="127.0.0.1", timeout=5, source=None):
        self.sock = socket.create_connection((host, port), timeout=timeout,
                                             source_address=(source, 0) if source else None)
        key = base64.b64encode(os.urandom(16))
        self.sock.sendall(b"GET " + target.encode() + b" HTTP/1.1\r\nHost: " + f"{host}:{port}".encode() +
                          b"\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: " + key +
                          b"\r\nSec-WebSocket-Version: 13\r\n\r\n")
        head = b""
        while b"\r\n\r\n" not in head:
            chunk = self.sock.recv(1)
            if not chunk:
                raise ConnectionError("closed during the handshake")
            head += chunk
        self.status = int(head.split(b" ", 2)[1])
        accept = base64.b64encode(hashlib.sha1(key + WEBSOCKET_GUID).digest())
        if self.status == 101 and b"sec-websocket-accept: " + accept.lower() not in head.lower():
            raise ConnectionError("the server's Sec-WebSocket-Accept does not match the key")

    def send(self, payload, opcode=None):
        if isinstance(payload, str):
            payload, opcode = payload.encode(), opcode or 1
        opcode = opcode or 2
        mask = os.urandom(4)
        size = len(payload)
        header = bytes([0x80 | opcode])
        if size < 126:
            header += bytes([0x80 | size])
        elif size < 65536:
            header += bytes([0x80 | 126]) + struct.pack(">H", size)
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", size)
        masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
        self.sock.sendall(header + mask + masked)

    def command(self, name, path):
        self.send(json.dumps({"COMMAND": name, "DATA": path}))

    def _exactly(self, size):
        data = b""
        while len(data) < size:
            chunk = self.sock.recv(size - len(data))
            if not chunk:
                raise ConnectionError("closed")
            data += chunk
        return data

    def receive(self, timeout=5):
        """(opcode, payload) of the next data frame; None when the server closed the connection or
        nothing came within `timeout` seconds."""
        self.sock.settimeout(timeout)
        try:
            while True:
                first, second = self._exactly(2)
                size = second & 0x7F
                if size == 126:
                    size = struct.unpack(">H", self._exactly(2))[0]
                elif size == 127:
                    size = struct.unpack(">Q", self._exactly(8))[0]
                payload = self._exactly(size)
                opcode = first & 0x0F
                if opcode == 8:
                    return None
                if opcode == 9:
                    self.send(payload, opcode=10)
                    continue
                if opcode in (1, 2):
                    return opcode, payload
        except (socket.timeout, ConnectionError, OSError):
            return None

    def close(self):
        self.sock.close()
