#!/usr/bin/env bash
# input_events.sh VITRINE OUTDIR: a scripted drag drives a headless noodles run frame-exactly; the
# scene's events file records the grab and the release at the script's times, and the frame differs
# from the same run without the drag (the camera moved).
set -eu
vitrine=$1; out=$2; script=$(dirname "$0")/../input/drag_release.txt
mkdir -p "$out"; rm -f "$out/events.jsonl"
common=(--headless --scene noodles --size 96x54 --frames 40 --set grid=6 --set segments=16 --set msaa=off --validate)
"$vitrine" "${common[@]}" --input "$script" --events "$out/events.jsonl" --out "$out/dragged.exr"
"$vitrine" "${common[@]}" --out "$out/still.exr"
python3 - "$out/events.jsonl" <<'PY'
import json, sys
events = [json.loads(line) for line in open(sys.argv[1])]
names = [(e["event"], round(e["t"], 6), e["scene"]) for e in events]
assert names == [("orbit_grab", 0.2, "noodles"), ("orbit_release", 0.5, "noodles")], names
assert list(events[0].keys())[:3] == ["t", "scene", "event"], events[0]
assert abs(events[1]["x"] - 0.7) < 1e-6 and abs(events[1]["y"] - 0.45) < 1e-6, events[1]
print("events ok:", names)
PY
if "$vitrine" compare "$out/still.exr" "$out/dragged.exr" >/dev/null 2>&1; then
  echo "the drag did not change the picture"; exit 1
fi
echo "input and events ok"
