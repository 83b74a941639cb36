#!/bin/sh
# ISF generators as pieces from the command line: --isf lists and renders one, its inputs take --set
# with their ranges, a pieces folder adds its files (a refused one listed, and refused with its
# reason when run), a filter is no piece, and every hostile file is refused with its file and line.
# Usage: isf_pieces.sh VITRINE TESTS_ISF_DIR OUT_DIR
set -eu
vitrine=$1 isf=$2 out=$3
rm -rf "$out" && mkdir -p "$out/data/vitrine/pieces" "$out/config"
export XDG_DATA_HOME="$out/data" XDG_CONFIG_HOME="$out/config"

"$vitrine" --isf "$isf/every_input.fs" --list-scenes >"$out/list.txt"
tail -n 1 "$out/list.txt" | grep -q '^-  every_input  every_input$' || { cat "$out/list.txt"; exit 1; }

"$vitrine" --headless --isf "$isf/drag_point.fs" --set radius=0.3 --size 64x36 --out "$out/spot.png" >/dev/null
test -s "$out/spot.png"
if "$vitrine" --headless --isf "$isf/drag_point.fs" --set radius=7 --size 64x36 --out "$out/no.png" 2>"$out/err.txt"; then
  echo "radius=7 was taken"; exit 1
fi
grep -q 'radius=7: expected a number from 0.01 to 0.5' "$out/err.txt" || { cat "$out/err.txt"; exit 1; }

# A filter is not a scene.
if "$vitrine" --headless --isf "$isf/gles_style.fs" --out "$out/no.png" 2>"$out/err.txt"; then exit 1; fi
grep -q 'gles_style.fs:1: is a filter, not a generator' "$out/err.txt" || { cat "$out/err.txt"; exit 1; }

# The error of a file that does not compile is at the author's line.
if "$vitrine" --headless --isf "$isf/line12_error.fs" --size 64x36 --out "$out/no.png" 2>"$out/err.txt"; then exit 1; fi
grep -q "line12_error.fs:12: error: 'brightnes' : undeclared identifier" "$out/err.txt" || { cat "$out/err.txt"; exit 1; }

# Every hostile file: refused, naming itself and a line, and no crash (exit 1, not a signal).
for file in "$isf"/hostile/*.fs; do
  status=0
  "$vitrine" --headless --isf "$file" --size 64x36 --out "$out/no.png" 2>"$out/err.txt" || status=$?
  [ "$status" -eq 1 ] || { echo "$file: exit $status"; cat "$out/err.txt"; exit 1; }
  grep -q "^vitrine: .*$(basename "$file"):[0-9]*: " "$out/err.txt" || { echo "$file:"; cat "$out/err.txt"; exit 1; }
done

# The user's pieces folder: a good file and a broken one, both listed; the broken one says why.
cp "$isf/gl3_style.fs" "$out/data/vitrine/pieces/cells.fs"
printf '/*{ "ISFVSN": "2", "INPUTS": [ }*/\nvoid main() {}\n' >"$out/data/vitrine/pieces/broken.fs"
"$vitrine" --list-scenes >"$out/list.txt"
grep -q '^-  broken  *broken$' "$out/list.txt" && grep -q '^-  cells  *cells$' "$out/list.txt" || { cat "$out/list.txt"; exit 1; }
"$vitrine" --headless --scene cells --set cells=3 --size 64x36 --out "$out/cells.png" >/dev/null
if "$vitrine" --headless --scene broken --size 64x36 --out "$out/no.png" 2>"$out/err.txt"; then exit 1; fi
grep -q 'broken.fs:1: ' "$out/err.txt" || { cat "$out/err.txt"; exit 1; }
echo "isf pieces: listed, rendered, refused as they should be"
