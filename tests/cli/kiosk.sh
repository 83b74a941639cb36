#!/usr/bin/env bash
# kiosk.sh VITRINE OUTDIR: the gallery in kiosk mode on a virtual X display (xvfb-run). A scene that
# cannot start is skipped, the scenes cycle with cross-fades, an injected lost device after a few
# seconds ends that gallery with a log line and a fresh one starts on the next scene; SIGTERM (what a
# service manager sends) then stops it cleanly, with exit 0 and no validation messages. Its own saved
# state never stops it: a settings file holding a number out of range (1e400, which once ended every
# start with "unexpected error") is moved aside; and the kiosk's cycle does not become the scene the
# gallery starts with next time.
set -u
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out/config/vitrine"
settings=$out/config/vitrine/settings.json
echo '{"version": 1, "scene": "noodles", "window": {"zoom": 1e400}}' >"$settings"
log=$out/kiosk.log
# The kiosk until the lost device has restarted it and the cycle has passed the failing scene (the last
# of the events below, ~6 s), two seconds more for a cross-fade into the scene after it, then SIGTERM as
# a service manager sends it; the exit status is vitrine's. (A fixed 30 s once spent 40 CPU seconds
# rendering what this test does not look at.)
XDG_CONFIG_HOME=$out/config VITRINE_INJECT=scene-start:glass,device-lost:40 \
  timeout 80 xvfb-run -a -s "-screen 0 320x180x24" bash -c '
    "$0" --kiosk --dwell 1 --scene kifs --size 320x180 --validate --set noodles.grid=4x4x4 --set neon.chains=256 \
      >"$1" 2>&1 &
    pid=$!
    for _ in $(seq 600); do grep -q "kiosk: skipping glass" "$1" && break; sleep 0.1; done
    sleep 2; kill -TERM $pid; wait $pid' "$vitrine" "$log.run" >"$log" 2>&1
code=$?
cat "$log.run" >>"$log"
cat "$log"
fail() { echo "FAIL: $*"; exit 1; }
grep -q "kiosk: skipping glass: scene glass failed to start (injected" "$log" || fail "the failing scene was not skipped"
grep -q "The GPU stopped responding" "$log" || fail "the injected lost device was not reported"
grep -q "kiosk: restarting in 1 s" "$log" || fail "the kiosk did not restart"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code after SIGTERM (0 expected)"
ls "$out/config/vitrine" | grep -q '^settings.json.bad-' || fail "the unreadable settings file was not moved aside"
grep -q "is not a settings file (a number out of range)" "$log" || fail "no warning about the settings file"
# The --set values are remembered, as in the gallery; the scene to start with is not the kiosk's to write.
[ -f "$settings" ] || fail "the kiosk's --set values were not saved"
grep -q '"scene":' "$settings" && fail "the kiosk wrote the gallery's last scene: $(cat "$settings")"
echo "kiosk ok"
