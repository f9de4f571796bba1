#!/usr/bin/env python3
"""chapters_closed.py REPO: no chapter carries a later chapter's code.

A learner reads the chapters in order, and each must be whole when it is read: a later chapter
wraps or composes the earlier parts, never the other way round. So a file in a chapter's folder
`stepNN_*` (its code, shaders, tests, build files and pages) never names a later chapter:
- in every file that is not a page (.cpp, .hpp, .glsl, CMakeLists.txt, .sh, .py, ...), no
  `stepMM` with MM > NN at all: no include, no target, no path, and no comment such as "kept for
  step08" either, since such a comment is the sign of code kept for a later chapter;
- in a lesson page (.md), no `stepMM_...` folder: no link or path into a later chapter. A page
  may say in words what a later chapter brings ("step03 computes the normals exactly"), the way a
  book's chapter ends by naming the next one; it never sends the learner there to understand
  this one.
A failure prints `FAIL: FILE:LINE names stepMM, a later chapter: TEXT` and the test exits 1. It
cannot pass vacuously: it fails when it finds no chapter folder, and when it misjudges its
samples.
"""
import re
import sys
from pathlib import Path

CHAPTER = re.compile(r"^step(\d\d)_")
ANY_MENTION = re.compile(r"step(\d\d)")        # in code: step08, step08's, step08_wakes/...
FOLDER = re.compile(r"step(\d\d)_[a-z0-9_]+")  # in pages: a later chapter's folder
BINARY = {".png", ".jpg", ".pfm", ".exr", ".hdr", ".bin", ".ico"}


def later_mentions(chapter: int, name: str, text: str):
    """(line number, MM, line) for each mention in `text` of a chapter after `chapter`."""
    pattern = FOLDER if name.endswith(".md") else ANY_MENTION
    for number, line in enumerate(text.splitlines(), 1):
        for match in pattern.finditer(line):
            if int(match.group(1)) > chapter:
                yield number, int(match.group(1)), line.strip()


failures = []
# Self-check: what must be caught and what must pass.
SAMPLES = [
    (6, "sea.hpp", "// Another wind for step08's breeze", 1),
    (6, "CMakeLists.txt", "# The program's parts: step07 composes them.", 1),
    (1, "gpu.cpp", '#include "step02_sine3d/waves.hpp"', 1),
    (8, "README.md", "[the next chapter](../step09_radiation/README.md)", 1),
    (8, "README.md", "step09 takes the energy the buoy radiates", 0),
    (6, "sea.hpp", "// step05's simulation, four cascades of it; step06's own", 0),
    (7, "README.md", "[step06's sea](../step06_foam_sky/sea.md)", 0),
]
for chapter, name, text, expected in SAMPLES:
    found = len(list(later_mentions(chapter, name, text)))
    if found != expected:
        failures.append(f"self-check: {text!r} in step{chapter:02d}'s {name}: {found} mentions, not {expected}")

repo = Path(sys.argv[1])
chapters = sorted(p for p in repo.iterdir() if p.is_dir() and CHAPTER.match(p.name))
files = 0
for folder in chapters:
    chapter = int(CHAPTER.match(folder.name).group(1))
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or path.suffix.lower() in BINARY:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        files += 1
        for number, later, line in later_mentions(chapter, path.name, text):
            failures.append(f"{path.relative_to(repo)}:{number} names step{later:02d}, a later chapter: {line[:120]}")
if not chapters:
    failures.append("no chapter folder (stepNN_*) found")
print(f"{len(chapters)} chapters, {files} files read")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
