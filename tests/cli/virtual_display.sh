# Sourced by the gallery's checks: start_display WxH starts an Xvfb of that size on a free display
# (no access control, so xtest.py can connect) and sets $display and $xvfb; $out and fail() come from
# the caller. The caller's EXIT trap kills $xvfb.
start_display() {
  exec 3>"$out/display"
  Xvfb -displayfd 3 -screen 0 "$1x24" -nolisten tcp >"$out/xvfb.log" 2>&1 &
  xvfb=$!
  for _ in $(seq 50); do [ -s "$out/display" ] && break; sleep 0.1; done
  display=:$(head -n1 "$out/display")
  [ "$display" != ":" ] || fail "Xvfb did not start"
}
# grab_changes A.ppm B.ppm: how many of two screen grabs' values (xtest.py's shots) differ by more than a
# quarter of the range; a menu lets the scene through a little, so smaller differences are not changes.
grab_changes() {
  python3 - "$1" "$2" <<'EOF'
import sys
a, b = (open(p, "rb").read() for p in sys.argv[1:])
a, b = a[a.index(b"255\n") + 4:], b[b.index(b"255\n") + 4:]
print(sum(abs(x - y) > 64 for x, y in zip(a, b)))
EOF
}
# wait_for_line LOG PATTERN WHAT: waits (up to a minute) until a line of LOG matches PATTERN (grep), instead
# of sleeping for a busy machine's worst case; fails saying WHAT did not happen.
wait_for_line() {
  for _ in $(seq 600); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done
  fail "$3 within a minute"
}
# wait_for_showing LOG: until the gallery writing LOG shows its first frame ("vitrine: showing SCENE on
# DEVICE").
wait_for_showing() { wait_for_line "$1" "^vitrine: showing " "the gallery showed no frame"; }
# wait_for_setup LOG OUTPUT: until projector setup shows for OUTPUT ("vitrine: projector setup of
# OUTPUT"), its calibration card built, before a check drags a corner.
wait_for_setup() { wait_for_line "$1" "^vitrine: projector setup of $2\$" "projector setup of $2 did not show"; }
