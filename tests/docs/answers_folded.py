#!/usr/bin/env python3
"""answers_folded.py EXERCISE_TOOL REPO: no exercise's answer is printed unfolded in its chapter's pages.

For each exercise the tool lists, `exercise prepare` writes the learner's copy, with the function
the exercise empties; the lines of the chapter's own file that the copy lacks are the answer. No
line of code among them (a comment or a line of a few characters aside) may stand in a Markdown page
of the chapter's folder outside a <details> block, where a learner reads it only by opening the
summary that says it is the answer. A code excerpt's line is compared as the page shows it, its
`//>` note aside (tests/docs/excerpts.py).

Some exercises keep their answer back altogether: a variant the learner derives with the lesson's
method, marked in the chapter's exercises.cpp by a line `// derived: ...` just above its entry
(`{"stepNN_name", N, ...`). Their answer stands in no lesson page of any chapter, not even folded,
and every chapter with exercises has at least one. Exit 0 when all of this holds.
"""
import difflib
import pathlib
import re
import subprocess
import sys
import tempfile

from lessons import lesson_pages

tool, repo = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
SHORT = 12  # characters: "return h;", "}" or "vec2 k;" alone give nothing away


def exercises():
    listed = subprocess.run([tool, "list"], capture_output=True, text=True, check=True).stdout
    for line in listed.splitlines():
        m = re.match(r"^(step\d\d_[a-z0-9_]+) (\d+) ", line)
        if m:
            yield m.group(1), m.group(2)


def answer_lines(step, number, scratch):
    """The code lines of the chapter's files that the learner's copy lacks."""
    work = pathlib.Path(scratch) / f"{step}-{number}"
    subprocess.run([tool, "prepare", step, number, str(work)], capture_output=True, text=True, check=True)
    lines = set()
    for copy in work.iterdir():
        originals = [p for p in (repo / step / "shaders" / copy.name, repo / step / copy.name) if p.is_file()]
        if not originals:
            continue
        original = originals[0].read_text(encoding="utf-8").splitlines()
        for change in difflib.ndiff(original, copy.read_text(encoding="utf-8").splitlines()):
            text = change[2:].strip()
            if change.startswith("- ") and len(text) >= SHORT and not text.startswith("//"):
                lines.add(text)
    return lines


def unfolded_lines(page):
    """(line number, text) of the page outside <details> blocks, each `//>` note cut off."""
    folded = 0
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        folded += line.count("<details") - line.count("</details>")
        if folded <= 0:
            yield number, line.split("//>")[0].strip()


def derived_exercises():
    """(step, number) of every exercise marked `// derived:` in its chapter's exercises.cpp."""
    marked = set()
    for source in sorted(repo.glob("step*/exercises.cpp")):
        lines = source.read_text(encoding="utf-8").splitlines()
        for line, following in zip(lines, lines[1:]):
            entry = re.match(r'^\s*\{"(step\d\d_[a-z0-9_]+)", (\d+),', following)
            if line.strip().startswith("// derived:") and entry:
                marked.add((entry.group(1), entry.group(2)))
    return marked


def all_lines(page):
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        yield number, line.split("//>")[0].strip()


failures, checked = [], 0
derived = derived_exercises()
listed = list(exercises())
with tempfile.TemporaryDirectory() as scratch:
    for step, number in listed:
        answer = answer_lines(step, number, scratch)
        checked += 1
        kept_back = (step, number) in derived
        pages = lesson_pages(repo) if kept_back else sorted((repo / step).glob("*.md"))
        for page in pages:
            for line_number, text in (all_lines(page) if kept_back else unfolded_lines(page)):
                if text in answer:
                    how = "derived, so shown in no lesson page" if kept_back else "unfolded"
                    failures.append(f"{page.relative_to(repo)}:{line_number}: {step} exercise {number}'s answer, "
                                    f"{how}: {text[:70]}")
for step in sorted({step for step, _ in listed}):
    if not any(s == step for s, _ in derived):
        failures.append(f"{step}: no exercise marked '// derived:' (one whose answer no lesson page gives)")
for step, number in sorted(derived - set(listed)):
    failures.append(f"{step}/exercises.cpp: '// derived:' marks exercise {number}, which `exercise list` lacks")
for failure in failures:
    print("FAIL:", failure)
print(f"answers_folded: {checked} exercises ({len(derived)} derived), {len(failures)} failures")
sys.exit(1 if failures else 0)
