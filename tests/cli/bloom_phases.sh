#!/usr/bin/env bash
# bloom_phases.sh VITRINE OUTDIR: a scripted cursor held on the crystal, button down, makes it flip
# amber, rose, crimson and bloom (chroma) in that order, read from the GPU lattice; released and
# taken away, it vents below every threshold, each vent naming the phase it leaves. The WAV of the
# same run holds a bell at E4, B4 and E5 (within 1 Hz) at those moments, the drone, and no clipping.
set -eu
vitrine=$1; out=$2; script=$(dirname "$0")/../input/bloom_hold.txt
mkdir -p "$out"
"$vitrine" --headless --scene bloom --size 64x36 --frames 720 --set lattice=48 --validate \
  --input "$script" --events "$out/bloom.jsonl" --audio-out "$out/bloom.wav" --out "$out/bloom.exr"
python3 - "$out/bloom.jsonl" "$out/bloom.wav" <<'PY'
import json, math, struct, sys, wave
events = [json.loads(line) for line in open(sys.argv[1])]
seen = [e["event"] if e["event"] != "vent" else "vent:" + e["from"] for e in events]
expected = ["amber", "rose", "crimson", "chroma", "vent:chroma", "vent:crimson", "vent:rose", "vent:amber"]
assert seen == expected, seen
times = [e["t"] for e in events]
assert times == sorted(times), times
assert all(t < 6.0 for t in times[:4]) and all(t > 6.0 for t in times[4:]), times
assert all(e["scene"] == "bloom" and e["source"] == "gpu" for e in events), events
print("phases ok:", list(zip(seen, [round(t, 3) for t in times])))

with wave.open(sys.argv[2]) as w:
    assert (w.getnchannels(), w.getframerate(), w.getsampwidth()) == (2, 48000, 2), w.getparams()
    frames = w.getnframes()
    raw = w.readframes(frames)
assert frames == 720 * 800, frames  # 12 s at 48 kHz: the run's frames / 60, sample-exact
left = struct.unpack("<%dh" % (frames * 2), raw)[0::2]
peak = max(abs(v) for v in left)
assert 1000 < peak < 32767, peak  # audible, and never at full scale (no clipping)

def power(start, seconds, hz):  # Hann-windowed Goertzel
    n = int(seconds * 48000); s0 = int(start * 48000)
    k = 2 * math.cos(2 * math.pi * hz / 48000); a = b = 0.0
    for i in range(n):
        x = left[s0 + i] * (0.5 - 0.5 * math.cos(2 * math.pi * i / (n - 1)))
        a, b = x + k * a - b, a
    return a * a + b * b - k * a * b

def pitch(start, seconds, near):  # the strongest frequency within +-3 Hz, to a tenth of a hertz
    grid = [near + 0.5 * i for i in range(-6, 7)]
    p = [power(start, seconds, f) for f in grid]
    i = max(range(1, len(p) - 1), key=lambda j: p[j])
    den = p[i - 1] - 2 * p[i] + p[i + 1]
    return grid[i] + (0.5 * 0.5 * (p[i - 1] - p[i + 1]) / den if den else 0.0), p[i]

for name, hz in (("amber", 329.63), ("rose", 493.88), ("crimson", 659.26)):
    t = next(e["t"] for e in events if e["event"] == name)
    found, strength = pitch(t + 0.005, 0.25, hz)
    before = power(max(t - 0.26, 0.0), 0.25, hz)
    assert abs(found - hz) < 1.0, (name, found, hz)
    assert strength > 20 * before, (name, strength, before)  # the bell starts with the flip
    print(f"bell {name}: {found:.2f} Hz (expected {hz})")
drone, _ = pitch(8.0, 2.0, 55.0)
octave, _ = pitch(8.0, 2.0, 110.3)
assert abs(drone - 55.0) < 0.5 and abs(octave - 110.3) < 0.5, (drone, octave)
print(f"drone {drone:.2f} + {octave:.2f} Hz, peak {peak}/32767")
PY

# The seed's CPU proxy as the phase source: the same order, slower (dV/dt = 0.2 - 0.1 V).
"$vitrine" --headless --scene bloom --size 32x18 --frames 720 --set lattice=48 --set phase_source=cpu --validate \
  --input "$script" --events "$out/bloom-cpu.jsonl" --out "$out/bloom-cpu.exr"
python3 - "$out/bloom-cpu.jsonl" <<'PY'
import json, sys
events = [json.loads(line) for line in open(sys.argv[1])]
seen = [e["event"] if e["event"] != "vent" else "vent:" + e["from"] for e in events]
assert seen[:4] == ["amber", "rose", "crimson", "chroma"] and all(e["source"] == "cpu" for e in events), events
print("cpu proxy:", [(s, round(e["t"], 2)) for s, e in zip(seen, events)])
PY
