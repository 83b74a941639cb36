#!/usr/bin/env bash
# gallery_typing.sh VITRINE OUTDIR: digits typed into a menu field never switch scenes. The gallery
# on a virtual X display, its menu's time section open (from the layout file); Ctrl+click turns the
# speed slider into a field and "3" (neon's number key) is typed at once, as a person does at a few
# frames a second, then Enter. The scene the settings file names on exit is still bloom, and the
# [ ] \ speed keys and Esc still work after the field is left.
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
# The speed slider's row: under the fps line, five scenes, the section header and the vsync row.
keys ctrlclick:40,259 key:3 sleep:3 key:Return sleep:3 move:600,340 sleep:2 key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app; code=$?
scene=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["scene"])' "$out/config/vitrine/settings.json")
[ "$scene" = bloom ] || fail "the digit typed into the speed field switched the scene to $scene"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code"
echo "gallery typing ok"
