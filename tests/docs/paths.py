#!/usr/bin/env python3
"""Every repository path named in the docs and in comments exists.

Scans README.md, docs/*.md, and the comments of the sources under src/, shaders/, scripts/, tests/,
fuzz/, cmake/ and tools/ (and the CMakeLists.txt files) for:

- paths from the repository root (`src/...`, `shaders/...`, `docs/...`, `scripts/...`, `tests/...`,
  `cmake/...`, `tools/...`, `fuzz/...`, `assets/...`): each must match a file or folder. Placeholders
  are patterns: an upper-case segment (`NAME`, `SCENE`), `<...>`, `*`, `{a,b}` and `…` match anything;
- paths from src/ (`gpu/device.h`, `host/...`) that name a file, which must exist under src/, beside
  the file that names them, or from the root;
- bare source file names (`image_io.cpp`), which must exist somewhere in the tree;
- paths no clone can follow: `../shared/...`, machine paths (`/work/...`, `/home/...`), FIELD-NOTES,
  and scripts in ignored build folders (`build-gpu/x.sh`).

Prints each one that fails, with where it is named, and exits 1 if any does.
Run: python3 tests/docs/paths.py [REPO_ROOT]
"""
import fnmatch
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))

TOP = ("src", "shaders", "docs", "scripts", "tests", "cmake", "tools", "fuzz", "assets")
# Folders that are made, downloaded or ignored, never in a clone: a path into them is not a repository path.
GENERATED = ("assets/cache/",)
SOURCE_EXT = ("cpp", "h", "hpp", "comp", "vert", "frag", "glsl", "py", "cmake", "sh")
# Files of other projects and of the system that comments name by their own name.
EXTERNAL = {
    "vulkan.h", "vulkan_core.h", "imgui.h", "imgui.cpp", "imgui_impl_vulkan.cpp", "imgui_impl_glfw.cpp",
    "stb_image.h", "stb_image_write.h", "json.hpp", "glfw3.h", "CMakeLists.txt", "CTestTestfile.cmake",
    "gtest.h", "ImfRgbaFile.h", "openexr.h", "png.h", "jpeglib.h", "sndfile.h", "lo.h", "RtAudio.h",
    "ft2build.h", "hb.h", "record.json", "settings.json", "manifest.json", "package.json", "audio.wav",
    "vk_mem_alloc.h", "shaderc.hpp", "ShaderLang.h", "GlslangToSpv.h", "spirv.hpp", "glfw3native.h",
    # Placeholders and files the build generates.
    "file.cpp", "block_layout_checks.cpp",
}
# docs/ARCHITECTURE.md's worked example adds a scene that is not in the tree: paths naming it are examples.
EXAMPLE_SCENE = "swatch"

ROOT_PATH = re.compile(r"(?<![\w./~$-])(?:\./)?((?:%s)/[\w.*{},<>…@+-]*(?:/[\w.*{},<>…@+-]*)*)" % "|".join(TOP))
SRC_DIRS = sorted(d for d in os.listdir(os.path.join(ROOT, "src")) if os.path.isdir(os.path.join(ROOT, "src", d)))
SRC_PATH = re.compile(r"(?<![\w./~$-])((?:%s)/[\w/.-]*\.(?:%s))\b" % ("|".join(SRC_DIRS), "|".join(SOURCE_EXT)))
BARE = re.compile(r"(?<![\w./~$-])([A-Za-z_][\w-]*\.(?:cpp|h|hpp|comp|vert|frag|glsl))\b(?![\w/])")
DEAD = [
    (re.compile(r"\.\./shared/\S*"), "a folder outside the repository"),
    (re.compile(r"(?<![\w.])/(?:work|home)/\S+"), "a machine path"),
    (re.compile(r"FIELD-NOTES\S*"), "notes outside the repository"),
    (re.compile(r"build-gpu/[\w.*-]+\.sh"), "a script in an ignored build folder"),
]


def tracked_files():
    out = subprocess.run(["git", "-C", ROOT, "ls-files", "-co", "--exclude-standard"], capture_output=True,
                         text=True, check=True).stdout
    files = [f for f in out.splitlines() if os.path.exists(os.path.join(ROOT, f))]
    dirs = set()
    for f in files:
        parts = f.split("/")
        for i in range(1, len(parts)):
            dirs.add("/".join(parts[:i]))
    return files, dirs


FILES, DIRS = tracked_files()
ALL = set(FILES) | DIRS
BASENAMES = {os.path.basename(f) for f in FILES}


