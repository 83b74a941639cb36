#!/usr/bin/env bash
# link_menu.sh VITRINE OUTDIR: Ableton Link's controls in the gallery menu's rig section, clicked on a
# virtual display: "play" starts the session's transport, a tempo typed into the BPM field is led to the
# session, and the Link box leaves the session and joins it again; each is said on the console. Run in a
# network namespace of its own where one can be made, so no other Link session on the machine joins.
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
if [ -z "${LINK_MENU_INNER:-}" ] && unshare -n true 2>/dev/null; then
  exec env LINK_MENU_INNER=1 unshare -n bash -c 'ip link set lo up && exec "$0" "$@"' "$0" "$@"
fi
rm -rf "$out"; mkdir -p "$out"
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 960x540
DISPLAY=$display XDG_CONFIG_HOME=$out/config XDG_DATA_HOME=$out/data "$vitrine" --scene calibrate --size 960x540 \
  --validate --link --link-tempo 128 >"$log" 2>&1 &
app=$!
wait_for_showing "$log"
x() { python3 "$here/xtest.py" "$display" "$@" || fail "xtest $*"; }
# The rig section is open by default, its first row Link's: the box, the BPM field, play/stop.
x move:600,500 sleep:0.5 click:284,365
wait_for_line "$log" "link: the transport plays" "play did not start the transport"
x move:150,365 sleep:1 ctrlclick:150,365 sleep:2 key:9 key:6 sleep:2 key:Return
wait_for_line "$log" "link: tempo 96.00 BPM" "the typed tempo did not reach the session"
x move:31,365 sleep:1 click:31,365
wait_for_line "$log" "link: off: own clock" "the Link box did not leave the session"
x sleep:1 click:31,365
wait_for_line "$log" "link: joining the session again" "the Link box did not join again"
kill -TERM $app; wait $app; code=$?; app=
[ "$code" = 0 ] || fail "exit $code"
grep -q "validation messages" "$log" && fail "validation messages"
grep "link:" "$log"
echo "link menu ok"
