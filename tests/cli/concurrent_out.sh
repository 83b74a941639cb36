#!/usr/bin/env bash
# concurrent_out.sh VITRINE OUTDIR: four headless renders writing the same --out at once all succeed,
# and what is left is one whole EXR that compare reads, with no temporary files beside it.
set -u
vitrine=$1; dir=$2/concurrent
rm -rf "$dir"; mkdir -p "$dir"
pids=()
for t in 1 2 3 4; do
  "$vitrine" --headless --scene kifs --size 64x36 --time "$t" --validate --out "$dir/out.exr" >"$dir/log$t" 2>&1 &
  pids+=($!)
done
failed=0
for i in "${!pids[@]}"; do
  if ! wait "${pids[$i]}"; then echo "render $((i + 1)) failed:"; cat "$dir/log$((i + 1))"; failed=1; fi
done
[ $failed -eq 0 ] || exit 1
"$vitrine" compare "$dir/out.exr" "$dir/out.exr" || { echo "compare could not read the result"; exit 1; }
left=$(ls -A "$dir" | grep -v -e '^out\.exr$' -e '^log[0-9]$' || true)
[ -z "$left" ] || { echo "left behind: $left"; exit 1; }
echo "ok: four concurrent writers, one whole file"
