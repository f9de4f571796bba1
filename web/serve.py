#!/usr/bin/env python3
"""serve.py REPO SITE PORT: serves the browser build on http://127.0.0.1:PORT/ (./ocean web).

SITE's pages at the root, the lessons among them (SITE/lessons/, web/render_lessons.mjs). Where a
lesson has no page there (./ocean web found no marked to render them), /lessons/ serves the
repository's step and docs folders instead (the chapters' READMEs, as plain text, and the pictures
they show); nothing else of REPO. Local only (127.0.0.1); Ctrl-C stops it."""
import functools
import http.server
import pathlib
import sys
import urllib.parse

TYPES = {".wasm": "application/wasm", ".md": "text/plain; charset=utf-8", ".js": "text/javascript"}


class Handler(http.server.SimpleHTTPRequestHandler):
    def __init__(self, *args, repo, **kwargs):
        self.repo = repo
        super().__init__(*args, **kwargs)

    def guess_type(self, path):
        return TYPES.get(pathlib.Path(path).suffix, None) or super().guess_type(path)

    def translate_path(self, path):
        clean = urllib.parse.unquote(path.split("?", 1)[0].split("#", 1)[0])
        rendered = super().translate_path(path)
        if clean.startswith("/lessons/") and not pathlib.Path(rendered).is_file():
            return str(self.lesson_file(clean[len("/lessons/"):]))
        return rendered

    def lesson_file(self, relative):
        """The repository's file at `relative` if it is one inside a step or docs folder, else a
        path that does not exist (a 404)."""
        nowhere = self.repo / "build" / "no-such-file"
        try:
            wanted = (self.repo / relative).resolve()
        except (OSError, ValueError):  # a NUL byte, a loop of links
            return nowhere
        if not wanted.is_relative_to(self.repo) or not wanted.is_file():
            return nowhere
        top = wanted.relative_to(self.repo).parts[0]
        return wanted if top.startswith("step") or top == "docs" else nowhere

    def log_message(self, format, *args):  # one quiet line per failed request only
        if len(args) > 1 and str(args[1]).startswith(("4", "5")):
            super().log_message(format, *args)


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: serve.py REPO SITE PORT")
    repo, site, port = pathlib.Path(sys.argv[1]).resolve(), sys.argv[2], int(sys.argv[3])
    handler = functools.partial(Handler, directory=site, repo=repo)
    try:
        server = http.server.ThreadingHTTPServer(("127.0.0.1", port), handler)
    except OSError as error:
        sys.exit(f"serve.py: cannot listen on 127.0.0.1:{port}: {error.strerror} (--port N picks another)")
    print(f"the chapters: http://127.0.0.1:{server.server_address[1]}/  (Ctrl-C stops)", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
