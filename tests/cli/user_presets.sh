#!/usr/bin/env bash
# user_presets.sh VITRINE OUTDIR: a preset people make, end to end. A headless run saves its values as
# a preset of the user's (--save-preset, into the presets folder beside the settings file), and so
# does an OSC client of a headless --remote run (/vitrine/preset/save); --preset
# finds it by name; --export-preset writes it as a file, which --preset-file applies in a run with no
# settings folder at all; every one of those frames equals a run with the same --set values (compare,
# max difference 0). A built-in name, a broken file and a bad playlist are refused with a reason naming
# them, the playlist before any window opens. The gallery imports a --preset-file into its own store.
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
refused() {  # refused PATTERN COMMAND...: the command fails, saying PATTERN
  local pattern=$1; shift
  if err=$("$@" 2>&1); then fail "accepted: $*"; fi
  grep -q -- "$pattern" <<<"$err" || fail "refusal of '$*' does not say '$pattern': $err"
}
export XDG_CONFIG_HOME=$out/config
look=(--set step=6 --set tier=low --set fold=1.1)
args=(--headless --scene kifs --size 96x54 --frames 2 --time 3 --seed 0 --validate)

"$vitrine" "${args[@]}" "${look[@]}" --out "$out/set.exr"
"$vitrine" "${args[@]}" "${look[@]}" --save-preset "evening look" --out "$out/saved.exr" | tee "$out/save.log"
saved=$out/config/vitrine/presets/kifs-evening%20look.json
[ -f "$saved" ] || fail "no preset file at $saved: $(ls -R "$out/config")"
grep -q '"name": "evening look"' "$saved" || fail "the file does not name the preset: $(cat "$saved")"

"$vitrine" --list-params kifs | grep "evening look  (yours)  step=6" >/dev/null \
  || fail "--list-params does not list the user's preset: $("$vitrine" --list-params kifs)"
"$vitrine" "${args[@]}" --preset "evening look" --out "$out/by_name.exr"
"$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/set.exr" "$out/by_name.exr"

"$vitrine" --export-preset "kifs.evening look" --out "$out/shared/evening.json"
cmp -s "$saved" "$out/shared/evening.json" || fail "export wrote another format than the store's"
# Another machine: no settings folder, only the shared file.
XDG_CONFIG_HOME=$out/elsewhere "$vitrine" "${args[@]}" --preset-file "$out/shared/evening.json" --out "$out/imported.exr"
"$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/set.exr" "$out/imported.exr"
# A preset and --set still compose in order: the file's values, then --set over them.
XDG_CONFIG_HOME=$out/elsewhere "$vitrine" "${args[@]}" --preset-file "$out/shared/evening.json" --set step=9 \
  --out "$out/imported_then_set.exr"
if "$vitrine" compare "$out/set.exr" "$out/imported_then_set.exr" >/dev/null 2>&1; then
  fail "--set after --preset-file changed nothing"
fi

# Saved through OSC by a headless --remote run: a value set, then /vitrine/preset/save SCENE NAME.
"$vitrine" --headless --scene kifs --size 32x18 --frames 100000 --remote --remote-bind 127.0.0.1:0 \
  --out "$out/remote.exr" >"$out/remote.log" 2>&1 &
pid=$!
for _ in $(seq 200); do grep -q "remote control on" "$out/remote.log" && break; sleep 0.1; done
port=$(sed -nE 's/.*remote control on 127\.0\.0\.1:([0-9]+).*/\1/p' "$out/remote.log")
python3 - "$port" <<'PY'
import socket, struct, sys, time
def pad(b): return b + b"\0" * (4 - len(b) % 4)
def osc(address, tags, *args):
    body = b"".join(struct.pack(">i", a) if t == "i" else pad(a.encode()) for t, a in zip(tags, args))
    return pad(address.encode()) + pad(("," + tags).encode()) + body
sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.sendto(osc("/vitrine/kifs/step", "i", 4), ("127.0.0.1", int(sys.argv[1])))
time.sleep(0.5)
sock.sendto(osc("/vitrine/preset/save", "ss", "kifs", "remote look"), ("127.0.0.1", int(sys.argv[1])))
time.sleep(0.5)
PY
kill -TERM $pid; wait $pid || fail "the --remote run failed: $(cat "$out/remote.log")"
remote=$out/config/vitrine/presets/kifs-remote%20look.json
[ -f "$remote" ] || fail "OSC saved no preset: $(cat "$out/remote.log")"
grep -q '"step": 4' "$remote" || fail "the OSC preset lacks step 4: $(cat "$remote")"
"$vitrine" "${args[@]}" --preset "remote look" --out "$out/remote_by_name.exr"
"$vitrine" "${args[@]}" --set step=4 --out "$out/step4.exr"
"$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/step4.exr" "$out/remote_by_name.exr"

refused "one of the scene's own presets" "$vitrine" "${args[@]}" --save-preset sphere --out "$out/x.exr"
refused "yours: 'evening look'" "$vitrine" "${args[@]}" --preset nope --out "$out/x.exr"
printf '{"version": 1, "scene": "kifs", "name": "bad", "values": {"step": 12}}' >"$out/bad.json"
refused "bad.json is not a preset (step=12" "$vitrine" "${args[@]}" --preset-file "$out/bad.json" --out "$out/x.exr"
refused "/dev/null is not a preset (not a regular file)" "$vitrine" "${args[@]}" --preset-file /dev/null --out "$out/x.exr"
printf '{"version": 1,' >"$out/broken.json"
refused "broken.json is not a preset (not JSON" "$vitrine" "${args[@]}" --preset-file "$out/broken.json" --out "$out/x.exr"

# The gallery imports a --preset-file: it joins the user's presets of that machine, file for file.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/virtual_display.sh"
trap 'kill ${app:-} ${xvfb:-} 2>/dev/null; wait 2>/dev/null' EXIT
start_display 640x360
(DISPLAY=$display XDG_CONFIG_HOME=$out/gallery exec "$vitrine" --scene kifs --size 320x180 --no-vsync --validate \
   --preset-file "$out/shared/evening.json") >"$out/gallery.log" 2>&1 &
app=$!
wait_for_showing "$out/gallery.log"
python3 "$here/xtest.py" "$display" key:Escape || fail "xtest"
wait $app || fail "the gallery with --preset-file failed: $(cat "$out/gallery.log")"
grep -q "validation" "$out/gallery.log" && fail "validation messages: $(cat "$out/gallery.log")"
cmp -s "$saved" "$out/gallery/vitrine/presets/kifs-evening%20look.json" ||
  fail "the gallery did not import the preset file: $(ls -R "$out/gallery") $(cat "$out/gallery.log")"

# A playlist's bad line is refused by number before a window opens (no display is needed to say so).
printf 'kifs sphere 10\n# a comment\nkifs evening look 20\nnoodles nope 5\n' >"$out/playlist.txt"
refused "playlist.txt:4: noodles has no preset 'nope'" env -u DISPLAY "$vitrine" --kiosk --playlist "$out/playlist.txt"
refused "--playlist is the kiosk's" "$vitrine" --playlist "$out/playlist.txt"
echo "user presets ok"
