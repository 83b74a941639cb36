#!/usr/bin/env bash
# headless_remote_stop.sh VITRINE OUTDIR: a headless --remote run stopped by SIGTERM writes its last
# frame and reports the frames it rendered, not the number it was asked for.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
"$vitrine" --headless --scene kifs --size 32x18 --frames 100000 --remote --remote-bind 127.0.0.1:0 \
  --out "$out/stopped.exr" >"$out/log" 2>&1 &
pid=$!
for _ in $(seq 200); do grep -q "remote control on" "$out/log" && break; sleep 0.1; done
sleep 1  # some frames at 60 a second
kill -TERM $pid
wait $pid || { echo "FAIL: exit $?"; cat "$out/log"; exit 1; }
line=$(grep "^wrote .*stopped.exr" "$out/log") || { echo "FAIL: nothing written"; cat "$out/log"; exit 1; }
frames=$(sed -E 's/.*scene kifs, ([0-9]+) frames.*/\1/' <<<"$line")
[ "$frames" -ge 1 ] && [ "$frames" -lt 100000 ] || { echo "FAIL: reported $frames frames: $line"; exit 1; }
grep -q "stopped after $frames of the 100000 frames asked for" "$out/log" || { echo "FAIL: no stop line"; cat "$out/log"; exit 1; }
"$vitrine" compare "$out/stopped.exr" "$out/stopped.exr" >/dev/null
echo "ok: stopped after $frames frames"
