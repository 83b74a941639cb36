#!/bin/sh
# live_refused_range.sh VITRINE OUTDIR: a mapping onto a range the scene refuses (bloom's thresholds must
# rise: amber mapped up to 1 is not below rose) is set aside at once with one line, not refused again
# at every step of the run.
set -eu
vitrine=$1; out=$2
mkdir -p "$out"
python3 - "$out/tone.wav" <<'PY'
import math, struct, sys, wave
rate = 48000
with wave.open(sys.argv[1], "wb") as w:  # a 60 Hz tone swelling twice a second: the bass moves
    w.setnchannels(1); w.setsampwidth(2); w.setframerate(rate)
    w.writeframes(b"".join(struct.pack("<h", int(20000 * math.sin(2 * math.pi * 60 * i / rate) *
                                                 (0.5 + 0.5 * math.sin(2 * math.pi * 2 * i / rate))))
                           for i in range(rate)))
PY
"$vitrine" --headless --scene bloom --size 64x36 --frames 60 --audio-in "$out/tone.wav" --validate \
  --map audio.bass=bloom.threshold_amber:0.9:1 --out "$out/bloom.exr" 2>"$out/stderr.txt"
cat "$out/stderr.txt"
lines=$(grep -c "live input" "$out/stderr.txt" || true)
[ "$lines" = 1 ] || { echo "FAIL: $lines lines about live input, one expected"; exit 1; }
grep -q "the mapping audio.bass=bloom.threshold_amber:0.9:1 is set aside: bloom refuses" "$out/stderr.txt" ||
  { echo "FAIL: the mapping is not named as set aside"; exit 1; }
echo "live refused range ok"
