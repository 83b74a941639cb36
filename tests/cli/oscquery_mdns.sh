#!/usr/bin/env bash
# oscquery_mdns.sh VITRINE OUTDIR: a headless --remote run bound beyond loopback is found over mDNS.
# The test starts its own system bus (a private dbus-daemon) and avahi-daemon (a private configuration,
# as root without dropping it), points the run and avahi-browse at that bus, and finds _oscjson._tcp and
# _osc._udp on the run's port; then it restarts the daemon and the run announces itself again. Where the
# daemon cannot run here, it says why and exits 77 (skipped); cli.oscquery checks the "no daemon" line.
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }
for tool in dbus-daemon avahi-daemon avahi-browse; do
  command -v $tool >/dev/null || skip "$tool is not installed (scripts/setup --test installs it)"
done
[ "$(id -u)" = 0 ] || skip "avahi-daemon writes its pid file in /run/avahi-daemon, which needs root"
avahi-daemon --check 2>/dev/null && skip "an avahi-daemon already runs here; this test starts its own"

pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done' EXIT
cat >"$out/bus.conf" <<CONF
<!DOCTYPE busconfig PUBLIC "-//freedesktop//DTD D-Bus Bus Configuration 1.0//EN"
 "http://www.freedesktop.org/standards/dbus/1.0/busconfig.dtd">
<busconfig>
  <type>system</type>
  <listen>unix:path=$out/bus</listen>
  <auth>EXTERNAL</auth>
  <policy context="default">
    <allow user="*"/> <allow own="*"/>
    <allow send_type="method_call"/> <allow send_type="signal"/>
    <allow send_type="method_return"/> <allow send_type="error"/>
    <allow receive_type="method_call"/> <allow receive_type="signal"/>
    <allow receive_type="method_return"/> <allow receive_type="error"/>
  </policy>
</busconfig>
CONF
cat >"$out/avahi.conf" <<CONF
[server]
use-ipv4=yes
use-ipv6=no
enable-dbus=yes
[publish]
publish-hinfo=no
publish-workstation=no
CONF
dbus-daemon --config-file="$out/bus.conf" --fork --print-pid >"$out/dbus.pid" || skip "dbus-daemon would not start"
pids+=("$(cat "$out/dbus.pid")")
export DBUS_SYSTEM_BUS_ADDRESS=unix:path=$out/bus

wait_for() {  # wait_for FILE PATTERN [COUNT]: until FILE holds PATTERN COUNT times (5 s)
  for _ in $(seq 250); do [ "$(grep -c "$2" "$1" 2>/dev/null || true)" -ge "${3:-1}" ] && return 0; sleep 0.02; done
  return 1
}
start_avahi() {
  avahi-daemon -f "$out/avahi.conf" --no-drop-root --no-chroot >>"$out/avahi.log" 2>&1 &
  avahi=$!; pids+=("$avahi")
  wait_for "$out/avahi.log" "Server startup complete" "$1" || skip "avahi-daemon did not start: $(tail -3 "$out/avahi.log")"
}
start_avahi 1

"$vitrine" --headless --scene kifs --size 32x18 --frames 100000000 --remote --remote-bind 0.0.0.0:0 \
  --out "$out/x.exr" >"$out/vitrine.log" 2>&1 &
pids+=("$!")
wait_for "$out/vitrine.log" "mDNS: announced" || fail "not announced: $(cat "$out/vitrine.log")"
port=$(sed -nE 's/.*remote control on 0\.0\.0\.0:([0-9]+).*/\1/p' "$out/vitrine.log")
grep "mDNS:" "$out/vitrine.log"

browse() {  # browse TYPE: the resolved services' lines ("=;iface;proto;name;type;domain;host;address;port;txt")
  avahi-browse --resolve --terminate --parsable --no-db-lookup "$1" 2>/dev/null | grep '^=' || true
}
for type in _oscjson._tcp _osc._udp; do
  found=$(browse $type | grep -F ';Vitrine\032on\032' | grep ";$port;" || true)  # --parsable escapes spaces
  [ -n "$found" ] || fail "avahi-browse finds no $type on port $port: $(browse $type)"
  echo "avahi-browse $type: $(echo "$found" | head -1 | cut -d';' -f4,7-9)"
done

# The daemon restarts: the run waits for it and announces itself again.
kill "$avahi"; wait "$avahi" 2>/dev/null || true
start_avahi 2
wait_for "$out/vitrine.log" "mDNS: announced" 2 || fail "not announced again after avahi-daemon restarted: $(cat "$out/vitrine.log")"
[ -n "$(browse _oscjson._tcp | grep ";$port;")" ] || fail "not found after the restart"
echo "announced again after avahi-daemon restarted"
echo PASS
