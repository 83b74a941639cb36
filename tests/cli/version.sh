#!/usr/bin/env bash
# version.sh VITRINE SOURCE_DIR VERSION: `vitrine --version` names the project's version (CMakeLists.txt)
# and the commit the sources are at (the build rewrites it on every build).
set -u
vitrine=$1 source=$2 version=$3
line=$("$vitrine" --version) || { echo "FAIL: --version exited $?"; exit 1; }
commit=$(git -C "$source" describe --always --dirty --abbrev=12 2>/dev/null) || commit=unknown
[ "$line" = "vitrine $version (commit $commit)" ] || { echo "FAIL: '$line', expected 'vitrine $version (commit $commit)'"; exit 1; }
echo "$line"
