#!/usr/bin/env bash
# outputs.sh VITRINE OUTDIR: a projector pair from one render. The gallery on a virtual X display
# 1280x360: the main window (640x360 at the left) shows the left half of the frame (--output-warp with a
# region), and a second output (--outputs: a window without a frame at 640,0) the right half. What the
# screen shows, grabbed through X11, is a headless render of the whole 1280x360 frame to within 8-bit
# rounding: the scene rendered once at the frame's size and each output drew its own half; Esc with the
# second output focused quits. Projector setup (F7) drags a corner of each output and keeps the pins in
# the warp file and the settings file, and the next start shows them. kifs under --reduced-motion holds
# still, at the low tier the headless run is given too (the cheapest frame that still shows the whole
# fractal; a gallery without vsync draws flat out while the script waits). Then --span: one window over
# the whole desktop shows the same frame, and so does a window grown past the shared memory the system
# grants. --list-monitors lists the display's monitor, and a monitor that is not there, a bad outputs file
# or a window larger than the device draws, is refused. On lavapipe the windows are drawn through X shared memory
# (src/host/present/shm_presenter.h); the spanning window goes through Vulkan's swapchain (VITRINE_PRESENT=
# swapchain), so both paths are held to the headless frame.
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out/config" "$out/work"
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
echo '{"region": [0, 0, 0.5, 1]}' >"$out/left.json"
echo '[{"window": [640, 0, 640, 360], "warp": {"region": [0.5, 0, 1, 1]}}]' >"$out/outputs.json"

. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 1280x360

: >"$log"
(cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config exec "$vitrine" --scene kifs --reduced-motion \
   --set tier=low --size 640x360 --no-vsync --validate --output-warp "$out/left.json" --outputs "$out/outputs.json") \
   >"$log" 2>&1 &
app=$!
keys() { python3 "$here/xtest.py" "$display" "$@" || fail "xtest $*"; }
wait_for_showing "$log"
keys key:Tab sleep:3 shot:0,0,1280,360,"$out/screen.ppm"
oiiotool "$out/screen.ppm" --colorconvert sRGB linear -o "$out/screen.exr" || fail "cannot read the grab"
"$vitrine" --headless --scene kifs --reduced-motion --set tier=low --size 1280x360 --out "$out/frame.exr" >/dev/null
"$vitrine" compare --fail-fraction 0 --hard-limit 0.01 "$out/frame.exr" "$out/screen.exr" | tee "$out/compare.txt" |
  grep -q "^pass" || fail "the two outputs do not show the frame's halves: $(cat "$out/compare.txt")"
grep -q "^vitrine: frames reach the window through X shared memory" "$log" || fail "not drawn through X shared memory"
# Esc pressed while the second output has the keyboard's focus still reaches the gallery.
keys focus:960,180 key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
kill -0 $app 2>/dev/null && fail "Esc in the second output's window did not reach the gallery"
wait $app; code=$?
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code"

# Projector setup (F7) with a second output: the main window's top-left corner dragged in by a tenth and
# nudged one pixel right; F7 keeps it and goes on to the output named "right", which the main window then
# shows; its bottom-right corner dragged in by a tenth; Enter keeps that. The main pin is written to the
# --output-warp file, both to the settings file under the outputs' names; the screen's corners are black.
echo '{}' >"$out/pin.json"
echo '[{"window": [640, 0, 640, 360], "name": "right"}]' >"$out/pair.json"
: >"$log"
(cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config exec "$vitrine" --scene kifs --reduced-motion \
   --size 640x360 --no-vsync --validate --output-warp "$out/pin.json" --outputs "$out/pair.json") >"$log" 2>&1 &
app=$!
wait_for_showing "$log"
keys key:Tab key:F7
wait_for_setup "$log" main
keys drag:1,1,64,36 sleep:1 key:Right key:F7
wait_for_setup "$log" right
keys drag:639,359,576,324 sleep:1 key:Return sleep:2 shot:0,0,16,8,"$out/pinned.ppm" \
  shot:1264,352,16,8,"$out/pinned-right.ppm" key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app || fail "the gallery in projector setup failed"
python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["corners"]; assert c[0] == [0.1015625, 0.1] and c[2] == [1, 1], c' \
  "$out/pin.json" || fail "the kept pin: $(cat "$out/pin.json")"
python3 - "$out/config/vitrine/settings.json" <<'PY' || fail "the pins in the settings: $(cat "$out/config/vitrine/settings.json")"
import json, sys
outputs = json.load(open(sys.argv[1]))["outputs"]
assert outputs["main"]["corners"][0] == [0.1015625, 0.1], outputs
assert outputs["right"]["corners"][2] == [0.9, 0.9] and outputs["right"]["corners"][0] == [0, 0], outputs
PY
black() { python3 -c 'import sys; d = open(sys.argv[1], "rb").read(); assert max(d[d.index(b"255\n") + 4:]) == 0, "not black"' "$1" 2>/dev/null; }
black "$out/pinned.ppm" || fail "the pinned picture still reaches the main window's corner"
black "$out/pinned-right.ppm" || fail "the pinned picture still reaches the right output's corner"

# The next start, with no --output-warp, shows both outputs through the pins the settings file kept.
: >"$log"
(cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config exec "$vitrine" --scene kifs --reduced-motion \
   --size 640x360 --no-vsync --validate --outputs "$out/pair.json") >"$log" 2>&1 &
