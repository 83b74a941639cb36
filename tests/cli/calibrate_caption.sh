#!/bin/sh
# calibrate_caption.sh VITRINE OUTDIR: the card's centre cross ends above its caption; no glyph of the
# caption ("VITRINE · OFFSCREEN · W × H") lies on a row the cross's vertical arm reaches.
set -eu
vitrine=$1; out=$2
mkdir -p "$out"
"$vitrine" --headless --scene calibrate --size 480x270 --time 0 --out "$out/card.exr" --validate
oiiotool "$out/card.exr" --ch R -d uint8 -o "$out/card.pgm"
python3 - "$out/card.pgm" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
parts = data.split(maxsplit=4)  # P5 width height maxval pixels
assert parts[0] == b"P5", parts[0]
w, h = int(parts[1]), int(parts[2])
pixels = parts[4][-w * h:]
at = lambda x, y: pixels[y * w + x]
cx = w // 2
# The dark band between the colour bars and the grey ramp, below the centre.
rows = range(h // 2 + 2, int(h * 0.58))
cross = [y for y in rows if max(at(cx - 1, y), at(cx, y)) > 200]
caption = [y for y in rows if sum(1 for x in range(int(w * 0.25), int(w * 0.75)) if abs(x - cx) > 3 and at(x, y) > 60) >= 3]
assert cross and caption, (cross, caption)
print(f"cross down to row {max(cross)}, caption from row {min(caption)}")
assert max(cross) < min(caption) - 1, f"the cross (rows {min(cross)}..{max(cross)}) runs into the caption (rows {min(caption)}..{max(caption)})"
PY
