#!/usr/bin/env bash
# installed_tree.sh BUILD_DIR SOURCE_DIR OUTDIR: the tree `cmake --install` makes (scripts/start's
# /usr/local, the package's /usr) works away from the checkout. The installed binary draws the
# calibration card like its golden with the fonts installed in PREFIX/share/vitrine, and unlike it
# once they are taken away there (so the fonts did not come from the checkout); the kiosk unit starts
# PREFIX/bin/vitrine; the desktop entry and the AppStream metadata validate.
set -u
build=$1 source=$2 out=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
prefix=$out/prefix
cmake --install "$build" --prefix "$prefix" >"$out/install.log" || fail "cmake --install: $(tail -3 "$out/install.log")"
[ -x "$prefix/bin/vitrine" ] || fail "no bin/vitrine"
ls "$prefix"/share/vitrine/fonts/*.woff2 >/dev/null 2>&1 || fail "no fonts in share/vitrine/fonts"
cd "$source"
VITRINE="$prefix/bin/vitrine" scripts/golden-cases "$out/with-fonts" calibrate >"$out/with-fonts.log" 2>&1 ||
  fail "the installed binary's card differs from its golden: $(cat "$out/with-fonts.log")"
mv "$prefix/share/vitrine/fonts" "$out/fonts-away"
VITRINE="$prefix/bin/vitrine" scripts/golden-cases "$out/without-fonts" calibrate >"$out/without-fonts.log" 2>&1 &&
  fail "the card still matches with share/vitrine/fonts gone: the installed binary read another folder"
grep -qx "ExecStart=$prefix/bin/vitrine .*" "$prefix/lib/systemd/user/vitrine-kiosk.service" ||
  fail "the kiosk unit does not start $prefix/bin/vitrine: $(grep ExecStart "$prefix/lib/systemd/user/vitrine-kiosk.service")"
desktop-file-validate "$prefix"/share/applications/*.desktop || fail "desktop-file-validate"
appstreamcli validate --no-net --pedantic "$prefix"/share/metainfo/*.metainfo.xml || fail "appstreamcli validate"
head -n 1 "$out/with-fonts.log"
echo "installed tree ok"
