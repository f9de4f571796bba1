#!/usr/bin/env python3
"""make_index.py REPO SITE: the browser build's front page, SITE/index.html (./ocean web).

Every chapter in order, each with its title and the notes' sections it follows (the first and
third lines of its README), a link to its page where the web build has one, else what it needs,
and a link to its lesson: its page (web/render_lessons.mjs) or, where there is none, its README as
text (served from the repository by web/serve.py under /lessons/). The
licences of what the pages hold are copied beside them: the project's and Dear ImGui's."""
import html
import pathlib
import re
import shutil
import sys


def markdown_to_text(line):
    """A README line as plain text: links keep their words, `code` and emphasis lose their marks."""
    line = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", line)
    return line.replace("`", "").replace("*", "").strip()


def chapter_row(step, readme, has_page, lesson):
    lines = readme.read_text(encoding="utf-8").splitlines() if readme.is_file() else []
    title = markdown_to_text(lines[0].lstrip("# ")) if lines else step
    title = title.removeprefix(step).lstrip(" —-")
    notes = markdown_to_text(lines[2]) if len(lines) > 2 else ""
    if has_page:
        open_link = f'<a href="{step}.html">open</a>'
    else:
        open_link = ('<span class="needs">not in the browser build: '
                     f'<code>./ocean run {step}</code> natively</span>')
    return (f"<tr><td><b>{html.escape(step)}</b><br>{html.escape(title)}"
            f'<div class="notes">{html.escape(notes)}</div></td>'
            f'<td>{open_link}</td><td><a href="{lesson}">lesson</a></td></tr>')


def lesson_link(site, step):
    """The chapter's lesson: its rendered page where the build made one, else its Markdown text."""
    page = f"lessons/{step}/README.html"
    return page if (site / page).is_file() else f"lessons/{step}/README.md"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: make_index.py REPO SITE")
    repo, site = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    steps = sorted(p.parent.name for p in repo.glob("step[0-9][0-9]_*/CMakeLists.txt"))
    rows = "\n".join(chapter_row(s, repo / s / "README.md", (site / f"{s}.html").is_file(), lesson_link(site, s))
                     for s in steps)
    shutil.copyfile(repo / "LICENSE", site / "LICENSE.txt")
    if not (site / "imgui-LICENSE.txt").is_file():  # cmake/Web.cmake copies it there
        sys.exit("make_index.py: no Dear ImGui licence in SITE (build the pages first)")
    (site / "index.html").write_text(f"""<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<link rel="icon" href="data:,">
<title>Sin waves into water · in the browser</title>
<style>
  body {{ margin: 2em auto; max-width: 52em; background: #111418; color: #c8d0d8; font: 15px/1.5 sans-serif; }}
  a {{ color: #7fb8ff; }}
  table {{ width: 100%; border-collapse: collapse; }}
  td:first-child {{ width: 75%; }}
  td {{ padding: 0.5em 1em 0.5em 0; vertical-align: top; border-bottom: 1px solid #2a3038; }}
  .notes, .needs {{ opacity: 0.7; font-size: 0.9em; }}
</style>
</head>
<body>
<h1>Sin waves into water</h1>
<p>Real-time ocean rendering, one chapter at a time: each page is the chapter's program built to
WebAssembly, drawing with WebGL 2. In the 3D chapters a drag orbits the camera and the wheel zooms; F1 hides the panel. The page's
address sets parameters: <a href="step02_sine3d.html?amplitude=2.5">step02_sine3d.html?amplitude=2.5</a>
(each chapter's README lists them).</p>
<table>
{rows}
</table>
<p class="notes">The pages are under the project's licence (<a href="LICENSE.txt">MIT</a>) and
Dear ImGui's (<a href="imgui-LICENSE.txt">MIT</a>); they hold no GPL code.</p>
</body>
</html>
""", encoding="utf-8")
    print(f"make_index.py: {site / 'index.html'}: {len(steps)} chapters")


if __name__ == "__main__":
    main()
