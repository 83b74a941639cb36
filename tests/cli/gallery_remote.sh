#!/usr/bin/env bash
# gallery_remote.sh VITRINE OUTDIR: the gallery on a virtual display driven by an OSC client.
# - With --remote-saves a value the client set is in the settings file however the gallery ends, with no
#   scene switch before: Esc (a key sent through XTEST) and SIGTERM (a service manager) alike, and in a
#   kiosk playing a playlist too. Without --remote-saves it is not kept.
# - The freeze guard judges a value sent for a hidden scene by that scene's own frame time: noodles.grid
#   sent while kifs shows is refused when noodles opens with about the seconds a frame that the same value
#   sent while noodles shows is refused with (judged by the time of the scene showing, the first is off by
#   the two scenes' ratio: kifs at the low tier draws about 6 times faster than noodles on lavapipe).
set -u
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out"
log=
fail() { echo "FAIL: $*"; [ -n "$log" ] && cat "$log"; exit 1; }

. "$here/virtual_display.sh"
app=
trap 'kill $app $xvfb 2>/dev/null; wait 2>/dev/null' EXIT
start_display 320x180

# start NAME [FLAGS...]: a gallery on kifs with remote control, its settings under $out/NAME; sets $port.
start() {
  local name=$1; shift
  log=$out/$name.log
  DISPLAY=$display XDG_CONFIG_HOME=$out/$name "$vitrine" --scene kifs --size 320x180 --validate --set kifs.tier=low \
    --remote --remote-bind 127.0.0.1:0 "$@" >"$log" 2>&1 &
  app=$!
  wait_for_showing "$log"
  port=$(sed -nE 's/.*remote control on 127\.0\.0\.1:([0-9]+).*/\1/p' "$log" | head -n1)
  [ -n "$port" ] || fail "no remote port in the log"
}
# osc ADDRESS [s TEXT | i NUMBER]: one datagram to the gallery.
osc() {
  python3 - "$port" "$@" <<'PY' || fail "OSC send"
import socket, struct, sys
def pad(b): return b + b"\0" * (4 - len(b) % 4)
port, address, args = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
tags, body = ",", b""
for kind, value in zip(args[::2], args[1::2]):
    tags += kind
    body += struct.pack(">i", int(value)) if kind == "i" else pad(value.encode())
socket.socket(socket.AF_INET, socket.SOCK_DGRAM).sendto(pad(address.encode()) + pad(tags.encode()) + body, ("127.0.0.1", port))
PY
}
# stop esc|term: ends the gallery; it must exit 0 without validation messages.
stop() {
  if [ "$1" = esc ]; then python3 "$here/xtest.py" "$display" key:Escape || fail "xtest"; else kill -TERM $app; fi
  for _ in $(seq 100); do kill -0 $app 2>/dev/null || break; sleep 0.1; done
  wait $app || fail "exit $?"
  grep -q "validation messages" "$log" && fail "validation messages"
}
step_of() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["scenes"]["kifs"].get("step", "none"))' "$1" 2>/dev/null || echo "no file"; }

printf 'kifs 60\nnoodles 60\n' >"$out/playlist.txt"
for run in esc:--remote-saves term:--remote-saves "playlist:--remote-saves --kiosk --playlist $out/playlist.txt" unsaved:; do
  name=${run%%:*}; flag=${run#*:}
  start "$name" $flag
  osc /vitrine/kifs/step i 4
  sleep 1.5
  stop "$([ "$name" = esc ] && echo esc || echo term)"
  step=$(step_of "$out/$name/vitrine/settings.json")
  if [ -n "$flag" ]; then [ "$step" = 4 ] || fail "$name lost the OSC value: step $step"
  else [ "$step" != 4 ] || fail "without --remote-saves the OSC value was kept"; fi
done

# noodles at 8x8x8 strands, then a client asks for 64x64x32: first while kifs shows, then while noodles does.
start hidden --set noodles.grid=8
osc /vitrine/noodles/grid s 64x64x32
sleep 0.5
osc /vitrine/scene s noodles
wait_for_line "$log" "remote value for noodles.grid refused" "the value sent while noodles was hidden was not refused"
osc /vitrine/noodles/grid s 64x64x32
wait_for_line "$log" "^vitrine: remote osc [^ ]* refused: This change" "the value sent while noodles showed was not refused"
stop term
hidden=$(sed -nE 's/.*remote value for noodles.grid refused: .*about ([0-9.]+) s a frame.*/\1/p' "$log" | head -n1)
showing=$(sed -nE 's/^vitrine: remote osc [^ ]+ refused: This change .*about ([0-9.]+) s a frame.*/\1/p' "$log" | head -n1)
echo "noodles.grid=64x64x32 judged at $hidden s a frame while hidden, $showing s while showing"
awk -v h="$hidden" -v s="$showing" 'BEGIN { exit !(h > 0 && s > 0 && h * 3 > s && s * 3 > h) }' ||
  fail "judged at $hidden s a frame while hidden, $showing s while showing"
echo "gallery remote ok"