app=$!
wait_for_showing "$log"
keys key:Tab sleep:2 shot:0,0,16,8,"$out/again.ppm" shot:1264,352,16,8,"$out/again-right.ppm" shot:300,170,16,8,"$out/middle.ppm" key:Escape
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app || fail "the gallery with saved pins failed"
black "$out/again.ppm" || fail "the main window's saved pin was not applied"
black "$out/again-right.ppm" || fail "the right output's saved pin was not applied"
black "$out/middle.ppm" && fail "the middle of the main window is black: nothing drawn"

# Where the system grants no shared-memory segment as big as the window (VITRINE_INJECT=shm-bytes: 640x360
# fits, 1280x360 does not), the window goes on through Vulkan's swapchain: F11 makes it fullscreen, and it
# shows the whole frame. F11 again makes it 640x360, which fits: its frames go through X shared memory
# again, and it shows the 640x360 frame.
: >"$log"
(cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config-small VITRINE_INJECT=shm-bytes:1000000 exec "$vitrine" \
   --scene kifs --reduced-motion --set tier=low --size 640x360 --no-vsync --validate) >"$log" 2>&1 &
app=$!
wait_for_showing "$log"
keys key:Tab key:F11 sleep:3 shot:0,0,1280,360,"$out/grown.ppm" key:F11 sleep:3 shot:0,0,640,360,"$out/shrunk.ppm" \
  key:Escape
oiiotool "$out/grown.ppm" --colorconvert sRGB linear -o "$out/grown.exr" || fail "cannot read the grab"
"$vitrine" compare --fail-fraction 0 --hard-limit 0.01 "$out/frame.exr" "$out/grown.exr" | tee "$out/compare.txt" |
  grep -q "^pass" || fail "the grown window does not show the frame: $(cat "$out/compare.txt")"
grep -q "^vitrine: frames reach a 1280x360 window through Vulkan's swapchain until it fits (shmget of 1843200 bytes" \
  "$log" || fail "the grown window did not turn to Vulkan's swapchain"
"$vitrine" --headless --scene kifs --reduced-motion --set tier=low --size 640x360 --out "$out/small.exr" >/dev/null
oiiotool "$out/shrunk.ppm" --colorconvert sRGB linear -o "$out/shrunk.exr" || fail "cannot read the grab"
"$vitrine" compare --fail-fraction 0 --hard-limit 0.01 "$out/small.exr" "$out/shrunk.exr" | tee "$out/compare.txt" |
  grep -q "^pass" || fail "the window made small again does not show the frame: $(cat "$out/compare.txt")"
grep -q "^vitrine: frames reach a 640x360 window through X shared memory again" "$log" ||
  fail "the window made small again stayed on Vulkan's swapchain"
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app; code=$?
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "the grown window's gallery: exit $code"

# One window spanning the desktop (its one monitor here) shows the whole frame (a fresh settings file),
# through Vulkan's swapchain.
: >"$log"
(cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config-span VITRINE_PRESENT=swapchain exec "$vitrine" --scene kifs --reduced-motion \
   --set tier=low --span --no-vsync --validate) >"$log" 2>&1 &
app=$!
wait_for_showing "$log"
keys key:Tab sleep:3 shot:0,0,1280,360,"$out/span.ppm" key:Escape
oiiotool "$out/span.ppm" --colorconvert sRGB linear -o "$out/span.exr" || fail "cannot read the grab"
"$vitrine" compare --fail-fraction 0 --hard-limit 0.01 "$out/frame.exr" "$out/span.exr" | tee "$out/compare.txt" |
  grep -q "^pass" || fail "the spanning window does not show the frame: $(cat "$out/compare.txt")"
grep -q "^vitrine: frames reach the window through Vulkan's swapchain (VITRINE_PRESENT=swapchain)" "$log" ||
  fail "VITRINE_PRESENT=swapchain did not choose Vulkan's swapchain"
for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
wait $app || fail "the spanning gallery failed"

DISPLAY=$display "$vitrine" --list-monitors | grep -q '^\* 0 .* 1280x360 at 0,0' || fail "--list-monitors"
if DISPLAY=$display "$vitrine" --monitor projector 2>"$out/err.txt"; then fail "a monitor that is not there"; fi
grep -q "No monitor 'projector'; there are:" "$out/err.txt" || fail "$(cat "$out/err.txt")"
echo '[{"window": [0, 0, 640, 360], "monitor": "0"}]' >"$out/both.json"
if DISPLAY=$display "$vitrine" --outputs "$out/both.json" 2>"$out/err.txt"; then fail "both a window and a monitor"; fi
grep -q "both.json, output 1: an output is fullscreen on a monitor, a window at a place or a PipeWire node, one of them" "$out/err.txt" ||
  fail "$(cat "$out/err.txt")"
echo '[{"window": [0, 0, 100000, 100000]}]' >"$out/huge.json"
if DISPLAY=$display "$vitrine" --outputs "$out/huge.json" 2>"$out/err.txt"; then fail "a window past the device's limit"; fi
grep -q "huge.json, output 1: a window of 100000x100000 is outside what .* supports" "$out/err.txt" ||
  fail "$(cat "$out/err.txt")"
echo "outputs ok"
