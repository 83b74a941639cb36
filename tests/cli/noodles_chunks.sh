#!/usr/bin/env bash
# noodles_chunks.sh VITRINE OUTDIR: strands bound in chunks draw the picture one binding draws. A device
# whose storage bindings cover 1 MiB (VITRINE_INJECT=storage-range, src/gpu/fault_injection.h) splits the
# default nest's 4.3 MB of nodes into five bindings, as 10^7 segments split on lavapipe's 128 MiB: the
# same segments win every sample, and only the order the chunks' shading adds up in differs (2e-3).
# A range smaller than one strand's nodes is refused, so the injected range is the one the plan used.
# And four samples a pixel need four keys each (at 160x90, 460 KB in one binding): where the range
# cannot hold them the frame falls back to one sample, the msaa=off picture bit for bit.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
run() { local to=$1; shift; "$vitrine" --headless --scene noodles --size 160x90 --frames 3 --validate --out "$to" "$@"; }
run "$out/one.exr"
VITRINE_INJECT=storage-range:1048576 run "$out/chunked.exr"
"$vitrine" compare "$out/one.exr" "$out/chunked.exr" | tee "$out/compare.txt"
grep -q "^pass: 0 failing pixels" "$out/compare.txt"
awk '/max difference/ { for (i = 1; i < NF; i++) if ($i == "difference") found = $(i + 1) + 0 }
     END { if (found == "" || found >= 2e-3) { print "chunked picture off by " found; exit 1 } }' "$out/compare.txt"
if VITRINE_INJECT=storage-range:512 run "$out/refused.exr" 2>"$out/refused.txt"; then
  echo "a 512-byte storage range was not refused"; exit 1
fi
grep -q "maxStorageBufferRange" "$out/refused.txt" || { cat "$out/refused.txt"; exit 1; }
VITRINE_INJECT=storage-range:262144 run "$out/fallback.exr"
VITRINE_INJECT=storage-range:262144 run "$out/one-sample.exr" --set msaa=off
"$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/one-sample.exr" "$out/fallback.exr" >/dev/null ||
  { echo "the fallback to one sample is not the msaa=off picture"; exit 1; }
if "$vitrine" compare "$out/chunked.exr" "$out/fallback.exr" | grep -q "max difference 0.00000,"; then
  echo "the fallback drew four samples a pixel"; exit 1
fi
echo "chunked nest ok"
