#!/usr/bin/env python3
"""Writes font/seed.ttf: a tiny TrueType font drawn here (a triangle, a square, a ring and an empty space),
enough for FreeType to load and HarfBuzz to shape, so the font target starts from a valid file rather
than from nothing. The output is checked in; run again only to change it."""
import os
import struct

UNITS = 1000
# Glyph outlines: lists of contours, each a list of on-curve points (x, y), clockwise.
TRIANGLE = [[(50, 0), (350, 700), (650, 0)]]
SQUARE = [[(100, 0), (100, 500), (500, 500), (500, 0)]]
RING = [[(50, 0), (50, 700), (650, 700), (650, 0)], [(200, 150), (500, 150), (500, 550), (200, 550)]]
GLYPHS = [None, TRIANGLE, SQUARE, RING, None]  # .notdef, then glyphs 1..4 (4: a space, no ink)
ADVANCES = [500, 700, 600, 700, 300]
CMAP = {"A": 1, "V": 1, "i": 2, "t": 2, "r": 2, "n": 2, "e": 3, "g": 3, "f": 2, " ": 4}


def glyph_data(contours):
    if not contours:
        return b""
    points = [p for c in contours for p in c]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    out = struct.pack(">hhhhh", len(contours), min(xs), min(ys), max(xs), max(ys))
    end = -1
    for c in contours:
        end += len(c)
        out += struct.pack(">H", end)
    out += struct.pack(">H", 0)  # no instructions
    out += bytes([0x01] * len(points))  # on curve, 16-bit deltas
    prev = 0
    for x in xs:
        out += struct.pack(">h", x - prev)
        prev = x
    prev = 0
    for y in ys:
        out += struct.pack(">h", y - prev)
        prev = y
    return out + b"\0" * (-len(out) % 4)


def cmap_table():
    chars = sorted((ord(c), g) for c, g in CMAP.items())
    segments = [(c, c, (g - c) % 65536) for c, g in chars] + [(0xFFFF, 0xFFFF, 1)]
    n = len(segments)
    search = 2 ** (n.bit_length() - 1)
    sub = struct.pack(">HHHHHHH", 4, 0, 0, n * 2, search * 2, search.bit_length() - 1, n * 2 - search * 2)
    sub += b"".join(struct.pack(">H", e) for _, e, _ in segments) + b"\0\0"
    sub += b"".join(struct.pack(">H", s) for s, _, _ in segments)
    sub += b"".join(struct.pack(">H", d) for _, _, d in segments)
    sub += b"\0\0" * n
    sub = sub[:2] + struct.pack(">H", len(sub)) + sub[4:]
    return struct.pack(">HHHHI", 0, 1, 3, 1, 12) + sub


def build():
    glyf, loca = b"", [0]
    for g in GLYPHS:
        glyf += glyph_data(g)
        loca.append(len(glyf))
    n = len(GLYPHS)
    name_text = "Vitrine Seed".encode("utf-16-be")
    tables = {
        b"head": struct.pack(">IIIIHHqqhhhhHHhhh", 0x00010000, 0x00010000, 0, 0x5F0F3CF5, 0, UNITS, 0, 0,
                             0, 0, 700, 700, 0, 8, 2, 1, 0),
        b"hhea": struct.pack(">Ihhh" + "H" + "hhh" + "hhh" + "hhhh" + "hH", 0x00010000, 800, -200, 0, max(ADVANCES),
                             0, 0, 700, 1, 0, 0, 0, 0, 0, 0, 0, n),
        b"maxp": struct.pack(">IHHHHHHHHHHHHHH", 0x00010000, n, 8, 2, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0),
        b"hmtx": b"".join(struct.pack(">Hh", a, 0) for a in ADVANCES),
        b"loca": b"".join(struct.pack(">I", o) for o in loca),
        b"glyf": glyf,
        b"cmap": cmap_table(),
        b"post": struct.pack(">IIhhIIIII", 0x00030000, 0, -100, 50, 0, 0, 0, 0, 0),
        b"name": struct.pack(">HHHHHHHHH", 0, 1, 18, 3, 1, 0x409, 1, len(name_text), 0) + name_text,
    }
    count = len(tables)
    search = 2 ** (count.bit_length() - 1)
    out = struct.pack(">IHHHH", 0x00010000, count, search * 16, search.bit_length() - 1, count * 16 - search * 16)
    offset = 12 + 16 * count
    directory, body = b"", b""
    for tag in sorted(tables):
        data = tables[tag] + b"\0" * (-len(tables[tag]) % 4)
        checksum = sum(struct.unpack(">%dI" % (len(data) // 4), data)) & 0xFFFFFFFF
        directory += struct.pack(">4sIII", tag, checksum, offset + len(body), len(tables[tag]))
        body += data
    return out + directory + body


here = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(here, "font"), exist_ok=True)
with open(os.path.join(here, "font", "seed.ttf"), "wb") as f:
    f.write(build())
