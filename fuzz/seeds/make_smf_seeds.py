#!/usr/bin/env python3
"""Writes smf/*.mid: small Standard MIDI Files built byte by byte here, one for each path through the
parser (src/live/smf.cpp), so the smf target starts from valid files rather than from nothing. The
outputs are checked in; run again only to change them."""
import os
import struct


def vlq(value):
    out = [value & 0x7F]
    value >>= 7
    while value:
        out.insert(0, (value & 0x7F) | 0x80)
        value >>= 7
    return bytes(out)


def chunk(kind, data):
    return kind + struct.pack(">I", len(data)) + data


def header(fmt, tracks, division):
    return chunk(b"MThd", struct.pack(">HHH", fmt, tracks, division))


def track(*events):
    """Events as (delta, bytes); end of track appended."""
    return chunk(b"MTrk", b"".join(vlq(d) + e for d, e in events) + vlq(0) + b"\xff\x2f\x00")


def tempo(micros):
    return b"\xff\x51\x03" + struct.pack(">I", micros)[1:]


SEEDS = {
    # Format 0 as writeSmf writes it: a tempo, notes with running status, a CC.
    "format0.mid": header(0, 1, 480) + track(
        (0, tempo(500000)), (0, b"\x90\x3c\x64"), (240, b"\x40\x50"), (240, b"\x3c\x00"), (0, b"\x40\x00"),
        (120, b"\xb0\x07\x64"), (360, b"\xc0\x05"), (0, b"\xe0\x00\x40")),
    # Format 1: a tempo track changing tempo mid-way, an unknown chunk, a track with sysex, meta and
    # running status across them, several channels.
    "format1.mid": header(1, 2, 96) + track((0, tempo(500000)), (192, tempo(250000)), (0, b"\xc0\x05"))
    + chunk(b"XFIH", b"\x01\x02\x03")
    + track((0, b"\x90\x3c\x64"), (96, b"\x3c\x00"), (0, b"\xb1\x07\x7f"), (96, b"\x08\x40"),
            (0, b"\xff\x01\x03abc"), (48, b"\x9f\x40\x50"), (0, b"\xf0\x03\x7e\x7f\xf7"), (48, b"\x40\x00"),
            (0, b"\xf7\x02\x01\x02"), (10, b"\xa2\x40\x10"), (10, b"\xd3\x20")),
    # SMPTE division, 25 frames x 40 ticks, whose tempo event does not apply.
    "smpte.mid": header(0, 1, 0xE728) + track((0, tempo(250000)), (500, b"\x90\x3c\x64"), (500, b"\x80\x3c\x00")),
}

folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "smf")
os.makedirs(folder, exist_ok=True)
for name, data in SEEDS.items():
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)
