#!/usr/bin/env bash
# remote_floods.sh VITRINE OUTDIR: a bounded flood from loopback at a headless --remote run: 3,000
# /vitrine/preset/save from 3,000 loopback addresses (each under its own message budget) write at most
# the preset-write budget's files (a burst of 10, then 2 a second). Sends only to 127.0.0.1, for at
# most ~6 s. (The cap on OSC source names is tested on live::SourceBank, in live_sources_test.)
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out/config"
fail() { echo "FAIL: $*"; exit 1; }
XDG_CONFIG_HOME=$out/config "$vitrine" --headless --scene kifs --size 32x18 --frames 100000000 --remote \
  --remote-bind 127.0.0.1:0 --out "$out/remote.exr" >"$out/remote.log" 2>&1 &
pid=$!
trap 'kill -TERM $pid 2>/dev/null || true' EXIT
for _ in $(seq 200); do grep -q "remote control on" "$out/remote.log" && break; sleep 0.1; done
port=$(sed -nE 's/.*remote control on 127\.0\.0\.1:([0-9]+).*/\1/p' "$out/remote.log")
[ -n "$port" ] || fail "no remote control: $(cat "$out/remote.log")"
python3 - "$port" <<'PY'
import socket, struct, sys, time
port = int(sys.argv[1])
def pad(b): return b + b"\0" * (4 - len(b) % 4)
def osc(address, tags, *args):
    body = b"".join(struct.pack(">f", a) if t == "f" else pad(a.encode()) for t, a in zip(tags, args))
    return pad(address.encode()) + pad(("," + tags).encode()) + body
def flood(messages, seconds):
    start = time.monotonic()
    for i, message in enumerate(messages):
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        sock.bind((f"127.{1 + i // 65025 % 250}.{i // 255 % 255}.{1 + i % 255}", 0))  # a new sender each time
        sock.sendto(message, ("127.0.0.1", port))
        sock.close()
        if i % 500 == 499: time.sleep(0.05)  # within the socket's buffer
        if time.monotonic() - start > seconds: break
    time.sleep(1.0)
    return time.monotonic() - start
took = flood([osc("/vitrine/preset/save", "ss", "kifs", f"p{i}") for i in range(3000)], 5)
print(f"3,000 preset saves sent in {took:.1f} s")
PY
sleep 0.5
saved=$(ls "$out/config/vitrine/presets" 2>/dev/null | wc -l)
echo "$saved preset files written"
[ "$saved" -le 40 ] || fail "$saved preset files written by a flood of saves"
[ "$saved" -ge 1 ] || fail "no preset saved at all: $(tail -5 "$out/remote.log")"
