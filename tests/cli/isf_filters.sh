#!/usr/bin/env bash
# isf_filters.sh VITRINE ISF_DIR OUTDIR: ISF filters on the command line. --set filter.NAME.KEY reaches
# the filter (an inversion at amount 0 is the plain picture, at 1 it is not); a --set naming no filter,
# a file that is not a filter and a value out of range are refused, naming what is wrong; a recording
# keeps its filters and their values in record.json and refuses to resume with other ones.
set -u
vitrine=$1; isf=$2; out=$3
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
args=(--headless --scene calibrate --size 160x90 --frames 1 --validate)
"$vitrine" "${args[@]}" --out "$out/plain.exr" || fail "the plain run failed"
"$vitrine" "${args[@]}" --filter "$isf/filter_invert.fs" --set filter.filter_invert.amount=0 --out "$out/none.exr" ||
  fail "the run with the filter failed"
"$vitrine" compare "$out/plain.exr" "$out/none.exr" || fail "an inversion by 0 changed the picture"
"$vitrine" "${args[@]}" --filter "$isf/filter_invert.fs" --set filter.filter_invert.amount=1 --out "$out/inverted.exr" ||
  fail "the run with the filter at 1 failed"
"$vitrine" compare "$out/plain.exr" "$out/inverted.exr" >/dev/null 2>&1 && fail "an inversion by 1 left the picture as it was"

refused() {  # refused PATTERN ARGS...: the run fails and says PATTERN
  local pattern=$1; shift
  if err=$("$vitrine" "${args[@]}" "$@" --out "$out/x.exr" 2>&1); then fail "accepted: $*"; fi
  grep -q -- "$pattern" <<<"$err" || fail "'$*' was refused without '$pattern': $err"
}
refused "no --filter is named nope (the filters are filter_invert)" --filter "$isf/filter_invert.fs" --set filter.nope.amount=1
refused "expects filter.NAME.KEY=VALUE" --filter "$isf/filter_invert.fs" --set filter.amount=1
refused "is an ISF transition, not a filter" --filter "$isf/transition_mix.fs"
refused "filter filter_invert .* rejects amount=7" --filter "$isf/filter_invert.fs" --set filter.filter_invert.amount=7
refused "transition.KEY=VALUE needs --transition" --set transition.dip=1

# A film with a filter: its record.json names the filter's file and values, and a resume with another
# value is refused.
film=(--scene calibrate --size 64x36 --fps 30 --seconds 0.1 --validate --filter "$isf/filter_invert.fs")
"$vitrine" record "${film[@]}" --set filter.filter_invert.amount=0.25 --out "$out/film" || fail "the film failed"
grep -q '"filter_invert [0-9a-f]\{16\}"' "$out/film/record.json" || fail "record.json names no filter: $(cat "$out/film/record.json")"
grep -q '"filter.filter_invert.amount": "0.25"' "$out/film/record.json" || fail "record.json holds no filter value"
if err=$("$vitrine" record "${film[@]}" --set filter.filter_invert.amount=0.5 --out "$out/film" 2>&1); then
  fail "a resume with another filter value was accepted"
fi
grep -q "filter.filter_invert.amount: 0.25 in the folder, 0.5 in this run" <<<"$err" || fail "the refusal does not say the value: $err"
echo "isf filters ok"
