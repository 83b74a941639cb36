#!/usr/bin/env bash
# checkpoint.sh VITRINE OUTDIR: `record --checkpoint-every N` saves the simulation beside the frames, and
# a later run starts from the latest checkpoint at or before its first missing frame: its frames are a
# whole run's bit for bit for bloom (through its phase flips), neon (mid-stroke, with beat bursts from
# --audio-in, two samples a frame) and noodles (mid-drag); a resumed whole run writes the same sound;
# --checkpoints-only simulates without drawing; a corrupt or foreign checkpoint, or one whose values are
# not the film's, is refused, naming the file, before anything is written.
set -euo pipefail
vitrine=$1; out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$out"; mkdir -p "$out"

same() {  # same WHOLE PART FIRST LAST: the part's frames FIRST..LAST are the whole run's, bit for bit
  for f in $(seq "$3" "$4"); do
    n=$(printf %06d "$f")
    # Equal files are equal frames (the writer's bytes follow from the pixels alone); only files that
    # differ are read and compared pixel by pixel, which costs a process start of ~0.1 CPU-s a frame.
    cmp -s "$1/frame_$n.exr" "$2/frame_$n.exr" ||
      "$vitrine" compare --fail-fraction 0 --hard-limit 0 "$1/frame_$n.exr" "$2/frame_$n.exr" >/dev/null ||
      { echo "$2: frame $f differs from the whole run's"; exit 1; }
  done
}
# part WHOLE PART CHECKPOINT: a folder holding only the film's record.json and one of its checkpoints.
part() { mkdir -p "$2"; cp "$1/record.json" "$1/checkpoint_$(printf %06d "$3").state" "$2/"; }

# Four kicks for neon's audio mapping (a burst on each beat).
python3 - "$out/kicks.wav" <<'PY'
import math, struct, sys, wave
rate = 48000
samples = [0.0] * (rate * 3)
for k in (0.3, 0.8, 1.3, 1.8):
    start, phase = int(k * rate), 0.0
    for i in range(int(0.15 * rate)):
        t = i / rate
        phase += 2 * math.pi * (55 + 95 * math.exp(-t * 40)) / rate
        samples[start + i] += 0.9 * math.exp(-t * 25) * math.sin(phase)
with wave.open(sys.argv[1], "wb") as w:
    w.setnchannels(1); w.setsampwidth(2); w.setframerate(rate)
    w.writeframes(b"".join(struct.pack("<h", int(max(-1, min(1, s)) * 32767)) for s in samples))
PY

# bloom: the vapour held on the crystal; checkpoint 7 falls between its rose and crimson flips, while a
# reading of the lattice is still on its way back from the GPU.
bloom=(record --scene bloom --preset quick --size 64x36 --fps 30 --seconds 2 --input "$here/input/bloom_hold.txt" --validate)
"$vitrine" "${bloom[@]}" --checkpoint-every 7 --events "$out/bloom-events.jsonl" --out "$out/bloom" | tee "$out/bloom.log"
grep -q "8 checkpoints written" "$out/bloom.log"
grep -q '"chroma"' "$out/bloom-events.jsonl"  # the film crosses every flip
part "$out/bloom" "$out/bloom-7" 7
"$vitrine" "${bloom[@]}" --range 8:16 --out "$out/bloom-7" | grep "simulated from the checkpoint at frame 7" >/dev/null
same "$out/bloom" "$out/bloom-7" 8 15
part "$out/bloom" "$out/bloom-49" 49
"$vitrine" "${bloom[@]}" --range 52:60 --out "$out/bloom-49" | grep "recorded 8 of frames 52..59 .*checkpoint at frame 49" >/dev/null
same "$out/bloom" "$out/bloom-49" 52 59
# A whole run missing its last frames resumes from the latest checkpoint before them; its sound is the
# whole film's all the same (the checkpoint carries the sound so far).
cp -r "$out/bloom" "$out/bloom-resumed"
rm "$out/bloom-resumed"/frame_00004[5-9].exr "$out/bloom-resumed"/frame_00005*.exr "$out/bloom-resumed/audio.wav"
"$vitrine" "${bloom[@]}" --checkpoint-every 7 --out "$out/bloom-resumed" | grep "recorded 15 of frames 0..59 .*checkpoint at frame 42" >/dev/null
cmp "$out/bloom/audio.wav" "$out/bloom-resumed/audio.wav"
same "$out/bloom" "$out/bloom-resumed" 45 59
# --checkpoints-only: every checkpoint, no frame; a range from one of them is the whole run's.
"$vitrine" "${bloom[@]}" --checkpoint-every 25 --checkpoints-only --out "$out/bloom-sim" | grep "recorded 0 of frames 0..59 .*2 checkpoints written" >/dev/null
test -z "$(ls "$out/bloom-sim" | grep '^frame_')"
"$vitrine" "${bloom[@]}" --range 55:58 --out "$out/bloom-sim" | grep "checkpoint at frame 50" >/dev/null
same "$out/bloom" "$out/bloom-sim" 55 57

