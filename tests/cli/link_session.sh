#!/usr/bin/env bash
# link_session.sh VITRINE LINK_PEER OUTDIR: two Ableton Link peers in a network namespace the test makes
# (only loopback, up): the kiosk joining with --link-tempo
# and --link-wait-bar on a virtual X display, and the test peer (tests/support/link_peer.cpp). The
# kiosk's lead tempo reaches the peer and the peer's tempo reaches the kiosk; the kiosk's beat at each
# bar-quantised switch agrees with the peer's at the same host time within 1 ms of phase, and the
# switch comes on the bar's first frame; the transport's start reaches it; a
# flood of tempo changes (1500 in 3 s) gets a line a second on the console and the kiosk goes on
# switching on bars; the peer gone, the kiosk keeps the session's time without a jump. SIGTERM then
# ends it with exit 0 and no validation messages. Where no namespace can be made, it says why and runs
# in the default one.
set -u
vitrine=$1; peer=$2; out=$3
rm -rf "$out"; mkdir -p "$out/config"
fail() { echo "FAIL: $*"; exit 1; }

if unshare -n true 2>/dev/null; then
  ns=(unshare -n)
elif unshare -rn true 2>/dev/null; then
  ns=(unshare -rn)
else
  ns=()
  echo "network namespaces are not permitted here ($(unshare -n true 2>&1 | head -1)): running in the default namespace"
fi
printf 'noodles 1\nneon 1\n' >"$out/playlist.txt"

# Inside the namespace: the peer reads commands from a fifo; the kiosk runs under xvfb-run.
inner='
  set -u
  vitrine=$1; peer=$2; out=$3; namespaced=$4
  if [ "$namespaced" = 1 ]; then
    # Loopback up is all Link needs (measured: down, the peers never meet; multicast flag and a route
    # for 224.0.0.0/4 on lo change nothing).
    ip link set lo up || { echo "cannot bring loopback up in the namespace"; exit 2; }
    echo "network namespace: $(ip -o link show lo | cut -c1-50)"
  fi
  mkfifo "$out/peer.cmd"
  "$peer" 120 <"$out/peer.cmd" >"$out/peer.log" 2>&1 &
  peerpid=$!
  exec 3>"$out/peer.cmd"
  XDG_CONFIG_HOME=$out/config "$vitrine" --kiosk --playlist "$out/playlist.txt" \
    --size 320x180 --validate --set noodles.grid=4x4x4 --set neon.chains=256 --link-tempo 133 --link-wait-bar \
    --remote --remote-bind 127.0.0.1:0 \
    >"$out/vitrine.log" 2>&1 &
  vpid=$!
  log=$out/vitrine.log
  waitfor() {  # waitfor FILE REGEX TENTHS; gives up at once when the kiosk has ended
    for _ in $(seq "$3"); do
      grep -qE "$2" "$1" && return 0
      kill -0 "$vpid" 2>/dev/null || { echo "vitrine ended while waiting for /$2/"; return 1; }
      sleep 0.1
    done
    echo "timed out waiting for /$2/ in $1"; return 1
  }
  switches() { grep -c "kiosk: .* comes in" "$log"; }
  waitswitch() {  # one more bar-quantised switch than now
    local n; n=$(switches); for _ in $(seq 200); do [ "$(switches)" -gt "$n" ] && return 0; sleep 0.1; done
    echo "no bar-quantised switch within 20 s"; return 1
  }
  ok=1
  waitfor "$log" "vitrine: showing" 600 || { kill "$peerpid"; exit 1; }
  waitfor "$out/peer.log" "^tempo-seen [0-9]+ 13(3\.0|2\.99)" 100 || ok=0    # the kiosk led: 133 BPM
  echo "tempo 96" >&3
  waitfor "$log" "link: tempo 96\.00 BPM" 100 || ok=0                 # the peer set 96 BPM
  echo "play 1" >&3
  waitfor "$log" "the transport plays" 100 || ok=0
  waitswitch && waitswitch || ok=0
  sleep 0.7  # past the frame that started the incoming scene (hundreds of ms on lavapipe)
  echo "tempo 110" >&3                                                # settled: the propagation time
  waitfor "$log" "link: tempo 110\.00 BPM" 100 || ok=0
  waitswitch || ok=0
  echo "flood 500 3" >&3
  waitfor "$out/peer.log" "^flood-end" 100 || ok=0
  waitswitch || ok=0
  kill "$peerpid"; wait "$peerpid" 2>/dev/null
  waitfor "$log" "every peer left" 100 || ok=0
  waitswitch || ok=0
  # A new peer at 120 BPM joins the kiosk, alone at 100: the kiosk leads again with 133.
  "$peer" 120 </dev/null >"$out/peer2.log" 2>&1 &
  peer2=$!
  waitfor "$out/peer2.log" "^tempo-seen [0-9]+ 13(3\.0|2\.99)" 100 || ok=0
  kill "$peer2"; wait "$peer2" 2>/dev/null
  # A phone applies a preset to the scene that has just faded in (2 s): it waits for the next bar (the
  # touch holds the kiosk on that scene, so the bar brings the preset, not a switch).
  waitswitch || ok=0
  sleep 2.2
  port=$(sed -nE "s/.*remote control on 127\.0\.0\.1:([0-9]+).*/\1/p" "$log" | head -n1)
  showing=$(grep -aoE "kiosk: \w+ comes in" "$log" | tail -n1 | cut -d" " -f2)
  preset=clean; [ "$showing" = noodles ] && preset=smooth
  python3 -c "
