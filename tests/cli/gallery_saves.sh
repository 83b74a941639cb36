#!/usr/bin/env bash
# gallery_saves.sh VITRINE OUTDIR: the gallery on a virtual X display, driven by keys sent through
# XTEST (xtest.py). F12 saves what the window shows at the window's size, whatever the scene renders
# at (bloom's low tier renders 160x90 in a 320x180 window), names the render size in the PNG's
# metadata and prints the absolute path on the console, with the UI shown and hidden alike. F9 twice
# captures a sequence; the console's last word on it, said as soon as it is true, counts the frames on disk.
# Both land in the user's XDG folders under Vitrine/ (the pictures folder as user-dirs.dirs names it, the
# videos folder by its default name), never in the folder the gallery was started from.
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out/config" "$out/work" "$out/home"
echo 'XDG_PICTURES_DIR="$HOME/Bilder"' >"$out/config/user-dirs.dirs"
pictures=$out/home/Bilder/Vitrine videos=$out/home/Videos/Vitrine
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }

. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 320x180

(cd "$out/work" && DISPLAY=$display HOME=$out/home XDG_CONFIG_HOME=$out/config exec "$vitrine" --scene bloom --size 320x180 \
   --validate --set bloom.tier=low) >"$log" 2>&1 &
app=$!
keys() { python3 "$here/xtest.py" "$display" "$@" || fail "xtest $*"; }
wait_for_showing "$log"
keys key:F12 sleep:3 shot:0,0,160,40,"$out/ui-shown.ppm" key:Tab sleep:1 shot:0,0,160,40,"$out/ui-hidden.ppm" \
  key:F12 sleep:3 key:Tab
keys key:F9 sleep:3 key:F9 sleep:4
# Said on the console once the last frame is on disk, while the gallery runs (not only at quit).
grep -q "^vitrine: captured $videos/.*written" "$log" || fail "the capture's summary waited for quit"
keys key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app; code=$?

# Tab hid the menu between the two screenshots: the window's top-left corner changed.
[ "$(grab_changes "$out/ui-shown.ppm" "$out/ui-hidden.ppm")" -gt 500 ] || fail "Tab did not hide the menu"
shots=("$pictures"/*.png)
[ ${#shots[@]} = 2 ] && [ -f "${shots[0]}" ] || fail "two screenshots expected, found: ${shots[*]}"
for png in "${shots[@]}"; do
  python3 - "$png" <<'EOF' || fail "$png"
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
width, height = struct.unpack(">II", data[16:24])
text, at = {}, 8
while at < len(data):
    length, kind = struct.unpack(">I4s", data[at:at + 8])
    body = data[at + 8:at + 8 + length]
    if kind == b"tEXt":
        key, _, value = body.partition(b"\0")
        text[key.decode()] = value.decode()
    elif kind == b"zTXt":
        key, _, rest = body.partition(b"\0")
        text[key.decode()] = zlib.decompress(rest[1:]).decode()
    elif kind == b"iTXt":
        key, _, rest = body.partition(b"\0")
        text[key.decode()] = rest[2:].split(b"\0", 2)[2].decode()
    at += 12 + length
print(sys.argv[1], f"{width}x{height}", text)
assert (width, height) == (320, 180), f"saved at {width}x{height}, not the window's 320x180"
assert text.get("vitrine:render_size") == "160x90", f"render size not in the metadata: {text}"
EOF
done
grep -q "^vitrine: saved $pictures/vitrine-bloom-" "$log" || fail "no absolute path on the console"
frames=$(ls "$videos"/*/frame_*.exr 2>/dev/null | wc -l)
[ "$frames" -gt 0 ] || fail "no captured frames"
grep -q "^vitrine: captured $videos/.*: $frames frames\? written" "$log" ||
  fail "the capture's last line does not count the $frames frames on disk"
[ -z "$(ls -A "$out/work")" ] || fail "the gallery wrote into its working folder: $(ls "$out/work")"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code"
cat "$log"
echo "gallery saves ok"
