#!/usr/bin/env bash
# unreadable_inputs.sh VITRINE OUTDIR: a fifo with no writer, or a link to /dev/zero, where Vitrine reads a
# file (a sound for --audio-in, a film's audio.wav for encode, a checkpoint) is refused at once, naming
# the file, instead of waiting forever for a writer or reading until memory runs out. Each run has 20 s.
set -uo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
mkfifo "$out/fifo"
ln -s /dev/zero "$out/zero"
fails=0

# refused REGEX -- COMMAND...: exits non-zero within 20 s (not killed) with stderr matching REGEX, in
# under 256 MB of memory.
refused() {
  local regex=$1; shift 2
  local err code
  err=$(ulimit -v 4000000; timeout 20 "$@" 2>&1 >/dev/null); code=$?
  if [ $code -eq 0 ] || [ $code -ge 124 ]; then
    echo "FAIL (exit $code, 124: hung for 20 s): $*"; echo "$err" | tail -3; fails=$((fails + 1)); return
  fi
  if ! grep -Eq -e "$regex" <<<"$err"; then
    echo "FAIL: stderr did not match /$regex/: $*"; echo "$err" | tail -3; fails=$((fails + 1)); return
  fi
  echo "ok (exit $code): $(head -c 300 <<<"$err")"
}

refused "fifo.*fifo, not a regular file" -- "$vitrine" --headless --scene kifs --size 32x18 --audio-in "$out/fifo" \
  --out "$out/a.exr"
refused "zero.*character device, not a regular file" -- "$vitrine" --headless --scene kifs --size 32x18 \
  --audio-in "$out/zero" --out "$out/b.exr"
refused "fifo.*fifo, not a regular file" -- "$vitrine" record --scene kifs --size 32x18 --fps 10 --seconds 0.2 \
  --audio-in "$out/fifo" --out "$out/film-audio"

# A film with its checkpoints; each checkpoint in turn a fifo, then /dev/zero, when the run resumes.
film=(record --scene bloom --preset quick --size 32x18 --fps 10 --seconds 0.4)
"$vitrine" "${film[@]}" --checkpoint-every 2 --out "$out/film" >/dev/null 2>&1 || { echo "the film was not recorded"; exit 1; }
for kind in fifo zero; do
  mkdir -p "$out/resume-$kind"; cp "$out/film/record.json" "$out/resume-$kind/"
  ln -s "$out/$kind" "$out/resume-$kind/checkpoint_000002.state"
  refused "checkpoint_000002.state.*not a regular file" -- "$vitrine" "${film[@]}" --range 3:4 --out "$out/resume-$kind"
done

# encode reads the film's audio.wav.
if grep -q "vitrine encode" <<<"$("$vitrine" --help 2>&1)"; then
  mkdir -p "$out/encode"; cp "$out/film/"frame_*.exr "$out/film/record.json" "$out/encode/"
  ln -s "$out/fifo" "$out/encode/audio.wav"
  refused "audio.wav.*fifo, not a regular file" -- "$vitrine" encode "$out/encode" --out "$out/encode.mkv"
fi
[ $fails -eq 0 ] || { echo "$fails refused runs failed"; exit 1; }
