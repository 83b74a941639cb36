#!/usr/bin/env bash
# neon_releases.sh VITRINE OUTDIR: a scripted drag releases tubes, each one a `release` event with its
# position on the release plane; the quick stroke releases faster than the slow one, and the autopilot
# stays quiet while the cursor plays and for autopilot_idle seconds after.
set -eu
vitrine=$1; out=$2; script=$(dirname "$0")/../input/neon_drag.txt
mkdir -p "$out"; rm -f "$out/events.jsonl"
"$vitrine" --headless --scene neon --size 96x54 --frames 130 --set chains=256 --set autopilot_idle=1 --validate \
  --input "$script" --events "$out/events.jsonl" --out "$out/neon.exr"
python3 - "$out/events.jsonl" <<'PY'
import json, sys
events = [json.loads(line) for line in open(sys.argv[1]) if '"release"' in line]
cursor = [e for e in events if e["by"] == "cursor"]
autopilot = [e for e in events if e["by"] == "autopilot"]
slow = [e for e in cursor if e["t"] <= 0.5]
quick = [e for e in cursor if 0.6 <= e["t"] <= 0.7]
assert len(slow) >= 5 and len(quick) >= 5, (len(slow), len(quick))
assert len(quick) / 0.1 > 2 * len(slow) / 0.45, ("the quick stroke should release faster", len(slow), len(quick))
assert all(abs(e["z"] - 4.0) < 1e-4 for e in cursor), "cursor releases lie on the release plane"
# The autopilot plays until the first drag, then waits autopilot_idle after the last drag (~0.68 s).
assert all(e["t"] < 0.05 or e["t"] >= 1.65 for e in autopilot), [e["t"] for e in autopilot]
assert any(e["t"] >= 1.7 for e in autopilot), "the autopilot should take over again after the idle time"
print(f"releases ok: {len(slow)} slow, {len(quick)} quick, {len(autopilot)} by the autopilot")
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
