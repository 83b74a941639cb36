#!/usr/bin/env bash
# flash_guard.sh VITRINE OUTDIR: the calibration card's strobe (10 Hz over a quarter of the frame)
# flashes about ten times a second without the flash guard, and no more than three times in any one
# second through it (on by default with --reduced-motion), counted by flash_count.py on the frames
# written, white and saturated red. A still card goes through the guard unchanged, bit for bit.
set -euo pipefail
vitrine=$1; out=$2
here=$(dirname "$0")
rm -rf "$out"; mkdir -p "$out"
strobe=(record --scene calibrate --size 128x72 --fps 30 --validate --set strobe=on)
card=("${strobe[@]}" --seconds 3)
"$vitrine" "${card[@]}" --out "$out/bare" >/dev/null
python3 "$here/flash_count.py" "$out/bare" 30 --at-least 9 | tee "$out/bare.txt"
"$vitrine" "${card[@]}" --reduced-motion --out "$out/guarded" >/dev/null
python3 "$here/flash_count.py" "$out/guarded" 30 --at-most 3 --at-least 2 | tee "$out/guarded.txt"
"$vitrine" "${card[@]}" --reduced-motion --set strobe_colour=red --out "$out/red" >/dev/null
python3 "$here/flash_count.py" "$out/red" 30 --at-most 3 --at-least 2 | tee "$out/red.txt"
grep -Eq " and (2|2.5|3) red flashes" "$out/red.txt"  # red on black is a general flash too
# --flash-guard off wins over --reduced-motion's default.
"$vitrine" "${strobe[@]}" --seconds 1 --reduced-motion --flash-guard off --out "$out/off" >/dev/null
python3 "$here/flash_count.py" "$out/off" 30 --at-least 9
# Without the strobe the card is still: the guard changes no bit of any frame.
still=(record --scene calibrate --size 128x72 --fps 30 --seconds 0.5 --validate)
"$vitrine" "${still[@]}" --flash-guard on --out "$out/still-on" >/dev/null
"$vitrine" "${still[@]}" --flash-guard off --out "$out/still-off" >/dev/null
same=$(oiiotool --frames 0-14 "$out/still-on/frame_%06d.exr" "$out/still-off/frame_%06d.exr" --absdiff --printstats |
  grep -c "Max: 0.000000 0.000000 0.000000 0.000000" || true)
[ "$same" = 15 ] || { echo "the guard changed $((15 - same)) of 15 still frames"; exit 1; }
# ...while it does change the strobe's frames (the comparison can fail).
same=$(oiiotool --frames 0-89 "$out/guarded/frame_%06d.exr" "$out/bare/frame_%06d.exr" --absdiff --printstats |
  grep -c "Max: 0.000000 0.000000 0.000000 0.000000" || true)
[ "$same" -lt 90 ]
echo "flash guard: ok"
