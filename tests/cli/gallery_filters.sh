#!/usr/bin/env bash
# gallery_filters.sh VITRINE ISF_DIR OUTDIR: the gallery on a virtual X display (xvfb-run) starts a scene
# with the filter chain and the transition its settings file keeps, with the validation layer on; a
# saved filter whose file is gone is said on the console, the scene runs, and the file still keeps it.
set -u
vitrine=$1; isf=$2; out=$3
rm -rf "$out"; mkdir -p "$out/config/vitrine"
settings=$out/config/vitrine/settings.json
log=$out/gallery.log
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }
cat >"$settings" <<JSON
{"version": 1,
 "filters": {"calibrate": [{"file": "$isf/filter_invert.fs", "values": {"amount": "0.5"}}, {"file": "$out/gone.fs"}]},
 "transition": {"file": "$isf/transition_mix.fs", "values": {"dip": "0.3"}}}
JSON
XDG_CONFIG_HOME=$out/config timeout 60 xvfb-run -a -s "-screen 0 320x180x24" bash -c '
    "$0" --scene calibrate --size 320x180 --validate >"$1" 2>&1 &
    pid=$!
    for _ in $(seq 300); do grep -q "showing calibrate" "$1" && break; sleep 0.1; done
    sleep 1; kill -TERM $pid; wait $pid' "$vitrine" "$log" >"$log.xvfb" 2>&1
code=$?
grep -q "showing calibrate" "$log" || fail "the gallery showed nothing"
grep -q "filters of calibrate: .*gone.fs" "$log" || fail "the missing filter was not said"
grep -q "validation messages" "$log" && fail "validation messages"
[ "$code" = 0 ] || fail "exit $code after SIGTERM (0 expected)"
grep -q "filter_invert.fs" "$settings" || fail "the chain was not kept: $(cat "$settings")"
grep -q "gone.fs" "$settings" || fail "the filter that did not load was dropped from the file: $(cat "$settings")"
grep -q '"dip": "0.3"' "$settings" || fail "the transition's values were not kept: $(cat "$settings")"
echo "gallery filters ok"
