#!/usr/bin/env python3
"""lesson_length.py REPO: every lesson page is one a learner reads in one sitting.

A chapter's lesson may have several pages (lessons.py lists them: step*/*.md but how_we_know.md);
each holds at most PROSE_LIMIT lines of prose (lessons.prose_lines: lines not blank, not in a code
block, not a heading, an image or a bare HTML tag). A page over it prints `FAIL: PAGE: N lines of
prose (at most 350): split it into pages or move what is not the lesson out`, and the test exits 1.
It cannot pass vacuously: it fails when it finds no page, or when its count misjudges the samples.
"""
import sys

from lessons import lesson_pages, prose_lines

PROSE_LIMIT = 350

failures = []
SAMPLE = "# A title\n\nOne line.\nTwo lines.\n\n```cpp\nint code;\n```\n![a picture](p.png)\n<details>\n| a | table |\n"
if prose_lines(SAMPLE) != 3:
    failures.append(f"self-check: the sample counts {prose_lines(SAMPLE)} lines of prose, not 3")

pages = lesson_pages(sys.argv[1])
for page in pages:
    count = prose_lines(page.read_text(encoding="utf-8"))
    print(f"{page.parent.name}/{page.name}: {count}")
    if count > PROSE_LIMIT:
        failures.append(f"{page.parent.name}/{page.name}: {count} lines of prose (at most {PROSE_LIMIT}): "
                        "split it into pages or move what is not the lesson out")
if not pages:
    failures.append("no lesson page (step*/README.md) found")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
