#!/usr/bin/env bash
# ltc_timecode.sh VITRINE LTC_WAV OUTDIR: LTC written by libltc's encoder (vitrine_ltc_wav) as --audio-in
# of a headless run drives a mapping through ltc.seconds, frame-exact: at every step the mapped value
# says the frame the timecode was on at that step's time. Then hostile input: a file of noise gives no
# ltc source and no complaint beyond it, and the run goes on.
set -eu
vitrine=$1; ltcwav=$2; out=$3
rm -rf "$out"; mkdir -p "$out"

for rate in 25 29.97df; do
  "$ltcwav" "$out/ltc_$rate.wav" "$rate" 00:00:30:00 2.5
  "$vitrine" --headless --scene kifs --size 32x18 --frames 120 --audio-in "$out/ltc_$rate.wav" \
    --map "ltc.seconds=kifs.fold:0.8:1.3" --events "$out/ltc_$rate.jsonl" --out "$out/ltc_$rate.exr" >/dev/null
  python3 - "$out/ltc_$rate.jsonl" "$rate" <<'PY'
import json, math, sys
path, rate = sys.argv[1], sys.argv[2]
fps = 30000 / 1001 if rate == "29.97df" else float(rate)
start = 30 * (30 if rate == "29.97df" else int(fps))  # 00:00:30:00 as a frame count (no drop before a minute)
mapped = [e for e in map(json.loads, open(path)) if e["event"] == "mapped" and e["by"] == "ltc.seconds"]
assert mapped, "no value mapped from ltc.seconds"
checked = 0
for e in mapped:
    t = e["t"]
    sent = t * fps                        # frames begun since the code's first
    if t < 0.2 or abs(sent - round(sent)) < 0.02:
        continue                          # the decoder's first two frames; a frame boundary, either is right
    seconds = (float(e["value"]) - 0.8) / 0.5 * 60.0
    frame = math.floor(seconds * fps + 1e-3)
    want = start + math.floor(sent)
    assert frame == want, f"{rate}: at t={t:.4f} s the mapping says frame {frame}, the timecode was on {want}"
    checked += 1
assert checked >= 90, f"{rate}: only {checked} steps checked"
print(f"ltc {rate}: {checked} steps frame-exact")
PY
done

# Noise where LTC should be: no ltc source is ever written, the run completes.
python3 - "$out/noise.wav" <<'PY'
import random, struct, sys, wave
random.seed(4)
with wave.open(sys.argv[1], "wb") as w:
    w.setnchannels(1); w.setsampwidth(2); w.setframerate(48000)
    w.writeframes(b"".join(struct.pack("<h", random.randint(-32000, 32000)) for _ in range(48000)))
PY
"$vitrine" --headless --scene kifs --size 32x18 --frames 30 --audio-in "$out/noise.wav" \
  --map "ltc.seconds=kifs.fold:0.8:1.3" --events "$out/noise.jsonl" --out "$out/noise.exr" >/dev/null
python3 - "$out/noise.jsonl" <<'PY'
import json, sys
values = {e["value"] for e in map(json.loads, open(sys.argv[1])) if e["event"] == "mapped" and e["by"] == "ltc.seconds"}
assert values <= {"0.8"}, f"noise moved the mapping through ltc.seconds: {sorted(values)[:5]}"
print("noise: no timecode, the run completed")
PY
