#!/usr/bin/env bash
# compare_fixtures.sh VITRINE OUTDIR: the files the compare-input tests feed to `vitrine compare`: a
# 64x36 EXR (to mismatch a 192x108 golden) and a PNG renamed .exr.
set -eu
vitrine=$1; dir=$2/compare
rm -rf "$dir"; mkdir -p "$dir"
"$vitrine" --headless --scene kifs --size 64x36 --validate --out "$dir/small.exr"
"$vitrine" --headless --scene kifs --size 64x36 --validate --out "$dir/small.png"
cp "$dir/small.png" "$dir/png_named.exr"
