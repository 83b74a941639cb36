#!/usr/bin/env bash
# man_page.sh VITRINE OUT: `vitrine --help-man` is a man page groff reads without a warning, man can
# render and index (lexgrog finds its NAME), and it has an entry for every flag --help lists.
set -euo pipefail
vitrine=$1; out=$2
mkdir -p "$out"
"$vitrine" --help-man >"$out/vitrine.1"
warnings=$(groff -man -Tutf8 -ww -z "$out/vitrine.1" 2>&1)
[ -z "$warnings" ] || { echo "groff warns:"; echo "$warnings"; exit 1; }
lexgrog "$out/vitrine.1" | grep -q 'vitrine - a gallery of real-time GPU pieces'
MANWIDTH=100 man -l "$out/vitrine.1" 2>/dev/null >"$out/vitrine.txt"
# The flags of --help's entries ("  --scene NAME", "  -h, --help"), each an entry of the rendered page.
missing=0; count=0
for flag in $("$vitrine" --help | sed -nE 's/^  (-h, )?(--[a-z0-9-]+).*/\2/p' | sort -u); do
  count=$((count + 1))
  grep -qE "^ +(-h, )?$flag( |$)" "$out/vitrine.txt" || { echo "no entry for $flag"; missing=1; }
done
[ $count -ge 60 ] || { echo "only $count flags in --help"; exit 1; }
[ $missing = 0 ] && echo "man page: $count flags, each with an entry"
exit $missing
