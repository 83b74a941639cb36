#!/usr/bin/env bash
# bench_json.sh VITRINE OUTDIR: the benchmark runs headless and writes per-pass medians and p95s; with
# --pipeline-stats it lists every pipeline it made, each with what the driver reports of its executables
# (lavapipe reports none: it says so, and the list holds the pipelines' names), and each pass's shader
# invocations where the device counts them (lavapipe does): a compute pass's threads, a render pass's
# vertices and fragments.
set -eu
vitrine=$1; out=$2/bench.json
mkdir -p "$2"; rm -f "$out"
"$vitrine" bench --scene kifs --size 64x36 --frames 5 --warmup 1 --set step=4 --validate --json "$out"
python3 - "$out" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
scene = data["scenes"][0]
assert scene["scene"] == "kifs", scene
assert scene["gpu"]["median_ms"] > 0 and scene["gpu"]["p95_ms"] >= scene["gpu"]["median_ms"], scene
names = [p["name"] for p in scene["passes"]]
assert "kifs march" in names and "present" in names, names
assert data["size"] == [64, 36] and data["frames"] == 5, data
# Every parameter of the scene, typed, from its schema: the --set value and the defaults.
assert scene["parameters"]["step"] == 4 and scene["parameters"]["tier"] == "auto", scene["parameters"]
assert scene["parameters"]["target_ms"] == 8, scene["parameters"]
print("bench json ok:", names)
PY
"$vitrine" bench --scene kifs --size 64x36 --frames 2 --warmup 0 --validate --pipeline-stats --json "$out" 2>"$2/stats.err"
python3 - "$out" "$2/stats.err" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))["scenes"][0]
pipelines = {p["pipeline"]: p["executables"] for p in scene["pipelines"]}
assert "kifs/kifs.comp" in pipelines and "host/present.comp" in pipelines, pipelines
captured = any(pipelines.values())
notice = "cannot report its pipelines' statistics" in open(sys.argv[2]).read()
assert captured != notice, (captured, notice)  # statistics, or a word that there are none
print("pipeline statistics ok:", "captured" if captured else "not reported by this device")
PY
"$vitrine" bench --scene bloom --size 64x36 --frames 2 --warmup 0 --validate --pipeline-stats --json "$out" 2>"$2/stats.err"
python3 - "$out" "$2/stats.err" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))["scenes"][0]
passes = {p["name"]: p for p in scene["passes"]}
if "cannot count its passes' invocations" in open(sys.argv[2]).read():
    assert not any("invocations" in p for p in passes.values()), passes
    print("invocations: not counted by this device")
    sys.exit(0)
assert all("invocations" in p for p in passes.values()), passes
crystal = passes["bloom crystal"]["invocations"]  # the raymarch: a render pass over the crystal's proxy
assert crystal["vertex"] > 0 and 0 < crystal["fragment"] <= 64 * 36 * 4 and crystal["compute"] == 0, crystal
diffuse = passes["bloom diffuse"]["invocations"]  # compute only
assert diffuse["compute"] > 0 and diffuse["vertex"] == 0 and diffuse["fragment"] == 0, diffuse
print("invocations ok:", {name: p["invocations"] for name, p in passes.items()})
PY