import socket, struct, sys
pad = lambda b: b + b\"\\0\" * (4 - len(b) % 4)
body = pad(b\"/vitrine/preset/apply\") + pad(b\",ss\") + pad(sys.argv[2].encode()) + pad(sys.argv[3].encode())
socket.socket(socket.AF_INET, socket.SOCK_DGRAM).sendto(body, (\"127.0.0.1\", int(sys.argv[1])))
" "$port" "$showing" "$preset" || ok=0
  echo "sent preset $preset for $showing at $(date +%s.%N)"
  waitfor "$log" "link: bar -?[0-9]+ .*: preset $preset" 100 || ok=0
  kill -TERM "$vpid"; wait "$vpid"; code=$?
  echo "vitrine exit $code"
  [ "$ok" = 1 ] && exit "$code"
  exit 1
'
namespaced=1; [ ${#ns[@]} = 0 ] && namespaced=0
timeout 110 "${ns[@]}" xvfb-run -a -s "-screen 0 320x180x24" bash -c "$inner" inner "$vitrine" "$peer" "$out" "$namespaced"
code=$?
echo "--- vitrine's console"; grep -v "^sample" "$out/vitrine.log"
echo "--- the peer's events"; grep -v "^sample" "$out/peer.log" | grep -v "^tempo-seen" | head -20
echo "(the peer saw $(grep -c '^tempo-seen' "$out/peer.log") tempo changes)"
grep -q "validation messages" "$out/vitrine.log" && fail "validation messages"
[ "$code" = 0 ] || fail "the run ended with $code (0 expected)"

# The numbers, from both logs on Link's host clock (CLOCK_MONOTONIC_RAW, the same for both processes).
python3 - "$out/vitrine.log" "$out/peer.log" "$out/peer2.log" <<'PY' || fail "see above"
import re, sys
vlog, plog = open(sys.argv[1]).read(), open(sys.argv[2]).read().splitlines()
samples = [tuple(map(float, l.split()[1:4])) for l in plog if l.startswith("sample ")]  # (us, beat, bpm)
def peer_beat(us):
    """The peer's beat at host time us, from its last sample before, the tempo unchanged up to the next."""
    for i in range(len(samples) - 1, -1, -1):
        t, beat, bpm = samples[i]
        if t <= us:
            if i + 1 < len(samples) and samples[i + 1][2] != bpm: return None
            return beat + (us - t) * 1e-6 * bpm / 60.0, bpm
    return None
problems = []
# Tempo propagation, both ways.
# The kiosk's lead reaching a peer that joined it alone at 100 BPM (the first peer's 133 may have come
# with the session it joined instead).
leads = re.findall(r"leading the session's tempo: 133\.00 BPM \(link clock ([\d.]+) s\)", vlog)
p2 = open(sys.argv[3]).read().splitlines()
seen = next((float(l.split()[1]) for l in p2 if re.match(r"tempo-seen \d+ 13(3\.0|2\.99)", l)), None)
if len(leads) == 2 and seen: print(f"kiosk -> peer: 133 BPM in {(seen - float(leads[1]) * 1e6) / 1e3:.1f} ms")
else: problems.append(f"{len(leads)} leads (2 expected) or the second peer never saw 133 BPM")
for bpm in (96, 110):
    set_at = next((float(l.split()[1]) for l in plog if l.startswith("tempo-set") and abs(float(l.split()[2]) - bpm) < 0.01), None)
    got = re.search(rf"link: tempo {bpm}\.00 BPM \(beat [\d.-]+, link clock ([\d.]+) s\)", vlog)
    if set_at and got: print(f"peer -> kiosk: {bpm} BPM in {(float(got.group(1)) * 1e6 - set_at) / 1e3:.1f} ms (read once a step)")
    else: problems.append(f"no time for {bpm} BPM on either side")
# Each bar-quantised switch: on the bar's first frame (the frame before was in the bar before), and in
# phase with the peer.
switches = [(int(b), float(beat), float(s), float(before)) for b, beat, s, before in
            re.findall(r"link: bar (-?\d+) \(beat ([\d.-]+), link clock ([\d.]+) s; the frame before at beat ([\d.-]+)\): "
                       r"kiosk: \w+ comes in", vlog)]
lost = re.search(r"every peer left: own clock from here at ([\d.]+) BPM \(beat ([\d.-]+), link clock ([\d.]+) s\)", vlog)
quantum = 4.0
phase_ms = []
for bar, beat, s, before in switches:
    line = bar * quantum
    p = peer_beat(s * 1e6) if not lost or s < float(lost.group(3)) else None  # the first peer's session only
    bpm = p[1] if p else float(lost.group(1)) if lost else 120.0
    if not before < line <= beat: problems.append(f"the switch on bar {bar} came at beat {beat}, the frame before at {before}")
    print(f"bar {bar}: switch {(beat - line) * 60000 / bpm:.1f} ms after the bar line, its frame {(beat - before) * 60000 / bpm:.1f} ms after the one before", end="")
    if p:
        diff = (beat - p[0] + quantum / 2) % quantum - quantum / 2  # phase within the bar: beats agree modulo it
        phase_ms.append(abs(diff) * 60000 / bpm)
        print(f"; phase against the peer {diff * 60000 / bpm:+.3f} ms")
    else:
        print(" (the peer gone)")
if len(switches) < 5: problems.append(f"{len(switches)} bar-quantised switches, 5 expected")
# A phone's preset, held for the bar: applied on the bar's first frame.
held = re.findall(r"link: bar (-?\d+) \(beat ([\d.-]+), link clock [\d.]+ s; the frame before at beat ([\d.-]+)\): preset (\w+)", vlog)
for bar, beat, before, name in held:
    line = int(bar) * quantum
    print(f"preset {name} held for bar {bar}: applied at beat {float(beat):.4f}, the frame before at {float(before):.4f}")
    if not float(before) < line <= float(beat): problems.append(f"the preset came at beat {beat}, not on bar {bar}'s first frame")
if len(held) != 1: problems.append(f"{len(held)} presets applied on a bar, 1 expected")
if not phase_ms: problems.append("no switch to compare with the peer's phase")
elif max(phase_ms) > 1.0: problems.append(f"phase differs by {max(phase_ms):.3f} ms (1 ms at most)")
else: print(f"phase agreement: {max(phase_ms):.3f} ms at worst over {len(phase_ms)} switches")
# The flood: a line a second at most, however many changes.
flood = [float(l.split()[1]) for l in plog if l.startswith("flood")]
told = [float(t) for t in re.findall(r"link: tempo [\d.]+ BPM \(beat [\d.-]+, link clock ([\d.]+) s\)", vlog)]
during = [t for t in told if flood and flood[0] <= t * 1e6 <= flood[-1] + 1.5e6]
print(f"a flood of 500 tempo changes a second for 3 s: {len(during)} tempo lines from the kiosk")
if len(during) > 5: problems.append(f"{len(during)} tempo lines during a 3 s flood (a line a second at most)")
# Alone: the beat runs on from where it was, at the session's last tempo (no jump).
after = [sw for sw in switches if lost and sw[2] > float(lost.group(3))]
if lost and after:
    bpm, b0, s0 = map(float, lost.groups())
    _, b1, s1, _ = after[0]
    jump = b1 - (b0 + (s1 - s0) * bpm / 60.0)
    print(f"alone: beat {b1:.4f} where the session's timeline puts {b1 - jump:.4f} (off by {jump * 60000 / bpm:.3f} ms)")
    if abs(jump * 60000 / bpm) > 1.0: problems.append("the beat jumped when the peer left")
else: problems.append("no switch after the peer left")
for p in problems: print("FAIL:", p)
sys.exit(1 if problems else 0)
PY
echo "link session ok"
