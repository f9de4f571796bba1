#!/usr/bin/env python3
"""links.py REPO: every relative link and image in every Markdown file of the repository resolves.

For each [text](target), ![alt](target) and <img src="target"> outside code blocks and code spans: a web address
(http, https, mailto) is left alone; any other target must name a file or folder of the repository,
relative to the Markdown file, and a #fragment must be a heading of the file it points to (GitHub's
anchors: lower case, punctuation dropped, spaces to hyphens). So no page links a file that is not
in the repository (the notes themselves are not: docs/notes.md outlines them).

It also holds the conventions a reader copies from the pages: a wave written with + t φ, or a
mode h̃₀(k) e^{+iωt}, must be the notes' slip or Tessendorf's convention, named on that line or
the one before.
Exit 0 when all hold.
"""
import pathlib
import re
import subprocess
import sys

repo = pathlib.Path(sys.argv[1]).resolve()
try:
    listed = subprocess.run(["git", "-C", str(repo), "ls-files", "--cached", "--others", "--exclude-standard", "*.md", "**/*.md"], capture_output=True, text=True,
                            check=True).stdout.split()
    pages = sorted({repo / p for p in listed})
except (subprocess.CalledProcessError, FileNotFoundError):
    pages = sorted(p for p in repo.rglob("*.md") if "build" not in p.parts and "work" not in p.parts)

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
IMG = re.compile(r"<img\s[^>]*src=\"([^\"]+)\"")  # an HTML picture (a table's thumbnail, sized)
SPAN = re.compile(r"`[^`]*`")


def anchors(page):
    found, fenced = set(), False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        if fenced or not line.startswith("#"):
            continue
        title = line.lstrip("#").strip().lower()
        slug = re.sub(r"[^\w\- ]", "", title, flags=re.UNICODE).replace(" ", "-")
        base, n = slug, 1
        while slug in found:
            slug, n = f"{base}-{n}", n + 1
        found.add(slug)
    return found


failures, checked = [], 0
for page in pages:
    fenced, previous = False, ""
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        where = f"{page.relative_to(repo)}:{number}"
        text = SPAN.sub("", line)
        for target in LINK.findall(text) + IMG.findall(text):
            if re.match(r"^(https?|mailto):", target):
                continue
            checked += 1
            path, _, fragment = target.partition("#")
            resolved = (page.parent / path).resolve() if path else page
            try:
                resolved.relative_to(repo)
            except ValueError:
                failures.append(f"{where}: {target} leaves the repository")
                continue
            if not resolved.exists():
                failures.append(f"{where}: {target} does not exist")
            elif fragment and resolved.suffix == ".md" and fragment not in anchors(resolved):
                failures.append(f"{where}: {target}: no heading '#{fragment}' there")
        context, previous = previous + " " + text, text  # a sentence may name the notes on the line before
        if page.name == "notes.md":
            context += " notes"  # the outline of the notes: every line is theirs
        if re.search(r"sin\([^)]*\+ ?t ?φ", text) and not re.search(r"notes|slip", context):
            failures.append(f"{where}: a wave with + t φ not named as the notes' slip: {line.strip()}")
        if re.search(r"h̃₀\(k\) ?e\^\{\+iωt\}", text) and not re.search(r"notes|Tessendorf|slip", context):
            failures.append(f"{where}: h̃₀(k) e^{{+iωt}} not named as the notes' or Tessendorf's: {line.strip()}")
for failure in failures:
    print("FAIL:", failure)
print(f"links: {checked} relative links in {len(pages)} Markdown files checked, {len(failures)} broken")
sys.exit(1 if failures or checked == 0 else 0)
