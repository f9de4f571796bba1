#!/usr/bin/env python3
"""answers_folded.py EXERCISE_TOOL REPO: no exercise's answer is printed unfolded in its chapter's pages.

For each exercise the tool lists, `exercise prepare` writes the learner's copy, with the function
the exercise empties; the lines of the chapter's own file that the copy lacks are the answer. No
line of code among them (a comment or a line of a few characters aside) may stand in a Markdown page
of the chapter's folder outside a <details> block, where a learner reads it only by opening the
summary that says it is the answer. A code excerpt's line is compared as the page shows it, its
`//>` note aside (tests/docs/excerpts.py).

Some exercises keep their answer back altogether: a variant the learner derives with the lesson's
method, `kDerived` in the chapter's exercises.cpp (`exercise list` prints its title after
"derived: "), with a line `// derived: why` just above its entry (`{"stepNN_name", N, ...`). Their
answer stands in no lesson page of any chapter, not even folded, nor in the copy any other exercise
of the chapter hands out (`exercise prepare` empties a derived function wherever it copies it), and
every chapter with exercises has at least one.

Nor may the copy the learner edits print the answer in its comments. The comments it keeps from the
chapter's file (the stub's own lines aside) are read as one text per run of comment lines, cut into
tokens: names, numbers and single symbols, so spacing does not count. The answer is the formula that
`exercise hint` prints; a piece of it is RUN tokens in a row, and the pieces the task itself prints
(`exercise prepare`'s text) are told anyway. No other piece may stand in those comments: a formula
written out, `e^{-r dt} + q (1 - e^{-r dt}) / r`, is caught whatever its spacing; a name or a
short phrase, `(dh/dx, dh/dz)`, is shorter than a piece. The rule cannot pass vacuously: it fails
when an exercise's formula has no piece beyond what its task prints, and when it misjudges the
samples below. Exit 0 when all of this holds.
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
RUN = 7  # tokens: a piece of a formula, "+ q (1 - e^"; six, ", l dDx/dz)" of a layout, can be a name
TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|\d+(?:\.\d+)?|\S")


def exercises():
    """(step, number, the file the learner edits, derived) of every exercise the tool lists."""
    listed = subprocess.run([tool, "list"], capture_output=True, text=True, check=True).stdout
    for line in listed.splitlines():
        m = re.match(r"^(step\d\d_[a-z0-9_]+) (\d+)  (derived: )?.*\(([^()]+)\)$", line)
        if m:
            yield m.group(1), m.group(2), m.group(4), bool(m.group(3))


def pieces(text):
    """Every run of RUN tokens in text."""
    tokens = TOKEN.findall(text)
    return {tuple(tokens[i:i + RUN]) for i in range(len(tokens) - RUN + 1)}


def comment_runs(lines):
    """(first line number, text) of each run of consecutive lines with a // comment, the comments joined."""
    run, first = [], 0
    for number, line in enumerate(list(lines) + [None], 1):
        if line is not None and "//" in line:
            first = first or number
            run.append(line[line.index("//") + 2:])
        elif run:
            yield first, " ".join(run)
            run, first = [], 0


def answer_pieces(hint, task):
    """The pieces of the --hint formula that the task does not print."""
    return pieces(hint) - pieces(task)


def giveaways(copy_lines, original_lines, secret):
    """(first line, the secret pieces in it) of each run of comments the copy keeps from the original."""
    kept = set(original_lines)
    lines = [line if line in kept else "" for line in copy_lines]  # the stub's lines are the task's
    for number, text in comment_runs(lines):
        found = sorted(" ".join(piece) for piece in pieces(text) & secret)
        if found:
            yield number, found


def original_of(step, copy):
    originals = [p for p in (repo / step / "shaders" / copy.name, repo / step / copy.name) if p.is_file()]
    return originals[0] if originals else None


def prepare(step, number, scratch):
    """The learner's copy, and the task `exercise prepare` prints."""
    work = pathlib.Path(scratch) / f"{step}-{number}"
    task = subprocess.run([tool, "prepare", step, number, str(work)], capture_output=True, text=True, check=True).stdout
    return work, task


def answer_lines(work, step):
    """The code lines of the chapter's files that the learner's copy lacks."""
    lines = set()
    for copy in work.iterdir():
        if original_of(step, copy) is None:
            continue
        original = original_of(step, copy).read_text(encoding="utf-8").splitlines()
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
# The self-check: step06 3's formula and task, and comments that print it or do not.
SAMPLE_HINT = "u(dt) = foam e^{-r dt} + q (1 - e^{-r dt}) / r = foam * exp(-x) + injection_rate * dt * mean_of_exp(x)"
SAMPLE_TASK = "The foam u obeys du/dt = q - r u: made at the rate q = injection_rate, fading at the rate r"
MUST_CATCH = ["// f obeys df/dt = q - r f. Held through the frame, q and r give the exact step",
              "//     f(t + dt) = f e^{-r dt} + q (1 - e^{-r dt}) / r",
              "// so the foam is the same at any frame rate."]
