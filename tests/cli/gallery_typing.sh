#!/usr/bin/env bash
# gallery_typing.sh VITRINE OUTDIR: digits typed into a menu field never switch scenes. The gallery
# on a virtual X display, its menu's time section open (from the layout file); Ctrl+click turns the
# speed slider into a field and "3" (neon's number key) is typed at once, as a person does at a few
# frames a second, then Enter. The slider then shows another speed, the scene the settings file names
# on exit is still bloom, and after the field is left the \ key (back to 1x) and Esc still work. With
# vsync on (the default) the window shows at most a frame a refresh: 60 Hz where Xvfb names none.
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out/config/vitrine" "$out/work"
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
printf '[Window][Vitrine]\nPos=12,12\nCollapsed=0\n\n[Vitrine][menu]\ntime=1\npanel=0\ntimings=0\n' \
  >"$out/config/vitrine/gallery-menu.ini"

. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 640x360

(cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config exec "$vitrine" --scene bloom --size 640x360 \
   --validate --set bloom.lattice=48) >"$log" 2>&1 &
app=$!
keys() { python3 "$here/xtest.py" "$display" "$@" || fail "xtest $*"; }
wait_for_showing "$log"
# The speed slider's row: under the fps line, five scenes, the calibration card, the section header and
# the vsync row. Its picture before, after the typed speed, and after \ (1x again), the cursor away
# from it (a hovered slider is lit and shows a tooltip).
slider=20,272,148,24
keys shot:$slider,"$out/slider-1x.ppm" ctrlclick:40,284 key:3 sleep:3 key:Return sleep:1 move:600,340 sleep:2 \
  shot:$slider,"$out/slider-typed.ppm" key:backslash sleep:1 shot:$slider,"$out/slider-back.ppm" key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app; code=$?
scene=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["scene"])' "$out/config/vitrine/settings.json")
[ "$scene" = bloom ] || fail "the digit typed into the speed field switched the scene to $scene"
[ "$(grab_changes "$out/slider-1x.ppm" "$out/slider-typed.ppm")" -gt 20 ] || fail "the typed speed did not reach the slider"
[ "$(grab_changes "$out/slider-1x.ppm" "$out/slider-back.ppm")" = 0 ] || fail "\\ did not set the speed back to 1x"
fps=$(sed -n 's/^vitrine: showed .* (\([0-9.]*\) fps)$/\1/p' "$log")
python3 -c 'import sys; sys.exit(not 0 < float(sys.argv[1]) <= 61.5)' "${fps:-0}" ||
  fail "vsync on, yet the window showed ${fps:-no} frames a second (at most 60 Hz)"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code"
echo "gallery typing ok"
