#!/usr/bin/env bash
# pipewire_out.sh VITRINE OUTDIR: the gallery's picture as PipeWire video sources. A private PipeWire
# daemon (and WirePlumber, which links a consumer to the node it names, under a private D-Bus) runs in a
# runtime folder of the test's own; the gallery on a virtual X display publishes the whole frame
# (--pipewire) and, from --outputs, the right half of it through that output's warp. GStreamer's
# pipewiresrc takes frames from each node: each equals the headless frame of the same scene, size and
# warp, as 8-bit sRGB, to within one step. The calibration card holds still, so every frame is the
# same moment. A consumer that stops reading (SIGSTOP) does not slow the gallery: its frame rate stays
# at least what it was with a consumer reading, and the node counts the frames it dropped. Without a
# daemon, one line says so and the gallery runs.
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out/config" "$out/work" "$out/run" "$out/empty-run"
chmod 700 "$out/run" "$out/empty-run"
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log" 2>/dev/null; tail -5 "$out/pipewire.log" "$out/wireplumber.log" 2>/dev/null; exit 1; }
for tool in pipewire wireplumber dbus-run-session gst-launch-1.0 Xvfb oiiotool; do
  command -v $tool >/dev/null || { echo "SKIP: $tool is not installed (scripts/setup --test installs it)"; exit 0; }
done

. "$here/virtual_display.sh"
app= daemon= manager= consumer=
trap 'kill $app $consumer $manager $daemon $xvfb 2>/dev/null; kill -CONT $consumer 2>/dev/null; wait 2>/dev/null' EXIT
start_display 320x180

export XDG_RUNTIME_DIR=$out/run PIPEWIRE_RUNTIME_DIR=$out/run
# The daemon's own D-Bus modules (portal, rtkit) are optional: without a session bus they say so and it runs.
pipewire >"$out/pipewire.log" 2>&1 &
daemon=$!
for _ in $(seq 100); do [ -S "$out/run/pipewire-0" ] && break; sleep 0.1; done
[ -S "$out/run/pipewire-0" ] || fail "the PipeWire daemon did not start"
dbus-run-session -- wireplumber >"$out/wireplumber.log" 2>&1 &
manager=$!

echo '{"region": [0.5, 0, 1, 1]}' >"$out/right.json"
echo '[{"pipewire": "vitrine-right", "size": [160, 180], "warp": {"region": [0.5, 0, 1, 1]}}]' >"$out/outputs.json"
gallery() {  # the gallery publishing both nodes, into $log
  : >"$log"
  (cd "$out/work" && DISPLAY=$display XDG_CONFIG_HOME=$out/config exec "$vitrine" --scene calibrate --size 320x180 \
     --no-vsync --validate --pipewire vitrine-test --outputs "$out/outputs.json") >"$log" 2>&1 &
  app=$!
  wait_for_showing "$log"
}
stop_gallery() {
  kill -TERM $app
  for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
  wait $app || fail "the gallery failed"
  grep -q "validation messages" "$log" && fail "validation messages"
}
# take NODE COUNT FILE W H: COUNT frames of NODE as raw 8-bit RGB, the last kept in FILE.
take() {
  timeout 60 gst-launch-1.0 -q pipewiresrc target-object="$1" num-buffers="$2" always-copy=true ! videoconvert ! \
    "video/x-raw,format=RGB,width=$4,height=$5" ! multifilesink location="$out/$3-%d.rgb" >"$out/$3.log" 2>&1 ||
    fail "no frames from node $1: $(cat "$out/$3.log")"
  ls "$out/$3"-*.rgb >/dev/null 2>&1 || fail "node $1 gave no frame"
}
# same WANT.png GOT.rgb: the largest difference between a headless PNG and a frame taken, in 8-bit steps.
same() {
  oiiotool "$1" -o "$1.ppm" || fail "cannot read $1"
  python3 - "$1.ppm" "$2" <<'EOF'
import sys
want = open(sys.argv[1], "rb").read()
want = want[want.index(b"255\n") + 4:]
got = open(sys.argv[2], "rb").read()
assert len(want) == len(got), f"{len(got)} bytes taken, {len(want)} in the headless frame"
print(max(abs(a - b) for a, b in zip(want, got)))
EOF
}

gallery
"$vitrine" --headless --scene calibrate --size 320x180 --out "$out/whole.png" >/dev/null || fail "headless whole frame"
"$vitrine" --headless --scene calibrate --size 160x180 --output-warp "$out/right.json" --out "$out/right.png" \
  >/dev/null || fail "headless right half"
take vitrine-test 4 whole 320 180
take vitrine-right 4 right 160 180
for frame in "$out"/whole-*.rgb; do
  worst=$(same "$out/whole.png" "$frame") || fail "$frame: $worst"
  [ "$worst" -le 1 ] || fail "$frame differs from the headless frame by $worst steps"
done
for frame in "$out"/right-*.rgb; do
  worst=$(same "$out/right.png" "$frame") || fail "$frame: $worst"
  [ "$worst" -le 1 ] || fail "$frame (the warped output) differs from the headless frame by $worst steps"
done
echo "frames taken: $(ls "$out"/whole-*.rgb | wc -l) whole, $(ls "$out"/right-*.rgb | wc -l) warped, each within 1 step"
stop_gallery

# fps LOG: the gallery's frames a second, from its last line.
fps() { sed -n 's/^vitrine: showed .* (\([0-9.]*\) fps)$/\1/p' "$1"; }
# A consumer reading throughout, then one that stops: the gallery keeps its pace and the node drops.
for mode in reading stopped; do
  gallery
  gst-launch-1.0 -q pipewiresrc target-object=vitrine-test ! fakesink sync=false >"$out/consumer.log" 2>&1 &
  consumer=$!
  sleep 2
  [ $mode = stopped ] && kill -STOP $consumer
  sleep 4
  stop_gallery
  kill -CONT $consumer 2>/dev/null; kill $consumer 2>/dev/null; wait $consumer 2>/dev/null; consumer=
  cp "$log" "$out/$mode.log"
done
reading=$(fps "$out/reading.log"); stopped=$(fps "$out/stopped.log")
line=$(grep "^vitrine: pipewire: node vitrine-test" "$out/stopped.log")
dropped=$(echo "$line" | sed -n 's/.*, \([0-9]*\) dropped$/\1/p')
echo "gallery $reading fps with a consumer reading, $stopped fps with it stopped; $line"
python3 -c "import sys; r, s = map(float, sys.argv[1:]); sys.exit(0 if s >= 0.8 * r else 1)" "$reading" "$stopped" ||
  fail "a stopped consumer slowed the gallery from $reading to $stopped fps"
[ "${dropped:-0}" -gt 0 ] || fail "the stopped consumer's frames were not counted as dropped: $line"

# No daemon: one line, and the gallery shows its frames.
XDG_RUNTIME_DIR=$out/empty-run PIPEWIRE_RUNTIME_DIR=$out/empty-run gallery
stop_gallery
[ "$(grep -c "^vitrine: pipewire: no PipeWire daemon" "$log")" = 1 ] || fail "not one line saying there is no daemon"
echo "without a daemon: $(grep "^vitrine: pipewire: no PipeWire daemon" "$log")"
echo "pass"
