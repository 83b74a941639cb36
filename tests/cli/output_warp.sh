#!/usr/bin/env bash
# output_warp.sh VITRINE OUTDIR: an output's warp (--output-warp FILE; src/maths/output_warp.h) in the
# present pass. A half turn, a quarter turn and a mirror show the plain frame turned and flipped (oiiotool
# turns the plain one; the two agree to within a half-float step, the warp's sampling positions moving by
# rounding only); a region shows its part of the frame; a corner pin leaves black where the picture does
# not reach; a soft edge darkens its edge and leaves the middle as it was; an empty warp is the plain
# path, bit for bit; a bad file, or a region so small that its frame is larger than the device draws, is
# refused, naming it.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"; cd "$out"
render() {  # render SIZE OUT [WARP]
  "$vitrine" --headless --scene kifs --time 3 --size "$1" --validate ${3:+--output-warp "$3"} --out "$2" >/dev/null
}
close() {  # close A B: within one half-float step of each other everywhere
  local d; d=$("$vitrine" compare "$1" "$2" | sed -n 's/.*max difference \([0-9.]*\).*/\1/p')
  awk -v d="$d" 'BEGIN { exit !(d != "" && d < 0.002) }' || { echo "$2 differs from $1 by $d"; exit 1; }
}
brightest() { oiiotool "$1" --printstats 2>&1 | sed -n 's/.*Stats Max: \([0-9.]*\) \([0-9.]*\) \([0-9.]*\).*/\1 \2 \3/p'; }

render 256x144 plain.exr
echo '{}' > none.json
render 256x144 none.exr none.json
"$vitrine" compare --fail-fraction 0 --hard-limit 0 plain.exr none.exr >/dev/null

# shows NAME WARP OUTPUT FRAME FRAME-IMAGE OIIOTOOL-ARGS...: an output of OUTPUT pixels with WARP shows the
# plain frame of FRAME pixels as oiiotool's ARGS turn, flip or cut it.
shows() {
  local name=$1 warp=$2 output=$3 frame=$4 plain=$5; shift 5
  echo "$warp" > "$name.json"
  render "$output" "$name.exr" "$name.json"
  [ -s "$plain" ] || render "$frame" "$plain"
  oiiotool "$plain" "$@" -o "$name-expected.exr"
  close "$name-expected.exr" "$name.exr"
}
shows half '{"turn": 180}' 256x144 256x144 plain.exr --rotate180
# A quarter turn: the scene renders the frame portrait (144x256) for a landscape output.
shows quarter '{"turn": 90}' 256x144 144x256 portrait.exr --rotate90
shows mirror '{"mirror": true}' 256x144 256x144 plain.exr --flop
# The right-hand projector of a pair: its 128x144 output shows the right half of the 256x144 frame.
shows right '{"region": [0.5, 0, 1, 1]}' 128x144 256x144 plain.exr --cut 128x144+128+0 --origin +0+0

# A keystone pin: the output's top-left corner lies outside the pinned picture, so it is black.
echo '{"corners": [[0.2, 0.1], [1, 0], [1, 1], [0, 1]]}' > pin.json
render 256x144 pin.exr pin.json
oiiotool pin.exr --cut 16x8+0+0 -o pin-corner.exr
test "$(brightest pin-corner.exr)" = "0.000000 0.000000 0.000000" || { echo "outside the pin: $(brightest pin-corner.exr)"; exit 1; }
test "$(brightest pin.exr)" != "0.000000 0.000000 0.000000"

# A soft left edge over a quarter of the picture: its first column keeps under 2 % of its light, the
# right half is untouched.
echo '{"blend": {"left": 0.25, "curve": 2, "gamma": 2.2}}' > blend.json
render 256x144 blend.exr blend.json
oiiotool blend.exr --cut 1x144+0+0 -o blend-edge.exr
oiiotool plain.exr --cut 1x144+0+0 -o plain-edge.exr
read -r er eg eb <<<"$(brightest blend-edge.exr)"
read -r pr pg pb <<<"$(brightest plain-edge.exr)"
awk -v e="$er $eg $eb" -v p="$pr $pg $pb" 'BEGIN { split(e, a); split(p, b); for (i = 1; i <= 3; i++) if (a[i] > 0.02 * b[i] + 1e-6) exit 1 }' ||
  { echo "blended edge $er $eg $eb against $pr $pg $pb"; exit 1; }
oiiotool blend.exr --cut 128x144+128+0 --origin +0+0 -o blend-right.exr
close right-expected.exr blend-right.exr

# Mistakes, each one sentence naming the file.
echo '{"turn": 45}' > bad-turn.json
echo '{"corners": [[0, 0], [1, 1], [1, 0], [0, 1]]}' > crossed.json
echo '{"rotate": 90}' > unknown.json
echo '{"region": [0.5, 0.5, 0.502, 0.502]}' > tiny.json  # a 64x36 output's frame would be 32000x18000
for bad in bad-turn:"turn is 0, 90, 180 or 270" crossed:"convex" unknown:'unknown key "rotate"' \
           tiny:"a region of 0.002 x 0.002 .*needs a 32000x18000 frame, outside what .* supports"; do
  file=${bad%%:*}.json
  if render 64x36 x.exr "$file" 2>err.txt; then echo "$file was accepted"; exit 1; fi
  grep -q "$file: .*${bad#*:}" err.txt || { cat err.txt; exit 1; }
done
echo "output warps ok"
