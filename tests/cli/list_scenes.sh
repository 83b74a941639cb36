#!/bin/sh
# --list-scenes: one line per scene, its title starting at the same column on every line.
set -eu
"$1" --list-scenes | python3 -c '
import sys
lines = sys.stdin.read().splitlines()
assert len(lines) >= 6, lines
columns = set()
for line in lines:
    key, name, title = line.split(None, 2)
    columns.add(line.index(title, len(key) + len(name)))
assert len(columns) == 1, "titles start at columns %s:\n%s" % (sorted(columns), "\n".join(lines))
print("aligned:", len(lines), "scenes")
'
