#!/usr/bin/env bash
# out_mixed_case.sh VITRINE OUTDIR: `--out x.Png` is the same 8-bit sRGB PNG as `--out x.png` (it once
# held linear values, far too dark), and `--out x.EXR` the same EXR as `--out x.exr`.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
for name in lower.png mixed.Png lower.exr mixed.eXr; do
  "$vitrine" --headless --scene kifs --size 32x18 --time 1 --out "$out/$name" >/dev/null
done
cmp "$out/lower.png" "$out/mixed.Png" || { echo "FAIL: x.Png differs from x.png"; exit 1; }
"$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/lower.exr" "$out/mixed.eXr" >/dev/null ||
  { echo "FAIL: x.eXr differs from x.exr"; exit 1; }
echo "ok: the name's case does not change the pixels"
