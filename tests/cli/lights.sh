#!/usr/bin/env bash
# lights.sh VITRINE PROBE OUTDIR: the room's lights through a real olad (docs/LIGHTS.md), started here
# with a configuration of its own (every plugin off, no HTTP, an RPC port that was free), and read and
# written with OLA's own client library (PROBE: tests/support/ola_probe.cpp).
# - bloom's phase colour on the bloom fixture at each phase (forced with --set fill), the chamber's
#   brightness and the climax on their dimmers, and the frame's region means on a pixel strip, as the
#   run's own frame has them;
# - a DMX value injected through olad moves a mapped parameter (soft takeover) within a frame;
# - olad killed and started again mid-run: said once each way, the run goes on and lights again;
# - a client flooding the input universe as fast as it can does not slow the run down;
# - hostile patches refused with FILE:LINE. Skips (77) where olad is not installed.
set -u
vitrine=$1; probe=$2; out=$3
rm -rf "$out"; mkdir -p "$out"
command -v olad >/dev/null || { echo "SKIP: olad is not installed (Debian's ola)"; exit 77; }
olad_pid=; watch_pid=; run_pid=; app=; xvfb=
trap 'kill $olad_pid $watch_pid $run_pid 2>/dev/null; wait 2>/dev/null' EXIT
fail() {
  echo "FAIL: $*"
  for log in "$out"/*.log; do echo "== $log"; tail -n 15 "$log"; done
  exit 1
}

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
conf=$out/olad
mkdir -p "$conf"
# Every plugin off: no Art-Net or sACN sockets on the machine's network, and a start in milliseconds.
for plugin in artnet dummy e131 espnet ftdidmx gpio karate kinet milinst opendmx openpixelcontrol osc pathport \
              renard sandnet shownet spi stageprofi uartdmx usbdmx usbserial; do
  echo "enabled = false" >"$conf/ola-$plugin.conf"
done
# olad refuses to run as root: under root (containers, CI) it runs as nobody.
as_user=()
if [ "$(id -u)" = 0 ]; then chmod -R a+rwX "$out"; as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups); fi
start_olad() {
  "${as_user[@]}" olad -c "$conf" --no-http --no-register-with-dns-sd -r "$port" -l 2 >>"$out/olad.log" 2>&1 &
  olad_pid=$!
  for _ in $(seq 200); do (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && return; sleep 0.02; done
  fail "olad did not start"
}
# watch UNIVERSE: a client registered for the universe, its frames a line each in $out/watch.txt.
watch() {
  [ -n "$watch_pid" ] && { kill $watch_pid; wait $watch_pid 2>/dev/null; }
  : >"$out/watch.txt"
  "$probe" "$port" watch "$1" 600 >"$out/watch.txt" 2>"$out/watch.log" &
  watch_pid=$!
  for _ in $(seq 200); do grep -q watching "$out/watch.log" && return; sleep 0.02; done
  fail "the probe did not register"
}
last_frame() { tail -n 1 "$out/watch.txt" | cut -d' ' -f2; }
channels() { last_frame | cut -d, -f"$1"; }  # channels FIRST-LAST: the last frame's values

start_olad
cat >"$out/patch.json" <<JSON
{"grid": [8, 1], "input": [2], "olad": $port,
 "fixtures": [
  {"name": "crystal", "type": "rgb", "universe": 1, "address": 1, "signal": "bloom.phase"},
  {"name": "chamber", "type": "dimmer", "universe": 1, "address": 4, "signal": "bloom.chamber"},
  {"name": "climax", "type": "dimmer", "universe": 1, "address": 5, "signal": "bloom.climax"},
  {"name": "wall", "type": "pixels", "count": 8, "universe": 1, "address": 11, "signal": "regions"}]}
JSON
watch 1

# Bloom at each phase: the crystal's colour is the phase's (bloom_math.h, kPhaseColours, as DMX levels).
# The fill held (no venting), so the phase it starts in is the phase it shows at the last frame.
for phase in "pristine 0 219,227,237" "amber 0.35 244,102,5" "rose 0.55 214,40,77" "crimson 0.75 77,1,4" "chroma 0.95 77,1,4"; do
  set -- $phase
  "$vitrine" --headless --scene bloom --size 64x36 --frames 30 --set fill="$2" --set decay_venting=0 --validate --lights "$out/patch.json" \
    --events "$out/$1.jsonl" --out "$out/$1.exr" >"$out/$1.log" 2>&1 || fail "$1: exit $?"
  grep -q "olad connected" "$out/$1.log" || fail "$1: never connected"
  for _ in $(seq 100); do [ "$(channels 1-3)" = "$3" ] && break; sleep 0.02; done
  [ "$(channels 1-3)" = "$3" ] || fail "$1: the crystal fixture shows $(channels 1-3), not $3"
  climax=$(channels 5)
  if [ "$1" = chroma ]; then [ "$climax" = 255 ] || fail "chroma: the climax dimmer reads $climax"
  else [ "$climax" = 0 ] || fail "$1: the climax dimmer reads $climax"; fi
  # The wall strip: the mean of each eighth of the run's own frame (a box filter of 8x36 pixels).
  oiiotool "$out/$1.exr" --ch R,G,B --clamp:min=0:max=1 --resize:filter=box 8x1 -d float -o "$out/$1-strip.exr" ||
    fail "$1: oiiotool"
  expected=$(oiiotool --dumpdata "$out/$1-strip.exr" | sed -nE 's/.*Pixel \([0-9]+, 0\): *(.*)/\1/p' |
    python3 -c 'import sys; print(",".join(str(round(float(v) * 255)) for line in sys.stdin for v in line.split()))')
  python3 - "$(channels 11-34)" "$expected" "$1" <<'PY' || fail "$1: the wall strip"
import sys
got = [int(v) for v in sys.argv[1].split(",")]
want = [int(v) for v in sys.argv[2].split(",")]
assert len(got) == len(want) == 24, (got, want)
worst = max(abs(a - b) for a, b in zip(got, want))
assert worst <= 2, (sys.argv[3], "strip", got, "frame", want)
print(f"{sys.argv[3]}: the wall strip within {worst} of the frame's region means")
PY
  echo "$1: crystal $(channels 1-3), chamber $(channels 4), climax $(channels 5)"
done

# Neon: its tubes along a 32-pixel strip, each cell in a tube's own colour (pink, cyan or amber) where
# the autopilot's tubes are over it, the rest dark.
cat >"$out/neon.json" <<JSON
{"olad": $port, "fixtures": [{"name": "strip", "type": "pixels", "count": 32, "universe": 1, "address": 1, "signal": "neon.tubes"},
                             {"name": "glow", "type": "rgb", "universe": 1, "address": 97, "signal": "neon.glow"}]}
JSON
"$vitrine" --headless --scene neon --size 64x36 --frames 120 --validate --lights "$out/neon.json" --out "$out/neon.exr" \
  >"$out/neon.log" 2>&1 || fail "neon: exit $?"
for _ in $(seq 100); do [ "$(channels 100-102)" = "0,0,0" ] && break; sleep 0.02; done  # our patch's last frame
python3 - "$(channels 1-99)" <<'PY' || fail "neon: the tubes' strip"
import sys
v = [int(x) for x in sys.argv[1].split(",")]
cells = [tuple(v[i:i + 3]) for i in range(0, 96, 3)]
lit = [c for c in cells if any(c)]
assert 0 < len(lit) < 32, ("lit cells", cells)
assert any(v[96:99]), ("glow", v[96:99])
print(f"neon: {len(lit)} of 32 strip cells lit by tubes, glow {tuple(v[96:99])}")
PY

# DMX in: a fader on universe 2 channel 1 plays kifs' fold (soft takeover: from 0 to full it passes the
# value, so it takes over); the step that takes the frame is the one whose parameter moves. Channel 9 is
# the patch's blackout source: the run's last lights are dark.
sed 's/"grid": \[8, 1\],/"grid": [8, 1], "blackout_source": "dmx.2.9",/' "$out/patch.json" >"$out/patch_in.json"
"$vitrine" --headless --scene kifs --size 64x36 --frames 150 --validate --lights "$out/patch_in.json" \
  --map 'dmx.2.1=kifs.fold:0.9:1.2' --events "$out/dmx_in.jsonl" --out "$out/dmx_in.exr" >"$out/dmx_in.log" 2>&1 &
run_pid=$!
for _ in $(seq 500); do grep -q "olad connected" "$out/dmx_in.log" && break; sleep 0.01; done
sleep 1  # past the first frames (pipelines built), at the run's steady 60 steps a second
sent=$("$probe" "$port" set 2 255,0,0,0,0,0,0,0,255) || fail "ola_probe set"
wait $run_pid || fail "dmx in: exit $?"
run_pid=
python3 - "$out/dmx_in.jsonl" "$sent" <<'PY' || fail "dmx in"
import json, sys
events = [json.loads(line) for line in open(sys.argv[1])]
sent = float(sys.argv[2])
dmx = [e for e in events if e["event"] == "dmx"]
mapped = [e for e in events if e["event"] == "mapped" and e["key"] == "fold"]
assert dmx and mapped, events
assert mapped[0]["t"] == dmx[0]["t"] and mapped[0]["value"] == "1.2", (dmx, mapped)
to_olad = dmx[0]["arrived"] - sent
to_step = dmx[0]["taken"] - sent
# A step every 16.7 ms takes what came before it; the margin is for a loaded machine's scheduling.
assert to_step < 2 / 60, f"injected to taken {to_step * 1000:.1f} ms: more than two steps"
print(f"dmx in: injected -> arrived {to_olad * 1000:.2f} ms, -> taken by the step {to_step * 1000:.2f} ms; fold 1.2 at t={mapped[0]['t']:.3f}")
PY
for _ in $(seq 100); do [ "$(channels 1-34 | tr -d ',0')" = "" ] && break; sleep 0.02; done
[ "$(channels 1-34 | tr -d ',0')" = "" ] || fail "the blackout source left $(channels 1-34)"

# olad killed and back mid-run: one line each way, the run ends normally and its last frame lights.
"$vitrine" --headless --scene bloom --size 64x36 --frames 200 --set fill=0.35 --set decay_venting=0 --validate --lights "$out/patch.json" \
  --out "$out/restart.exr" >"$out/restart.log" 2>&1 &
run_pid=$!
for _ in $(seq 500); do grep -q "olad connected" "$out/restart.log" && break; sleep 0.01; done
kill $olad_pid; wait $olad_pid 2>/dev/null
for _ in $(seq 300); do grep -q "olad went away" "$out/restart.log" && break; sleep 0.01; done
grep -q "olad went away" "$out/restart.log" || fail "the run did not notice olad leaving"
start_olad
watch 1
wait $run_pid || fail "restart: exit $?"
run_pid=
[ "$(grep -c "olad connected" "$out/restart.log")" = 2 ] || fail "not connected again once"
[ "$(grep -c "olad went away" "$out/restart.log")" = 1 ] || fail "olad's leaving said more than once"
for _ in $(seq 100); do [ "$(channels 1-3)" = "244,102,5" ] && break; sleep 0.02; done
[ "$(channels 1-3)" = "244,102,5" ] || fail "after olad's restart the crystal shows $(channels 1-3)"
echo "restart: $(grep -c 'vitrine: lights' "$out/restart.log") lines said; lit again after olad came back"

# A flood on the input universe, from the moment the run has registered for it (a busy olad serves a
# new client late): the paced run of 120 frames (2 s) still takes about 2 s.
start=$(date +%s.%N)
"$vitrine" --headless --scene kifs --size 64x36 --frames 120 --validate --lights "$out/patch.json" \
  --map 'dmx.2.7=kifs.fold:0.9:1.2' --out "$out/flood.exr" >"$out/flood_run.log" 2>&1 &
run_pid=$!
for _ in $(seq 500); do grep -q "olad connected" "$out/flood_run.log" && break; sleep 0.01; done
"$probe" "$port" flood 2 3 >"$out/flood.txt" 2>"$out/flood.log" &
flood_pid=$!
wait $run_pid || fail "flood: exit $?"
end=$(date +%s.%N)
wait $flood_pid
frames_in=$(sed -nE 's/.* ([0-9]+) in.*/\1/p' "$out/flood_run.log" | tail -n 1)
python3 -c "import sys; s = $end - $start; print(f'flood: {int(open(\"$out/flood.txt\").read())} frames sent by the flooder, {$frames_in} taken by the run, 120 frames in {s:.2f} s'); sys.exit(s > 6)" ||
  fail "the flood slowed the run"
[ "${frames_in:-0}" -gt 100 ] || fail "the flood did not reach the run"

# The gallery: the lights follow its frames (the guarded frame read back at 64x36, never waited for),
# and L blacks them out and back.
. "$(dirname "$0")/virtual_display.sh"
start_display 320x180
trap 'kill $olad_pid $watch_pid $run_pid $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
DISPLAY=$display XDG_CONFIG_HOME=$out/gallery "$vitrine" --scene bloom --size 320x180 --validate --set tier=low \
  --lights "$out/patch.json" >"$out/gallery.log" 2>&1 &
app=$!
watch 1
wait_for_showing "$out/gallery.log"
lit() { for _ in $(seq 300); do [ "$(channels "$1")" = "$2" ] && return 0; sleep 0.05; done; return 1; }
lit 1-3 219,227,237 || fail "the gallery's crystal fixture shows $(channels 1-3)"
strip=$(channels 11-34)
[ "$(tr -d ',0' <<<"$strip")" != "" ] || fail "the gallery's wall strip is dark: the readback gave nothing"
python3 "$(dirname "$0")/xtest.py" "$display" focus:160,90 key:l || fail "xtest"
lit 1-34 "$(printf '0%.0s,' $(seq 33))0" || fail "blackout left $(channels 1-34)"
python3 "$(dirname "$0")/xtest.py" "$display" key:l || fail "xtest"
lit 1-3 219,227,237 || fail "after the blackout the crystal shows $(channels 1-3)"
kill -TERM $app
wait $app || fail "the gallery: exit $?"
app=
grep -q "validation messages" "$out/gallery.log" && fail "validation messages"
echo "gallery: the crystal and the wall strip ($strip) lit, blacked out and back; $(sed -n 's/^vitrine: lights: [0-9]* fixtures/&/p' "$out/gallery.log" | tail -n 1)"

# No olad at all: one line, the run goes on and ends normally, its lights counted as not sent.
nobody=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
printf '{"olad": %s, "fixtures": [{"type": "rgb", "universe": 1, "address": 1, "signal": "regions"}]}' "$nobody" >"$out/absent.json"
"$vitrine" --headless --scene kifs --size 64x36 --frames 200 --validate --lights "$out/absent.json" --out "$out/absent.exr" \
  >"$out/absent.log" 2>&1 || fail "without olad: exit $?"
[ "$(grep -c 'vitrine: lights' "$out/absent.log")" = 1 ] || fail "without olad, not one line: $(grep 'lights' "$out/absent.log")"
grep -q "not connected; 0 frames sent.*were not sent" "$out/absent.log" || fail "without olad: $(tail -n 3 "$out/absent.log")"
echo "no olad: $(grep 'vitrine: lights' "$out/absent.log") (a 200-frame run, 3.3 s)"

# Hostile patches: refused at start, naming the file and line.
refuse() {  # refuse NAME TEXT REGEX
  printf '%s' "$2" >"$out/$1.json"
  err=$("$vitrine" --headless --scene kifs --size 64x36 --lights "$out/$1.json" --out "$out/x.exr" 2>&1 >/dev/null) &&
    fail "$1 accepted"
  grep -Eq "$3" <<<"$err" || fail "$1: $err"
  echo "$1: $err"
}
refuse broken $'{"fixtures": [\n  {"type": "rgb",\n' "$out/broken.json:3: not JSON"
refuse overlap $'{"fixtures": [\n{"type": "rgb", "universe": 1, "address": 1, "signal": "regions"},\n{"type": "dimmer", "universe": 1, "address": 3, "signal": "regions"}]}' \
  "overlap.json:3: fixture 2 \(channels 3..3 of universe 1\) overlaps fixture 1 \(channels 1..3, line 2\)"
refuse range $'{"fixtures": [\n{"type": "rgbw", "universe": 1, "address": 510, "signal": "regions"}]}' "range.json:2: .*past 512"
refuse type $'{"fixtures": [\n{"type": "moving-head", "universe": 1, "address": 1, "signal": "regions"}]}' "type.json:2: unknown fixture type"
refuse huge $'{"fixtures": [\n{"type": "pixels", "count": 1000000000, "universe": 1, "address": 1, "signal": "regions"}]}' \
  "huge.json:2: a strip's pixel count 1000000000 is outside 1..170"
echo "lights: all checks passed"