# neon: checkpoint 10 falls mid-stroke (a pen held by the drag), with beat bursts from the music.
neon=(record --scene neon --set chains=256 --size 64x36 --fps 30 --spp 2 --seconds 2 --validate
      --input "$here/input/neon_drag.txt" --audio-in "$out/kicks.wav")
"$vitrine" "${neon[@]}" --checkpoint-every 10 --events "$out/neon-events.jsonl" --out "$out/neon" >/dev/null
test "$(grep -c '"by":"burst"' "$out/neon-events.jsonl")" -ge 8
for at in 10 40; do
  part "$out/neon" "$out/neon-$at" $at
  "$vitrine" "${neon[@]}" --range $((at + 2)):$((at + 12)) --out "$out/neon-$at" | grep "checkpoint at frame $at" >/dev/null
  same "$out/neon" "$out/neon-$at" $((at + 2)) $((at + 11))
done

# noodles: checkpoint 10 falls mid-drag (the camera on its orbit).
noodles=(record --scene noodles --set grid=8x8x4 --size 64x36 --fps 30 --seconds 1.5 --validate
         --input "$here/input/drag_example.txt")
"$vitrine" "${noodles[@]}" --checkpoint-every 10 --out "$out/noodles" >/dev/null
part "$out/noodles" "$out/noodles-10" 10
"$vitrine" "${noodles[@]}" --range 12:20 --out "$out/noodles-10" | grep "checkpoint at frame 10" >/dev/null
same "$out/noodles" "$out/noodles-10" 12 19

# A corrupt checkpoint is refused, naming it; nothing in the folder is written or removed.
refused() {  # refused FOLDER PATTERN: the range run fails, saying PATTERN, and leaves the folder as it was
  local before; before=$(ls -l --time-style=+%s.%N "$1" | md5sum)
  if "$vitrine" "${neon[@]}" --range 42:50 --out "$1" 2>"$out/err.txt"; then echo "a bad checkpoint was used"; exit 1; fi
  grep -q "checkpoint_000040.state $2" "$out/err.txt" || { cat "$out/err.txt"; exit 1; }
  test "$(ls -l --time-style=+%s.%N "$1" | md5sum)" = "$before"
}
part "$out/neon" "$out/bad" 40
cp "$out/neon/frame_000042.exr" "$out/bad/"
python3 -c "import sys; p = sys.argv[1]; b = bytearray(open(p, 'rb').read()); b[len(b) // 2] ^= 1; open(p, 'wb').write(b)" \
  "$out/bad/checkpoint_000040.state"
refused "$out/bad" "is corrupt: its checksum does not match"
truncate -s 2000 "$out/bad/checkpoint_000040.state"
refused "$out/bad" "is cut short"
cp "$out/noodles/checkpoint_000010.state" "$out/bad/checkpoint_000040.state"  # another film's
refused "$out/bad" "belongs to another film"
# A value edited inside a checkpoint, its checksum recomputed: the restored values are not the ones the
# film's record.json names, so it is refused, naming the value, before anything is written.
part "$out/neon" "$out/edited" 40
cp "$out/neon/frame_000042.exr" "$out/edited/"
python3 - "$out/edited/checkpoint_000040.state" vignette <<'PY'
import struct, sys
path, key = sys.argv[1], sys.argv[2].encode()
header, payload = open(path, "rb").read().split(b"\n", 1)
name = struct.pack("<Q", len(key)) + key  # the archive's strings: a 64-bit length, then the bytes
at = payload.index(name) + len(name)
length = struct.unpack("<Q", payload[at:at + 8])[0]
value = bytearray(payload[at + 8:at + 8 + length])
last = max(i for i, c in enumerate(value) if chr(c).isdigit())
value[last] = ord("1") if value[last] != ord("1") else ord("2")  # another valid value, the same length
payload = payload[:at + 8] + bytes(value) + payload[at + 8 + length:]
digest = 0xcbf29ce484222325
for byte in payload:
    digest = ((digest ^ byte) * 0x100000001b3) & (2**64 - 1)
fields = header.split(b" ")
fields[-1] = b"%016x" % digest
open(path, "wb").write(b" ".join(fields) + b"\n" + payload)
PY
refused "$out/edited" "does not fit this run: it holds vignette="

# What cannot be checkpointed says so.
"$vitrine" record --scene glass --size 32x18 --seconds 0.1 --checkpoint-every 1 --out "$out/glass" 2>"$out/err.txt" >/dev/null
grep -q "glass cannot be checkpointed" "$out/err.txt"
test -z "$(ls "$out/glass" | grep '^checkpoint_')"
if "$vitrine" record --scene kifs --seconds 1 --checkpoints-only --out "$out/x" 2>"$out/err.txt"; then exit 1; fi
grep -q "say how often with --checkpoint-every" "$out/err.txt"
if "$vitrine" record --scene kifs --seconds 1 --checkpoint-every 5 --out "$out/x.mp4" 2>"$out/err.txt"; then exit 1; fi
grep -q "is a film, rendered whole" "$out/err.txt"
echo "checkpoints ok"
