#!/usr/bin/env python3
"""The README's command-line synopsis names exactly the flags the binary declares, mode by mode.

`vitrine --help` begins with one synopsis per mode, made from the flag table (src/app/flags.cpp); the
README's "Command line" section shows the same synopsis. For each mode (the gallery, --headless,
record, encode, bench, compare, --export-preset, the listings) the two must name the same flags, and
the README's sentence on flags given twice must name exactly the repeatable ones, as --help does.

Prints every difference and exits 1 if there is any.
Run: python3 tests/docs/synopsis.py VITRINE [README.md]
"""
import os
import re
import subprocess
import sys

FLAG = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*")


def mode_of(words):
    """The mode a synopsis entry is for, from its words after `vitrine`."""
    first = words[0] if words else ""
    if first in ("bench", "record", "encode", "compare"):
        return first
    if "--headless" in words:
        return "--headless"
    if first == "--export-preset":
        return "--export-preset"
    if first.startswith("--list") or first.startswith("--help") or first == "--version":
        return "listings"
    return "gallery"


def synopses(lines):
    """{mode: set of flags} from the synopsis entries among `lines`: an entry starts with `vitrine` and
    goes on over the more indented lines below it."""
    modes = {}
    entry, indent = None, 0
    for line in lines + [""]:
        stripped = line.strip()
        depth = len(line) - len(line.lstrip())
        if entry is not None and stripped and depth > indent and not stripped.startswith("vitrine"):
            entry += " " + stripped
            continue
        if entry is not None:
            words = entry.split()[1:]
            modes.setdefault(mode_of(words), set()).update(FLAG.findall(entry))
            entry = None
        if stripped.startswith("vitrine ") and depth > 0:
            entry, indent = stripped, depth
    return modes


def repeatable(text, where):
    """The flags named in the sentence '... given twice ..., except A, B and C, which repeat'."""
    match = re.search(r"given twice[^.]*?except (.*?),? which repeat", text, re.S)
    if not match:
        sys.exit(f"{where}: no sentence 'given twice ..., except ..., which repeat'")
    return set(FLAG.findall(match.group(1)))


def main():
    vitrine = sys.argv[1]
    readme_path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "README.md")
    help_text = subprocess.run([vitrine, "--help"], capture_output=True, text=True, check=True).stdout
    readme = open(readme_path, encoding="utf-8").read()
    section = readme.split("## Command line", 1)[1].split("\n## ", 1)[0]
    # The synopsis is the section's first indented block; the examples further down are not.
    block = section.split("\n\n    vitrine", 1)[1].split("\n\n", 1)[0]
    readme_modes = synopses(("    vitrine" + block).splitlines())
    help_modes = synopses(help_text.split("\n\n", 2)[1].splitlines())

    failures = []
    for mode in sorted(set(help_modes) | set(readme_modes)):
        want, have = help_modes.get(mode, set()), readme_modes.get(mode, set())
        if want - have:
            failures.append(f"README's {mode} synopsis lacks {' '.join(sorted(want - have))}")
        if have - want:
            failures.append(f"README's {mode} synopsis names {' '.join(sorted(have - want))}, which {mode} does not take")
    if repeatable(readme, "README.md") != repeatable(help_text, "vitrine --help"):
        failures.append("README says {} repeat; the table says {}".format(
            " ".join(sorted(repeatable(readme, "README.md"))), " ".join(sorted(repeatable(help_text, "--help")))))
    for failure in failures:
        print(failure)
    if not help_modes or len(help_modes) < 8:
        failures.append(f"--help shows synopses for {sorted(help_modes)} only")
        print(failures[-1])
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
