#!/usr/bin/env python3
"""The code that reads names and values from outside builds without the GPU layer.

src/live/, src/remote/ and src/app/ (live input, remote control, the command line), the fuzz targets
under fuzz/ and every Vitrine source fuzz/CMakeLists.txt compiles into them must not include anything
under src/gpu/, directly or through other headers: what they know of the scenes comes from
scenes/catalogue.h, never from scenes/scene.h (which brings gpu/device.h). Follows the quoted
#include lines as the compiler resolves them (beside the file, then src/, the repository root and
fuzz/), so it takes milliseconds, not a build. Prints each chain that reaches src/gpu/ and exits 1 if
there is one.

Run: python3 tests/build/gpu_free.py [REPO_ROOT]
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
FOLDERS = ("src/live", "src/remote", "src/app", "fuzz")
SEARCH = ("src", ".", "fuzz")
FORBIDDEN = "src/gpu/"
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def resolve(name, beside):
    for folder in (beside,) + tuple(os.path.join(ROOT, s) for s in SEARCH):
        path = os.path.normpath(os.path.join(folder, name))
        if os.path.isfile(path):
            return path
    return None  # generated, or a library's: not Vitrine's to check


def rel(path):
    return os.path.relpath(path, ROOT)


def starts():
    for folder in FOLDERS:
        for base, dirs, files in os.walk(os.path.join(ROOT, folder)):
            dirs[:] = [d for d in dirs if d not in ("seeds", "open-findings")]
            for name in sorted(files):
                if name.endswith((".cpp", ".h")):
                    yield os.path.join(base, name)
    with open(os.path.join(ROOT, "fuzz", "CMakeLists.txt"), encoding="utf-8") as cmake:
        for source in sorted(set(re.findall(r"\$\{root\}/(src/[\w/]+\.cpp)", cmake.read()))):
            yield os.path.join(ROOT, source)


def main():
    parent = {}  # every file reached, with the file that first included it
    failures = []
    for start in starts():
        if start in parent:
            continue
        parent[start] = None
        stack = [start]
        while stack:
            path = stack.pop()
            with open(path, encoding="utf-8", errors="replace") as source:
                names = INCLUDE.findall(source.read())
            for name in names:
                target = resolve(name, os.path.dirname(path))
                if target is None or target in parent:
                    continue
                parent[target] = path
                if rel(target).startswith(FORBIDDEN):
                    chain = [target]
                    while parent[chain[-1]] is not None:
                        chain.append(parent[chain[-1]])
                    failures.append(" <- ".join(rel(p) for p in chain))
                    continue
                stack.append(target)
    for failure in failures:
        print(f"gpu_free: {failure}")
    if failures:
        print(f"gpu_free: {len(failures)} GPU header(s) reached from {', '.join(FOLDERS)} and the fuzz build's sources")
        return 1
    print(f"gpu_free: {len(parent)} files reached from {', '.join(FOLDERS)} and the fuzz build's sources, none under {FORBIDDEN}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
