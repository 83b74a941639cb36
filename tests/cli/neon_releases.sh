#!/usr/bin/env bash
# neon_releases.sh VITRINE OUTDIR: each scripted drag draws one tube, one `release` event where it
# starts (on the release plane, or above the floor for a drag over the ground), and the autopilot
# stays quiet while the cursor plays and for autopilot_idle seconds after (at 20 heads a second, so that
# it releases again within the run).
set -eu
vitrine=$1; out=$2; script=$(dirname "$0")/../input/neon_drag.txt
mkdir -p "$out"; rm -f "$out/events.jsonl"
"$vitrine" --headless --scene neon --size 96x54 --frames 130 --set chains=256 --set autopilot_idle=1 \
  --set autopilot_rate=20 --validate \
  --input "$script" --events "$out/events.jsonl" --out "$out/neon.exr"
python3 - "$out/events.jsonl" <<'PY'
import json, sys
events = [json.loads(line) for line in open(sys.argv[1]) if '"release"' in line]
cursor = [e for e in events if e["by"] == "cursor"]
autopilot = [e for e in events if e["by"] == "autopilot"]
# One release per drag: a drag draws one tube (it used to spray one every 0.3 m of drag).
starts = [e["t"] for e in cursor]
assert len(starts) == 3 and all(a - 0.01 <= t <= a + 0.03 for t, a in zip(starts, (0.05, 0.6, 0.77))), starts
assert all(abs(e["z"] - 4.0) < 1e-4 for e in cursor[:2]), "drags over the facade start on the release plane"
# The drag over the ground (lower fifth) starts above the floor, nearer the camera: not underground.
assert cursor[2]["y"] >= 0.5 - 1e-4 and cursor[2]["z"] > 4.0, cursor[2]
# The autopilot plays until the first drag, then waits autopilot_idle after the last drag (~0.85 s).
assert all(e["t"] < 0.05 or e["t"] >= 1.84 for e in autopilot), [e["t"] for e in autopilot]
assert any(e["t"] >= 1.9 for e in autopilot), "the autopilot should take over again after the idle time"
print(f"releases ok: one per drag {[round(e['y'], 2) for e in cursor]}, {len(autopilot)} by the autopilot")
PY

# The scene's `release` action: each one a release where it asked, clamped to the release volume.
rm -f "$out/actions.jsonl"
"$vitrine" --headless --scene neon --size 96x54 --frames 30 --set chains=256 --set autopilot_idle=5 --validate \
  --input "$(dirname "$0")/../input/neon_actions.txt" --events "$out/actions.jsonl" --out "$out/neon_actions.exr"
python3 - "$out/actions.jsonl" <<'PY'
import json, sys
got = [(e["x"], e["y"], e["z"]) for e in map(json.loads, open(sys.argv[1])) if e.get("by") == "action"]
assert got == [(0, 6, 4), (-3, 8, 2.5), (16, 0, 4)], got
print("actions ok:", got)
PY
