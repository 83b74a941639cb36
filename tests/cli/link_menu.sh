#!/usr/bin/env bash
# link_menu.sh VITRINE OUTDIR: Ableton Link's controls in the gallery menu's rig section, clicked on a
# virtual display: "play" starts the session's transport, a tempo typed into the BPM field is led to the
# session, and the Link box leaves the session and joins it again; each is said on the console. The
# gallery runs in a network namespace of its own where one can be made, so no other Link session on the
# machine joins; the display stays in the machine's (it reaches the gallery through its socket file).
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out"
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 960x540
ns=()
if unshare -n true 2>/dev/null; then
  ns=(unshare -n bash -c 'ip link set lo up && exec "$0" "$@"')
else
  echo "network namespaces are not permitted here: the gallery joins the machine's Link sessions"
fi
DISPLAY=$display XDG_CONFIG_HOME=$out/config XDG_DATA_HOME=$out/data "${ns[@]}" "$vitrine" --scene calibrate \
  --size 960x540 --validate --link --link-tempo 128 >"$log" 2>&1 &
app=$!
wait_for_showing "$log"
x() { python3 "$here/xtest.py" "$display" "$@" || fail "xtest $*"; }
# act PATTERN WHAT XTEST-ACTIONS...: does the actions until a console line matches PATTERN, three tries
# of 5 s each (a click can land in the frame that first draws the row, on a loaded machine).
act() {
  local pattern=$1 what=$2; shift 2
  for _ in 1 2 3; do
    x "$@"
    for _ in $(seq 50); do grep -q "$pattern" "$log" && return 0; sleep 0.1; done
  done
  fail "$what"
}
# The rig section is open by default, under the closed sections (the fps line, six scenes, five headers);
# its first row is Link's: the box, the BPM field, play/stop.
act "link: the transport plays" "play did not start the transport" move:284,392 sleep:0.5 click:284,392
act "link: tempo 96.00 BPM" "the typed tempo did not reach the session" \
  move:150,392 sleep:1 ctrlclick:150,392 sleep:2 key:9 key:6 sleep:2 key:Return
act "link: off: own clock" "the Link box did not leave the session" move:31,392 sleep:1 click:31,392
act "link: joining the session again" "the Link box did not join again" move:31,392 sleep:1 click:31,392
kill -TERM $app; wait $app; code=$?; app=
[ "$code" = 0 ] || fail "exit $code"
grep -q "validation messages" "$log" && fail "validation messages"
grep "link:" "$log"
echo "link menu ok"
