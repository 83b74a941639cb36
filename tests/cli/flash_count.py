#!/usr/bin/env python3
"""flash_count.py FOLDER FPS [--at-most N] [--at-least N]: counts the flashes in a recorded sequence of
EXR frames as WCAG 2.3.1 counts them, with the arithmetic of src/host/flash_guard_math.h applied to the
frames on disk (what the guard let through), independently of the guard's own passes. Prints the most
general and red flashes found in any one second and fails when --at-most or --at-least does not hold
for the larger of the two. Frames are read through oiiotool as 8-bit linear PPM."""
import math
import os
import subprocess
import sys
import tempfile

GENERAL_STEP, DARKER_BELOW, RED_SHARE, RED_SCALE, RED_STEP = 0.1, 0.8, 0.8, 320.0, 20.0
AREA_FRACTION = (341.0 * 256.0) / (1024.0 * 768.0)


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # P6 WIDTH HEIGHT MAXVAL, whitespace-separated, then one byte
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    width, height, top = int(fields[1]), int(fields[2]), float(fields[3])
    values = [b / top for b in data[pos + 1:]]
    return width, height, [tuple(values[i:i + 3]) for i in range(0, len(values), 3)]


def read_frames(folder, count, scratch):
    """Frames 0 .. count - 1 as linear RGB, through one oiiotool run (8 bits: its 16-bit PPM is wrong)."""
    subprocess.run(["oiiotool", "--frames", f"0-{count - 1}", os.path.join(folder, "frame_%06d.exr"),
                    "--ch", "R,G,B", "-d", "uint8", "-o", os.path.join(scratch, "frame_%06d.ppm")], check=True)
    return [read_ppm(os.path.join(scratch, f"frame_{k:06d}.ppm")) for k in range(count)]


def luminance(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def general(a, b):
    la, lb = luminance(a), luminance(b)
    if abs(lb - la) < GENERAL_STEP or min(la, lb) >= DARKER_BELOW:
        return 0
    return 1 if lb > la else -1


def saturated_red(c):
    s = c[0] + c[1] + c[2]
    return s > 0 and c[0] >= RED_SHARE * s


def red_value(c):
    return max(0.0, c[0] - c[1] - c[2]) * RED_SCALE


def red(a, b):
    if not saturated_red(a) and not saturated_red(b):
        return 0
    change = red_value(b) - red_value(a)
    if abs(change) <= RED_STEP:
        return 0
    return 1 if change > 0 else -1


def transitions(before, after, area):
    """The frame's general and red transitions: one per direction whose pixels cover the area."""
    counts = {"general": [0, 0], "red": [0, 0]}
    for a, b in zip(before, after):
        g, r = general(a, b), red(a, b)
        if g:
            counts["general"][0 if g > 0 else 1] += 1
        if r:
            counts["red"][0 if r > 0 else 1] += 1
    made = {kind: sum(1 for n in pair if n >= area) for kind, pair in counts.items()}
    made["largest"] = max(max(pair) for pair in counts.values())
    return made


def main():
    folder, fps = sys.argv[1], float(sys.argv[2])
    at_most = at_least = None
    args = sys.argv[3:]
    while args:
        flag, value = args[0], int(args[1])
        args = args[2:]
        if flag == "--at-most":
            at_most = value
        elif flag == "--at-least":
            at_least = value
    names = sorted(n for n in os.listdir(folder) if n.startswith("frame_") and n.endswith(".exr"))
    with tempfile.TemporaryDirectory() as scratch:
        frames = read_frames(folder, len(names), scratch)
    width, height = frames[0][0], frames[0][1]
    area = max(1, math.ceil(AREA_FRACTION * width * height))
    per_frame = [{"general": 0, "red": 0, "largest": 0}] + [transitions(frames[k - 1][2], frames[k][2], area)
                                               for k in range(1, len(frames))]
    span = int(round(fps))  # frames i .. i + fps: a closed window of one second
    most = {}
    for kind in ("general", "red"):
        counts = [f[kind] for f in per_frame]
        worst = max(sum(counts[i:i + span + 1]) for i in range(len(counts)))
        most[kind] = worst / 2.0  # a flash is a pair of opposing transitions
    print(f"{len(frames)} frames at {width}x{height}: at most {most['general']:g} general and "
          f"{most['red']:g} red flashes in any one second (area {area} px)")
    largest = max(range(len(per_frame)), key=lambda k: per_frame[k]["largest"])
    print(f"the largest change: {per_frame[largest]['largest']} px in transition one way "
          f"({100.0 * per_frame[largest]['largest'] / (width * height):.1f} % of the frame) at frame {largest}")
    worst = max(most.values())
    if at_most is not None and worst > at_most:
        sys.exit(f"flash_count: {worst:g} flashes in one second, more than {at_most}")
    if at_least is not None and worst < at_least:
        sys.exit(f"flash_count: {worst:g} flashes in one second, fewer than {at_least}")


if __name__ == "__main__":
    main()
