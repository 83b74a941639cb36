#!/usr/bin/env bash
# kiosk_transition.sh VITRINE ISF_DIR OUTDIR: the kiosk on a virtual X display (xvfb-run) changes scenes
# through an ISF transition (--transition, one of its inputs set by --set transition.KEY): two changes
# are drawn through it with the validation layer on, and SIGTERM then stops the kiosk with exit 0.
set -u
vitrine=$1; isf=$2; out=$3
rm -rf "$out"; mkdir -p "$out/config"
log=$out/kiosk.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
XDG_CONFIG_HOME=$out/config timeout 80 xvfb-run -a -s "-screen 0 320x180x24" bash -c '
    "$0" --kiosk --dwell 0.5 --scene calibrate --size 320x180 --validate --transition "$2" --set transition.dip=0.5 \
      --set noodles.grid=4x4x4 --set neon.chains=256 >"$1" 2>&1 &
    pid=$!
    for _ in $(seq 700); do [ "$(grep -c "comes in through transition_mix.fs" "$1")" -ge 2 ] && break; sleep 0.1; done
    sleep 0.5; kill -TERM $pid; wait $pid' "$vitrine" "$log" "$isf/transition_mix.fs" >"$log.xvfb" 2>&1
code=$?
[ "$(grep -c "comes in through transition_mix.fs" "$log")" -ge 2 ] || fail "fewer than two changes through the transition"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code after SIGTERM (0 expected)"
echo "kiosk transition ok"
