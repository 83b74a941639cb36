#!/usr/bin/env bash
# presets.sh VITRINE GOLDEN_DIR OUTDIR: --preset applies a scene's named values (kifs' "sphere" is
# step 1, so it reproduces the step-1 golden); --set after it still applies; qualified and
# unqualified forms agree; an unknown preset is refused with the list.
set -eu
vitrine=$1; golden=$2; out=$3
mkdir -p "$out"
args=(--headless --scene kifs --size 192x108 --frames 1 --time 3 --seed 0 --validate)
"$vitrine" "${args[@]}" --preset sphere --out "$out/preset.exr"
"$vitrine" compare "$golden/kifs_step1.exr" "$out/preset.exr"
"$vitrine" "${args[@]}" --preset kifs.final --set step=1 --out "$out/preset_then_set.exr"
"$vitrine" compare "$golden/kifs_step1.exr" "$out/preset_then_set.exr"
if err=$("$vitrine" "${args[@]}" --preset nope --out "$out/x.exr" 2>&1); then echo "unknown preset accepted"; exit 1; fi
grep -q "sphere" <<<"$err" || { echo "the refusal does not list the presets: $err"; exit 1; }
echo "presets ok"
