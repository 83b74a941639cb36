#!/usr/bin/env bash
# headless_roundtrip.sh VITRINE GOLDEN OUTDIR: the documented headless command line, with validation,
# reproduces a golden frame through the CLI, EXR writer and compare command.
set -eu
vitrine=$1; golden=$2; out=$3
mkdir -p "$out"
"$vitrine" --headless --scene kifs --size 192x108 --frames 3 --time 3 --seed 7 --set step=9 --validate \
  --out "$out/roundtrip.exr"
"$vitrine" --headless --scene kifs --size 192x108 --frames 3 --time 3 --seed 7 --set step=9 --validate \
  --out "$out/roundtrip.png"
test -s "$out/roundtrip.png"
"$vitrine" compare "$golden" "$out/roundtrip.exr"
