#!/usr/bin/env bash
# bloom_phases.sh VITRINE OUTDIR: a scripted cursor held on the crystal, button down, makes it flip
# amber, rose, crimson and bloom (chroma) in that order, read from the GPU lattice; released and
# taken away, it vents below every threshold, each vent naming the phase it leaves.
set -eu
vitrine=$1; out=$2; script=$(dirname "$0")/../input/bloom_hold.txt
mkdir -p "$out"
"$vitrine" --headless --scene bloom --size 64x36 --frames 720 --set lattice=48 --validate \
  --input "$script" --events "$out/bloom.jsonl" --out "$out/bloom.exr"
python3 - "$out/bloom.jsonl" <<'PY'
import json, sys
events = [json.loads(line) for line in open(sys.argv[1])]
seen = [e["event"] if e["event"] != "vent" else "vent:" + e["from"] for e in events]
expected = ["amber", "rose", "crimson", "chroma", "vent:chroma", "vent:crimson", "vent:rose", "vent:amber"]
assert seen == expected, seen
times = [e["t"] for e in events]
assert times == sorted(times), times
assert all(t < 6.0 for t in times[:4]) and all(t > 6.0 for t in times[4:]), times
assert all(e["scene"] == "bloom" and e["source"] == "gpu" for e in events), events
print("phases ok:", list(zip(seen, [round(t, 3) for t in times])))
PY
