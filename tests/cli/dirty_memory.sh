#!/usr/bin/env bash
# dirty_memory.sh VITRINE OUTDIR: no frame reads GPU memory that nothing wrote. lavapipe hands out zeroed
# memory, where a GPU may hand back another program's; VITRINE_INJECT=dirty-memory fills every fresh
# allocation with garbage (src/gpu/fault_injection.h), and each run below must draw, bit for bit, what it
# draws in clean memory: every scene, the paths its options take (the diamond and the history TAA
# keeps, the baked flow, the flash guard's), and bloom's lattice, which only its clear at creation keeps
# empty outside the crystal (without it, 16 % of that run's pixels differ).
set -eu
vitrine=$1; out=$2; inputs=$(dirname "$0")/../input
rm -rf "$out"; mkdir -p "$out"
runs=(  # scene|frames|options: one run a scene, with the options that take the most paths
  "bloom|40|--set lattice=48 --input $inputs/bloom_press.txt"
  "glass|6|--set shape=diamond --set optics=physical"
  "neon|6|--preset dense"
  "kifs|6|"
  "noodles|6|--preset smooth --set field_source=baked --flash-guard on"
)
for i in "${!runs[@]}"; do
  IFS='|' read -r scene frames options <<<"${runs[$i]}"
  for memory in clean dirty; do
    inject=; [ $memory = dirty ] && inject=dirty-memory:1
    # shellcheck disable=SC2086 # the options are words
    VITRINE_INJECT=$inject "$vitrine" --headless --scene "$scene" --size 96x54 --validate --frames "$frames" $options \
      --out "$out/$i-$memory.exr" >/dev/null
  done
  same=yes
  result=$("$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/$i-clean.exr" "$out/$i-dirty.exr" 2>&1) || same=no
  echo "$scene $options: $result"
  [ $same = yes ] || { echo "$scene $options reads memory nothing wrote"; exit 1; }
done
