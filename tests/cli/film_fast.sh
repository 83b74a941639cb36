#!/usr/bin/env bash
# film_fast.sh VITRINE OUTDIR: a film's frames packed on the GPU and encoded on their own thread are
# the frames the CPU made before: `record --out` films, decoded, hold exactly the bytes of the same
# frames recorded as PNGs and encoded from the folder (the read-back path): H.264 at a size whose rows
# the converter splits into bands, FFV1 at an odd size (a packed frame's last word half empty). The
# stages line says the frames were packed on the GPU.
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
for tool in ffprobe ffmpeg; do
  command -v $tool >/dev/null || { echo "film_fast.sh needs $tool (apt-get install ffmpeg)"; exit 1; }
done
decoded() { ffmpeg -v error -i "$1" -map 0:v -f rawvideo -pix_fmt rgb24 -y "$2"; }

check() {  # check NAME FILM-EXTENSION RECORD-ARGS...: the film against its PNG frames encoded by `encode`
  local name=$1 ext=$2; shift 2
  VITRINE_FILM_STAGES=1 "$vitrine" record "$@" --validate --out "$out/$name.$ext" >"$out/$name.log" 2>"$out/$name.err" ||
    { cat "$out/$name.err"; exit 1; }
  grep "^film stages" "$out/$name.log"
  grep -q "packed on the GPU" "$out/$name.log" || { echo "$name: not packed on the GPU"; exit 1; }
  "$vitrine" record "$@" --format png --out "$out/$name-frames" >/dev/null 2>&1
  "$vitrine" encode "$out/$name-frames" --out "$out/$name-encoded.$ext" >/dev/null 2>&1
  decoded "$out/$name.$ext" "$out/$name.rgb"
  decoded "$out/$name-encoded.$ext" "$out/$name-encoded.rgb"
  local frames=$(ls "$out/$name-frames" | grep -c '\.png$')
  local size=$(stat -c %s "$out/$name.rgb")
  [ "$size" -gt 0 ] && [ $((size % frames)) = 0 ] || { echo "$name: $size bytes for $frames frames"; exit 1; }
  cmp "$out/$name.rgb" "$out/$name-encoded.rgb" || { echo "$name: the film's frames differ from its PNGs encoded"; exit 1; }
  echo "$name: $frames frames, $size bytes decoded, identical to the PNG frames encoded"
}

check kifs-h264 mp4 --scene kifs --size 96x160 --fps 30 --seconds 0.5
check kifs-ffv1 mkv --scene kifs --size 63x35 --fps 30 --seconds 0.5
echo "film_fast ok"
