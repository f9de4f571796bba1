"""The pages of the chapters' lessons, shared by the docs tests.

A chapter's lesson is its README.md and any other page in its folder (step06's sea.md, foam.md, ...),
all but how_we_know.md, which is where its test figures and history live. step_template's pages
count too: a new chapter starts from them.
"""
import pathlib


def lesson_pages(repo):
    """Every chapter's lesson pages, README first within each chapter."""
    repo = pathlib.Path(repo)
    pages = []
    for step in sorted(p for p in repo.glob("step*") if p.is_dir()):
        others = sorted(p for p in step.glob("*.md") if p.name not in ("README.md", "how_we_know.md"))
        pages += [p for p in [step / "README.md"] if p.is_file()] + others
    return pages


def prose_lines(text):
    """The lines a learner reads as prose: not blank, not inside a ``` block, not a heading, an
    image or a bare HTML tag (<details>, </summary>)."""
    count, in_block = 0, False
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("```"):
            in_block = not in_block
            continue
        if in_block or not stripped or stripped.startswith(("#", "![")):
            continue
        if stripped.startswith("<") and stripped.endswith(">") and len(stripped) < 40:
            continue
        count += 1
    return count
