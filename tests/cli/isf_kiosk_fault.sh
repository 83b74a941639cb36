#!/usr/bin/env bash
# isf_kiosk_fault.sh VITRINE OUTDIR: a lost device while the kiosk shows an ISF piece (injected: what a
# runaway shader the loop guard did not bound, or a driver fault, looks like to the host). That gallery
# ends with the host's sentence, a fresh one starts, and the piece is not started again while its file
# is unchanged: the playlist's next turn skips it, saying why. The piece's turn is long, so the loss
# (the 20th submission) falls within it however slow the machine.
set -u
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out/config" "$out/data"
log=$out/kiosk.log
printf '/*{ "ISFVSN": "2" }*/\nvoid main() { gl_FragColor = vec4(isf_FragNormCoord, 0.5, 1.0); }\n' >"$out/flat.fs"
printf 'flat 30\ncalibrate 1\n' >"$out/playlist.txt"
XDG_CONFIG_HOME=$out/config XDG_DATA_HOME=$out/data VITRINE_INJECT=device-lost:20 \
  timeout 80 xvfb-run -a -s "-screen 0 320x180x24" bash -c '
    "$0" --kiosk --isf "$2/flat.fs" --playlist "$2/playlist.txt" --size 320x180 --validate >"$1" 2>&1 &
    pid=$!
    for _ in $(seq 600); do grep -q "kiosk: skipping flat" "$1" && break; sleep 0.1; done
    kill -TERM $pid; wait $pid' "$vitrine" "$log.run" "$out" >"$log" 2>&1
code=$?
cat "$log.run" >>"$log"
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
grep -q "The GPU stopped responding" "$log" || fail "the injected lost device was not reported"
grep -q "kiosk: restarting in" "$log" || fail "the kiosk did not restart"
grep -q "kiosk: skipping flat: .*flat.fs: the GPU stopped responding while it ran" "$log" ||
  fail "the piece that was showing was started again"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code after SIGTERM (0 expected)"
echo "isf kiosk fault: reported, restarted, the piece held back"
