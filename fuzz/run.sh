#!/usr/bin/env bash
# run.sh fuzz TARGET SECONDS WORKDIR SEEDS: a bounded libFuzzer run, growing WORKDIR/corpus from SEEDS;
#   a crash, leak, sanitizer report, timeout (10 s an input) or out-of-memory (2.5 GB) fails the test
#   and leaves the input in WORKDIR/artifacts/: keep it in tests/fuzz-regressions/NAME/ and fix the bug.
# run.sh replay TARGET REGRESSIONS SEEDS: every kept crash input and seed run once; all must pass.
set -uo pipefail
mode=$1 target=$2
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}
# Third-party leaks only, each with its reason (fuzz/lsan.supp).
export LSAN_OPTIONS=suppressions=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}
case $mode in
fuzz)
  seconds=$3 work=$4 seeds=$5
  mkdir -p "$work/corpus" "$work/artifacts"
  dirs=("$work/corpus")
  [ -d "$seeds" ] && dirs+=("$seeds")
  "$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 -print_final_stats=1 \
    -artifact_prefix="$work/artifacts/" "${dirs[@]}"
  rc=$?
  if [ $rc != 0 ]; then
    echo "fuzz: $(basename "$target") failed; its input is in $work/artifacts/: copy it into" \
      "tests/fuzz-regressions/${target##*/fuzz_}/ and fix the bug" >&2
  fi
  exit $rc
  ;;
replay)
  files=()
  for dir in "$3" "$4"; do
    [ -d "$dir" ] && while IFS= read -r -d '' f; do files+=("$f"); done < <(find "$dir" -type f -print0 | sort -z)
  done
  ((${#files[@]})) || { echo "replay: no inputs for $(basename "$target")"; exit 0; }
  echo "replay: ${#files[@]} inputs"
  exec "$target" "${files[@]}"
  ;;
*) echo "run.sh: fuzz or replay, not '$mode'" >&2; exit 2 ;;
esac
