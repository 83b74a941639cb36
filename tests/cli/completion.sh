#!/usr/bin/env bash
# completion.sh VITRINE OUT: the bash completion script `vitrine --help-completion` prints is valid bash
# and, driven through bash's own COMP_WORDS/COMP_CWORD machinery as a shell at a prompt drives it,
# completes flags by mode, scene names, parameter keys, choices and preset names (the user's own too,
# from a scratch config folder).
set -euo pipefail
vitrine=$(realpath "$1"); out=$2
rm -rf "$out"; mkdir -p "$out/config"
"$vitrine" --help-completion >"$out/vitrine.bash"
bash -n "$out/vitrine.bash"
export XDG_CONFIG_HOME=$out/config
# A preset of the user's, with a space in its name, to be found by name.
"$vitrine" --headless --scene kifs --size 16x9 --set step=4 --save-preset "evening look" --out "$out/x.exr" >/dev/null

failed=0
# complete_words "LINE": COMPREPLY for the line's last word (empty after a final space), as
# `complete -F` would set it, sorted, one a line.
complete_words() {
  local -a words; read -ra words <<<"$1"
  [[ $1 == *" " ]] && words+=("")
  bash -c 'source "$1"; shift
           [[ $(complete -p vitrine) == *"-F _vitrine"* ]] || { echo "not registered"; exit 1; }
           COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
           _vitrine; printf "%s\n" "${COMPREPLY[@]}" | sort' \
    bash "$out/vitrine.bash" "$vitrine" "${words[@]}"
}
# expect "WORDS" PATTERN...: each grep -x PATTERN matches a line of the completion of WORDS.
expect() {
  local words=$1; shift
  local got; got=$(complete_words "$words")
  for pattern in "$@"; do
    if ! grep -qxe "$pattern" <<<"$got"; then
      echo "FAIL: '$words' -> no '$pattern' among:"; sed 's/^/    /' <<<"$got"; failed=1
    fi
  done
}
# refuse "WORDS" PATTERN: no line of the completion matches.
refuse() {
  local got; got=$(complete_words "$1")
  if grep -qxe "$2" <<<"$got"; then echo "FAIL: '$1' offers '$2'"; failed=1; fi
}

expect "--sce" --scene
expect "--scene b" bloom
expect "--scene " bloom glass neon kifs noodles calibrate
expect "bench --scene " all
refuse "--scene " all
expect "--set bloom." 'bloom\.[a-z_]*=' "bloom.$("$vitrine" --list-keys bloom | head -1 | cut -d. -f2)="
refuse "--set bloom." 'kifs\..*'
expect "--set " 'bloom\.' 'kifs\.'
expect "--scene kifs --set st" 'step='
expect "--flash-guard o" on off
expect "record --codec p" prores prores4444
expect "--preset kifs." 'kifs\.evening\\ look' "kifs.$("$vitrine" --list-presets kifs | head -1 | cut -d. -f2)"
# Each mode offers its own flags: --fps is record's, --json bench's, --out not the gallery's.
expect "record --f" --fps --format --flash-guard --full-range
refuse "--headless --f" --fps
expect "bench --j" --json
refuse "--o" --out
expect "--headless --o" --out --output-warp
expect "--list-p" --list-params --list-presets
expect "re" record
[ $failed = 0 ] && echo "completion: every case completes"
exit $failed
