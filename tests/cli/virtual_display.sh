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
# wait_for_showing LOG: waits (up to a minute) until the gallery writing LOG says it shows its first
# frame ("vitrine: showing SCENE on DEVICE"), instead of sleeping for a start's worst case.
wait_for_showing() {
  for _ in $(seq 600); do grep -q "^vitrine: showing " "$1" 2>/dev/null && return 0; sleep 0.1; done
  fail "the gallery showed no frame within a minute"
}
# wait_for_setup LOG OUTPUT: waits (up to a minute) until projector setup shows for OUTPUT ("vitrine:
# projector setup of OUTPUT"), its calibration card built, before a check drags a corner.
wait_for_setup() {
  for _ in $(seq 600); do grep -q "^vitrine: projector setup of $2\$" "$1" 2>/dev/null && return 0; sleep 0.1; done
  fail "projector setup of $2 did not show within a minute"
}
