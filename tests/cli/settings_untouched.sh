#!/usr/bin/env bash
# settings_untouched.sh VITRINE GOLDEN OUTDIR: headless runs neither read nor write the user's settings
# file, so goldens and benchmarks cannot depend on it: a settings file asking for kifs stage 1 leaves
# a default headless render at the final stage, and the file is not touched.
set -eu
vitrine=$1; golden=$2; out=$3
rm -rf "$out"; mkdir -p "$out/config/vitrine"
settings=$out/config/vitrine/settings.json
echo '{"version": 1, "scene": "kifs", "scenes": {"kifs": {"step": 1}}}' >"$settings"
before=$(stat -c '%Y %s' "$settings"; md5sum <"$settings")
# No --set step=9 here (the golden's own run has it): the default is 9, so the file's 1 would show if read.
XDG_CONFIG_HOME=$out/config "$vitrine" --headless --scene kifs --size 192x108 --frames 3 --time 3 --seed 7 \
  --validate --out "$out/headless.exr"
"$vitrine" compare "$golden" "$out/headless.exr"
XDG_CONFIG_HOME=$out/config "$vitrine" bench --scene kifs --size 32x18 --frames 2 --warmup 0 --json "$out/b.json"
after=$(stat -c '%Y %s' "$settings"; md5sum <"$settings")
[ "$before" = "$after" ] || { echo "the settings file changed"; exit 1; }
[ "$(ls "$out/config/vitrine")" = "settings.json" ] || { echo "something was written beside it"; ls "$out/config/vitrine"; exit 1; }
echo "settings untouched"
