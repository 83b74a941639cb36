#!/usr/bin/env bash
# kiosk.sh VITRINE OUTDIR: the gallery in kiosk mode on a virtual X display (xvfb-run). A scene that
# cannot start is skipped, the scenes cycle with cross-fades, an injected lost device after a few
# seconds ends that gallery with a log line and a fresh one starts on the next scene; SIGTERM (what a
# service manager sends) then stops it cleanly, with exit 0 and no validation messages.
set -u
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out/config"
log=$out/kiosk.log
# Thirty seconds of kiosk, then SIGTERM as a service manager sends it; the exit status is vitrine's.
XDG_CONFIG_HOME=$out/config VITRINE_INJECT=scene-start:glass,device-lost:40 \
  timeout 80 xvfb-run -a -s "-screen 0 320x180x24" bash -c '
    "$0" --kiosk --dwell 1 --scene kifs --size 320x180 --validate --set noodles.grid=4x4x4 --set neon.chains=256 &
    pid=$!; sleep 30; kill -TERM $pid; wait $pid' "$vitrine" >"$log" 2>&1
code=$?
cat "$log"
fail() { echo "FAIL: $*"; exit 1; }
grep -q "kiosk: skipping glass: scene glass failed to start (injected" "$log" || fail "the failing scene was not skipped"
grep -q "The GPU stopped responding" "$log" || fail "the injected lost device was not reported"
grep -q "kiosk: restarting in 1 s" "$log" || fail "the kiosk did not restart"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code after SIGTERM (0 expected)"
echo "kiosk ok"
