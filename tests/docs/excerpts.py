#!/usr/bin/env python3
"""excerpts.py REPO: every ```glsl and ```cpp block in a chapter's lesson pages quotes its code verbatim.

A block names its file with a line `// from FILE` (relative to the step's folder: shaders/ocean.vert,
ocean_simulation.cpp, ../step05_fft/ocean_simulation.cpp; more than one may follow each other); every other
line, but the `//>` notes and blank lines, must be a line of that file (leading and trailing spaces
aside). So an excerpt, shader or host code, cannot drift from the code: change the source and this
test names the README line to update. docs/portability.md holds the chapters' excerpts for the other
GL profiles: there a block's files are relative to the chapter whose "### stepNN_name: ..." heading
it sits under. Exit 0 when all hold.
"""
import re
import pathlib
import sys

from lessons import lesson_pages

repo = pathlib.Path(sys.argv[1])
failures, checked = [], 0
pages = [(page, page.parent) for page in lesson_pages(repo)]
pages.append((repo / "docs" / "portability.md", None))
for readme, step in pages:
    in_block, source, lines = False, None, set()
    for number, line in enumerate(readme.read_text(encoding="utf-8").splitlines(), 1):
        chapter = re.match(r"^### (step\d\d_[a-z0-9_]+)", line)
        if chapter and readme.name == "portability.md":
            step = repo / chapter.group(1)
        if line.startswith("```"):
            in_block = line.strip() in ("```glsl", "```cpp") and not in_block
            source = None
            continue
        if not in_block or not line.strip() or line.lstrip().startswith("//>"):
            continue
        if line.startswith("// from "):
            if step is None:
                failures.append(f"{readme}:{number}: an excerpt outside any chapter's '### stepNN_name' section")
                continue
            path = step / line[len("// from "):].strip()
            if not path.is_file():
                failures.append(f"{readme}:{number}: no file {path}")
                source = None
            else:
                source = path
                lines = {l.strip() for l in path.read_text(encoding="utf-8").splitlines()}
            continue
        if source is None:
            failures.append(f"{readme}:{number}: a code line before any '// from FILE'")
            continue
        checked += 1
        if line.strip() not in lines:
            failures.append(f"{readme}:{number}: not in {source.relative_to(repo)}: {line.strip()}")
for failure in failures:
    print("FAIL:", failure)
print(f"excerpts: {checked} quoted lines checked, {len(failures)} not found")
if checked == 0:
    print("FAIL: no excerpts found")
sys.exit(1 if failures or checked == 0 else 0)
