#!/usr/bin/env bash
# record_manifest.sh VITRINE OUTDIR: a folder remembers the film it holds (record.json); a run with
# other parameters is refused, naming what differs, before it renders, and the frames stay one film.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; cat "$out/log"; exit 1; }
"$vitrine" record --scene neon --size 48x27 --fps 10 --seconds 0.6 --range 0:3 --out "$out/film" >"$out/log" 2>&1 ||
  fail "the first part failed"
python3 -c "import json,sys; m=json.load(open(sys.argv[1])); assert m['scene']=='neon' and m['width']==48 and m['fps']==10, m" \
  "$out/film/record.json" || fail "record.json does not hold the run"
# Another scene and size into the same folder: refused, naming both.
if "$vitrine" record --scene kifs --size 80x45 --fps 10 --seconds 0.6 --out "$out/film" >"$out/log" 2>&1; then
  fail "a kifs film was resumed into a neon folder"
fi
grep -q "holds another film" "$out/log" || fail "no refusal"
grep -q "scene: neon in the folder, kifs in this run" "$out/log" || fail "the scene not named"
grep -q "size: 48x27 in the folder, 80x45 in this run" "$out/log" || fail "the size not named"
# The same scene with one value changed: the key is named.
if "$vitrine" record --scene neon --size 48x27 --fps 10 --seconds 0.6 --set glow=0.9 --out "$out/film" >"$out/log" 2>&1; then
  fail "a film with another glow was resumed"
fi
grep -q "glow: .* in the folder, 0.9 in this run" "$out/log" || fail "the changed value not named"
test "$(ls "$out/film" | grep -c '^frame_')" = 3 || fail "frames were written by a refused run"
# The same film: resumed, the rest written.
"$vitrine" record --scene neon --size 48x27 --fps 10 --seconds 0.6 --out "$out/film" >"$out/log" 2>&1 || fail "resume failed"
grep -q "recorded 3 of frames 0..5" "$out/log" || fail "the resume did not write the missing three"
# Frames with no manifest (an older run's, or copied in): refused rather than guessed.
mkdir -p "$out/old" && cp "$out/film/frame_000000.exr" "$out/old/"
if "$vitrine" record --scene neon --size 48x27 --fps 10 --seconds 0.6 --out "$out/old" >"$out/log" 2>&1; then
  fail "frames of unknown origin were resumed"
fi
grep -q "holds frames but no record.json" "$out/log" || fail "no reason for the unknown frames"
echo "record manifest ok"