def comments(path, text):
    """The comment text of a source file, line by line (line numbers kept); whole text for docs."""
    ext = os.path.splitext(path)[1]
    name = os.path.basename(path)
    if ext == "" and text.startswith("#!") and "python" in text.split("\n", 1)[0]:
        ext = ".py"
    lines = text.split("\n")
    if ext == ".md":
        return lines
    out = []
    if ext in (".cpp", ".h", ".hpp", ".comp", ".vert", ".frag", ".glsl", ".c", ".js", ".css"):
        in_block = False
        for line in lines:
            kept = ""
            i = 0
            while i < len(line):
                if in_block:
                    end = line.find("*/", i)
                    if end < 0:
                        kept += line[i:]
                        i = len(line)
                    else:
                        kept += line[i:end]
                        i = end + 2
                        in_block = False
                else:
                    s = line.find("//", i)
                    b = line.find("/*", i)
                    if s >= 0 and (b < 0 or s < b):
                        kept += line[s + 2:]
                        break
                    if b >= 0:
                        in_block = True
                        i = b + 2
                    else:
                        break
            out.append(kept)
        return out
    if ext in (".py", ".sh", ".cmake", ".txt", ".supp", ".sbatch", "") or name == "CMakeLists.txt":
        for line in lines:
            m = re.search(r"(?:^|\s)#(?!!)(.*)", line)
            out.append(m.group(1) if m else "")
        if ext == ".py":
            # Python docstrings: the text between triple quotes.
            in_doc = False
            for n, line in enumerate(lines):
                q = line.count('"""') + line.count("'''")
                if in_doc or q:
                    out[n] = line
                if q % 2:
                    in_doc = not in_doc
        return out
    return [""] * len(lines)


def to_glob(p):
    p = p.replace("…", "*").replace("...", "*")
    p = re.sub(r"<[^>/]*>?", "*", p)
    p = re.sub(r"\{[^}/]*\}?", "*", p)
    segs = []
    for seg in p.split("/"):
        if re.fullmatch(r"[A-Z][A-Z-]*\.md", seg):
            segs.append(seg)  # the docs' own names are upper case: docs/RELIABILITY.md is no placeholder
            continue
        # An upper-case word is a placeholder (NAME, SCENE, NAME_test.cpp, frame_N.png).
        seg = re.sub(r"(?<![a-z])[A-Z][A-Z0-9_]*[A-Z0-9](?![a-z])|(?<=_)[A-Z](?=[._]|$)", "*", seg)
        segs.append(seg)
    return "/".join(segs)


def exists(p):
    p = p.rstrip("/")
    if p in ALL:
        return True
    g = to_glob(p)
    if not any(c in g for c in "*?["):
        # "fuzz/image_exr" names the target fuzz/image_exr.cpp, "src/gpu/memory_ledger" its .h and .cpp.
        g += ".*"
    return any(fnmatch.fnmatchcase(f, g) for f in ALL)


def clean(p):
    p = re.sub(r"[.,:;)'\"`]+$", "", p)
    p = re.sub(r"/\*?$", "", p) if p.endswith("/*") else p
    return p


def check():
    missing = []
    sources = ["README.md"] + sorted(f for f in FILES if re.fullmatch(r"docs/[^/]+\.md", f))
    for f in FILES:
        top = f.split("/")[0]
        if top in ("src", "shaders", "scripts", "tests", "fuzz", "cmake", "tools") or f.endswith("CMakeLists.txt"):
            if f.startswith(("tests/golden/", "tests/fuzz-regressions/")) and not f.endswith((".txt", ".md")):
                continue
            if f == "tests/golden/RENDERED-ON.txt" or f == "tests/docs/paths.py":
                continue
            sources.append(f)
    for f in dict.fromkeys(sources):
        try:
            text = open(os.path.join(ROOT, f), encoding="utf-8").read()
        except (UnicodeDecodeError, IsADirectoryError, FileNotFoundError):
            continue
        here = os.path.dirname(f)
        for n, line in enumerate(comments(f, text), 1):
            for m in ROOT_PATH.finditer(line):
                p = clean(m.group(1))
                if p.count("/") == 0 or (p + "/").startswith(GENERATED) or p.endswith("/"):
                    continue
                if not exists(p):
                    missing.append((f, n, p, "no such path"))
            for m in SRC_PATH.finditer(line):
                p = clean(m.group(1))
                if p.split("/")[0] in TOP:
                    continue
                if not any(exists(c) for c in ("src/" + p, os.path.join(here, p), p)):
                    missing.append((f, n, p, "no such file under src/ or beside " + f))
            for m in BARE.finditer(line):
                p = m.group(1)
                if p in BASENAMES or p in EXTERNAL or re.search(r"[A-Z]{2,}", p.split(".")[0]):
                    continue
                missing.append((f, n, p, "no file of that name in the repository"))
            missing[:] = [x for x in missing if EXAMPLE_SCENE not in x[2]]
            for rx, why in DEAD:
                for m in rx.finditer(line):
                    missing.append((f, n, clean(m.group(0)), why))
    for f, n, p, why in missing:
        print(f"{f}:{n}: {p}: {why}")
    print(f"{len(missing)} dead path(s)" if missing else "every path named exists")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(check())
