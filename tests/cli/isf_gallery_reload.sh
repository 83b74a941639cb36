#!/usr/bin/env bash
# isf_gallery_reload.sh VITRINE OUTDIR: the gallery on a virtual X display showing an ISF piece
# (--isf) while its file is edited: a save that breaks it is said on the console with the author's
# file and line while the old version keeps drawing (the window's picture unchanged), and a save that
# mends it is taken up (the picture changes to the new colour). Edits are polled and compiled off the
# frame thread, so the frames keep coming throughout.
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out/config" "$out/home" "$out/data"
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
piece=$out/flat.fs
write() {  # write COLOUR: the piece, one flat colour
  printf '/*{ "ISFVSN": "2", "INPUTS": [{"NAME": "level", "TYPE": "float", "DEFAULT": 1.0}] }*/\nvoid main() { gl_FragColor = vec4(%s * level, 1.0); }\n' "$1" >"$piece.tmp"
  mv "$piece.tmp" "$piece"
}
write 'vec3(1.0, 0.0, 0.0)'

. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 320x180
(DISPLAY=$display HOME=$out/home XDG_CONFIG_HOME=$out/config XDG_DATA_HOME=$out/data exec "$vitrine" --isf "$piece" \
   --size 320x180 --validate) >"$log" 2>&1 &
app=$!
keys() { python3 "$here/xtest.py" "$display" "$@" || fail "xtest $*"; }
wait_for_showing "$log"
grep -q "^vitrine: showing flat " "$log" || fail "--isf did not start on the piece"
keys key:Tab sleep:1 shot:200,120,40,40,"$out/red.ppm"

sleep 1.1  # a file system whose times tick in seconds must see each edit as newer
write 'vec3(0.0, 1.0, 0.0) * brokn'
wait_for_line "$log" "flat.fs:2: error: 'brokn' : undeclared identifier" "the broken edit was not reported"
keys sleep:1 shot:200,120,40,40,"$out/still-red.ppm"
[ "$(grab_changes "$out/red.ppm" "$out/still-red.ppm")" -eq 0 ] || fail "the broken edit changed the picture"

sleep 1.1
write 'vec3(0.0, 1.0, 0.0)'
wait_for_line "$log" "flat.fs reloaded" "the mended edit was not taken up"
keys sleep:1 shot:200,120,40,40,"$out/green.ppm"
[ "$(grab_changes "$out/red.ppm" "$out/green.ppm")" -gt 1000 ] || fail "the mended edit did not change the picture"
keys key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app || fail "the gallery exited with $?"
grep -q "validation" "$log" && fail "the validation layer spoke"
echo "isf gallery reload: broken edit reported and the old version kept, mended edit drawn"