MUST_PASS = ["// The foam u obeys du/dt = q - r u: made at the rate q = injection_rate, fading at the",
             "// rate r, the equation solved exactly over the frame (foam.md, section 3), with mean_of_exp(x)."]
secret = answer_pieces(SAMPLE_HINT, SAMPLE_TASK)
if {n for n, _ in giveaways(MUST_CATCH, MUST_CATCH, secret)} != {1}:
    failures.append("self-check: the formula written out in a comment is not caught")
if list(giveaways(MUST_CATCH, [], secret)):
    failures.append("self-check: a stub's line (not in the chapter's file) is read as a comment the copy keeps")
if list(giveaways(MUST_PASS, MUST_PASS, secret)):
    failures.append("self-check: a comment that says only what the task prints is caught")

marked = derived_exercises()
listed = list(exercises())
derived = {(step, number) for step, number, _, is_derived in listed if is_derived}
for step, number in sorted(marked ^ derived):
    failures.append(f"{step} exercise {number}: '// derived:' in exercises.cpp and kDerived (exercise list) disagree")
copies, derived_answers = {}, {}
with tempfile.TemporaryDirectory() as scratch:
    for step, number, edited, _ in listed:
        work, task = prepare(step, number, scratch)
        copies[(step, number)] = work
        answer = answer_lines(work, step)
        if (step, number) in derived:
            derived_answers[(step, number)] = {line for line in answer if not line.startswith("//")}
            if not derived_answers[(step, number)]:
                failures.append(f"{step} exercise {number}: derived, but its copy lacks no line of code")
        checked += 1
        hint = subprocess.run([tool, "hint", step, number], capture_output=True, text=True, check=True).stdout
        secret = answer_pieces(hint.split("\n", 1)[-1], task)
        copy = work / edited
        if not secret:
            failures.append(f"{step} exercise {number}: its formula has no piece of {RUN} tokens beyond its task's")
        elif not copy.is_file() or original_of(step, copy) is None:
            failures.append(f"{step} exercise {number}: the copy lacks {edited}, or the chapter does")
        else:
            original = original_of(step, copy).read_text(encoding="utf-8").splitlines()
            for line_number, found in giveaways(copy.read_text(encoding="utf-8").splitlines(), original, secret):
                failures.append(f"{edited} (as prepared):{line_number}: {step} exercise {number}'s answer in the "
                                f"comment from this line: {len(found)} pieces of its formula, e.g. '{found[0]}'")
        kept_back = (step, number) in derived
        pages = lesson_pages(repo) if kept_back else sorted((repo / step).glob("*.md"))
        for page in pages:
            for line_number, text in (all_lines(page) if kept_back else unfolded_lines(page)):
                if text in answer:
                    how = "derived, so shown in no lesson page" if kept_back else "unfolded"
                    failures.append(f"{page.relative_to(repo)}:{line_number}: {step} exercise {number}'s answer, "
                                    f"{how}: {text[:70]}")
    # No other exercise's copy hands out a derived answer: it is emptied wherever it is copied.
    for (step, number), work in copies.items():
        for (derived_step, derived_number), secret_lines in derived_answers.items():
            if derived_step != step or derived_number == number:
                continue
            for copy in sorted(work.iterdir()):
                for line_number, line in enumerate(copy.read_text(encoding="utf-8").splitlines(), 1):
                    if line.strip() in secret_lines:
                        failures.append(f"{copy.name} (as exercise {number} of {step} prepares it):{line_number}: "
                                        f"derived exercise {derived_number}'s answer: {line.strip()[:60]}")
for step in sorted({step for step, _, _, _ in listed}):
    if not any(s == step for s, _ in derived):
        failures.append(f"{step}: no derived exercise (kDerived: one whose answer no lesson page gives)")
for step, number in sorted(marked - {(step, number) for step, number, _, _ in listed}):
    failures.append(f"{step}/exercises.cpp: '// derived:' marks exercise {number}, which `exercise list` lacks")
for failure in failures:
    print("FAIL:", failure)
print(f"answers_folded: {checked} exercises ({len(derived)} derived), {len(failures)} failures")
sys.exit(1 if failures else 0)
