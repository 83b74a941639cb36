#!/usr/bin/env bash
# record.sh VITRINE OUTDIR: `vitrine record` writes a numbered sequence at a fixed step, resumes by
# skipping finished frames, renders a --range bit for bit as the whole run does, writes the film's
# sound for a scene that makes any, and PNG on request.
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
common=(record --scene kifs --size 64x36 --fps 30 --seconds 0.3 --spp 2 --validate)
"$vitrine" "${common[@]}" --out "$out/whole" | tee "$out/whole.log"
test "$(ls "$out/whole" | grep -c '^frame_0000[0-9][0-9].exr$')" = 9
# Resume: only the missing frames are written; the others are left as they were.
stamp=$(stat -c %Y.%s "$out/whole/frame_000004.exr")
rm "$out/whole/frame_000002.exr" "$out/whole/frame_000007.exr"
sleep 1
"$vitrine" "${common[@]}" --out "$out/whole" | grep "recorded 2 of frames 0..8" >/dev/null
test "$(stat -c %Y.%s "$out/whole/frame_000004.exr")" = "$stamp"
test -s "$out/whole/frame_000002.exr" && test -s "$out/whole/frame_000007.exr"
# A range on its own: the same pixels as the whole run.
"$vitrine" "${common[@]}" --range 3:6 --out "$out/part" | grep "recorded 3 of frames 3..5" >/dev/null
test "$(ls "$out/part")" = "$(printf 'frame_000003.exr\nframe_000004.exr\nframe_000005.exr\nrecord.json')"
for f in 3 4 5; do
  "$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/whole/frame_00000$f.exr" "$out/part/frame_00000$f.exr" >/dev/null
done
# The stateful scenes too: a range simulates the frames before it without drawing them (FrameContext::draws),
# and its frames are the whole run's, bit for bit.
for scene in "neon --set chains=256" "bloom --preset quick --set fill=0.4" "noodles --set grid=8x8x4"; do
  name=${scene%% *}
  args=(record --scene $scene --size 48x27 --fps 30 --seconds 0.4 --validate)
  "$vitrine" "${args[@]}" --out "$out/$name-whole" >/dev/null 2>&1
  "$vitrine" "${args[@]}" --range 9:12 --out "$out/$name-part" >/dev/null 2>&1
  for f in 09 10 11; do
    "$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/$name-whole/frame_0000$f.exr" "$out/$name-part/frame_0000$f.exr" >/dev/null ||
      { echo "$name: frame $f of a range differs from the whole run's"; exit 1; }
  done
done
# Samples a frame are averaged: two samples differ from one where the fractal moves.
"$vitrine" record --scene kifs --size 64x36 --fps 30 --seconds 0.1 --spp 1 --out "$out/one" >/dev/null
if "$vitrine" compare "$out/one/frame_000002.exr" "$out/whole/frame_000002.exr" | grep -q "max difference 0.00000"; then
  echo "two samples a frame gave the same picture as one"; exit 1
fi
# Sound: bloom's drone, the film's length exactly (0.5 s at 48 kHz, stereo 16-bit PCM).
"$vitrine" record --scene bloom --size 32x18 --fps 24 --seconds 0.5 --set fill=0.5 --out "$out/sound" >/dev/null
python3 - "$out/sound/audio.wav" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
assert data[:4] == b"RIFF" and data[8:12] == b"WAVE", "not a WAV"
channels, rate = struct.unpack_from("<HI", data, 22)
bits = struct.unpack_from("<H", data, 34)[0]
size = struct.unpack_from("<I", data, data.index(b"data") + 4)[0]
assert rate == 48000 and channels == 2, (rate, channels)
assert size // (channels * bits // 8) == 24000, size
print("audio ok")
PY
# PNG on request, where the build writes PNG.
"$vitrine" record --scene kifs --size 32x18 --fps 10 --seconds 0.2 --format png --out "$out/png" >/dev/null
test -s "$out/png/frame_000001.png"
# Mistakes are one sentence each.
if "$vitrine" record --scene kifs --out "$out/x" 2>"$out/err.txt"; then exit 1; fi
grep -q "record needs --seconds" "$out/err.txt"
if "$vitrine" record --scene kifs --seconds 1 --range 5:5 --out "$out/x" 2>"$out/err.txt"; then exit 1; fi
grep -q -- "--range expects FIRST:END" "$out/err.txt"
echo "record ok"
