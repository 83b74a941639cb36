#!/usr/bin/env python3
"""xtest.py DISPLAY ACTION...: presses keys and moves or clicks the mouse on an X display through the
XTEST extension, speaking the X11 protocol over the display's local socket (no xdotool on the test
machine). Actions: key:NAME (a keysym name: F12, Tab, bracketright, 3 ...), move:X,Y, click:X,Y,
ctrlclick:X,Y, drag:X,Y,TOX,TOY (pressed, moved there over half a second, released), wheel:X,Y,NOTCHES,
focus:X,Y (the pointer there, and the keyboard's focus following the pointer from then on, as a window
manager's focus-follows-mouse would give the window under it),
sleep:SECONDS, and shot:X,Y,W,H,FILE.ppm, which saves that part of the
root window (what every window on the screen shows) as a binary PPM. For the gallery's checks under Xvfb (started without access control)."""
import os
import socket
import struct
import sys
import time

KEYSYMS = {"Tab": 0xFF09, "Escape": 0xFF1B, "Return": 0xFF0D, "Control_L": 0xFFE3, "Left": 0xFF51, "Up": 0xFF52,
           "Right": 0xFF53, "Down": 0xFF54, "bracketleft": 0x5B, "bracketright": 0x5D,
           "backslash": 0x5C, "period": 0x2E}
KEYSYMS.update({f"F{n}": 0xFFBD + n for n in range(1, 13)})
KEYSYMS.update({str(d): 0x30 + d for d in range(10)})
KEYSYMS.update({chr(c): c for c in range(ord("a"), ord("z") + 1)})


def recv(sock, n):
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            raise SystemExit("xtest: the X server closed the connection")
        data += chunk
    return data


def connect(display):
    number = display.split(":")[1].split(".")[0]
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.connect(f"/tmp/.X11-unix/X{number}")
    sock.sendall(struct.pack("<BxHHHHxx", 0x6C, 11, 0, 0, 0))
    head = recv(sock, 8)
    if head[0] != 1:
        raise SystemExit(f"xtest: connection refused by {display}")
    extra = struct.unpack("<H", head[6:8])[0] * 4
    setup = recv(sock, extra)
    min_keycode, max_keycode = setup[26], setup[27]
    vendor, formats = struct.unpack("<H", setup[16:18])[0], setup[21]
    screen = 32 + (vendor + 3) // 4 * 4 + 8 * formats  # the first screen, whose first field is its root window
    root = struct.unpack("<I", setup[screen:screen + 4])[0]
    return sock, min_keycode, max_keycode, root


def request(sock, data, reply=False):
    sock.sendall(data)
    if not reply:
        return None
    while True:
        head = recv(sock, 32)
        if head[0] == 0:
            raise SystemExit(f"xtest: X error {head[1]}")
        if head[0] == 1:
            length = struct.unpack("<I", head[4:8])[0] * 4
            return head + recv(sock, length)
        # an event: ignore


def main():
    display, actions = sys.argv[1], sys.argv[2:]
    sock, lo, hi, root = connect(display)
    name = b"XTEST"
    pad = (4 - len(name) % 4) % 4
    ext = request(sock, struct.pack("<BxHHxx", 98, 2 + (len(name) + pad) // 4, len(name)) + name + b"\0" * pad, True)
    if not ext[8]:
        raise SystemExit("xtest: the display has no XTEST extension")
    opcode = ext[9]
    count = hi - lo + 1
    mapping = request(sock, struct.pack("<BxHBBxx", 101, 2, lo, count), True)
    per = mapping[1]
    syms = struct.unpack(f"<{count * per}I", mapping[32:32 + 4 * count * per])
    keycode = {}
    for i in range(count):
        for j in range(per):
            keycode.setdefault(syms[i * per + j], lo + i)

    def fake(kind, detail, x=0, y=0):
        request(sock, struct.pack("<BBHBBxxIIxxxxxxxxhhxxxxxxxx", opcode, 2, 9, kind, detail, 0, 0, x, y))

    for action in actions:
        verb, _, arg = action.partition(":")
        if verb == "key":
            code = keycode.get(KEYSYMS[arg])
            if code is None:
                raise SystemExit(f"xtest: no keycode for {arg}")
            fake(2, code)
            fake(3, code)
        elif verb in ("move", "click", "ctrlclick"):
            x, y = map(int, arg.split(","))
            fake(6, 0, x, y)
            ctrl = keycode.get(KEYSYMS["Control_L"])
            if verb == "ctrlclick":
                fake(2, ctrl)
            if verb != "move":
                fake(4, 1)
                time.sleep(0.05)
                fake(5, 1)
            if verb == "ctrlclick":
                fake(3, ctrl)
        elif verb == "drag":
            x, y, to_x, to_y = map(int, arg.split(","))
            fake(6, 0, x, y)
            time.sleep(0.1)
            fake(4, 1)
            for i in range(1, 11):  # a hand's pace: every frame sees the button held somewhere on the way
                time.sleep(0.05)
                fake(6, 0, x + (to_x - x) * i // 10, y + (to_y - y) * i // 10)
            time.sleep(0.2)
            fake(5, 1)
        elif verb == "wheel":  # wheel:X,Y,N: N notches down (negative: up)
            x, y, n = map(int, arg.split(","))
            fake(6, 0, x, y)
            for _ in range(abs(n)):
                fake(4, 5 if n > 0 else 4)
                fake(5, 5 if n > 0 else 4)
                time.sleep(0.05)
        elif verb == "focus":
            x, y = map(int, arg.split(","))
            fake(6, 0, x, y)
            request(sock, struct.pack("<BBHII", 42, 1, 3, 1, 0))  # SetInputFocus: PointerRoot, reverting to it
        elif verb == "shot":  # GetImage (ZPixmap) in bands that fit a reply, written as RGB
            x, y, w, h, path = arg.split(",", 4)
            x, y, w, h = int(x), int(y), int(w), int(h)
            pixels = b""
            # The server grabbed for the bands, so that no frame is drawn between two of them: a moving
            # scene grabbed without it shows seams every 64 rows where one frame meets the next.
            request(sock, struct.pack("<BxH", 36, 1))  # GrabServer
            for top in range(0, h, 64):
                rows = min(64, h - top)
                reply = request(sock, struct.pack("<BBHIhhHHI", 73, 2, 5, root, x, y + top, w, rows, 0xFFFFFFFF), True)
                data = reply[32:32 + w * rows * 4]  # 32-bit BGRX on a 24-bit TrueColor screen
                pixels += b"".join(bytes((data[i + 2], data[i + 1], data[i])) for i in range(0, len(data), 4))
            request(sock, struct.pack("<BxH", 37, 1))  # UngrabServer
            with open(path, "wb") as out:
                out.write(b"P6\n%d %d\n255\n" % (w, h) + pixels)
        elif verb == "sleep":
            time.sleep(float(arg))
        else:
            raise SystemExit(f"xtest: unknown action {action}")
    # GetInputFocus: a round trip, so every request has been handled before we go.
    request(sock, struct.pack("<BxH", 43, 1), True)
    sock.close()


if __name__ == "__main__":
    main()
