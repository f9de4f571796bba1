#!/usr/bin/env python3
"""serve.py REPO SITE PORT: serves the browser build on http://127.0.0.1:PORT/ (./ocean web).

SITE's pages at the root; the chapters' lessons (READMEs and the pictures they show) under
/lessons/, read from REPO: Markdown as plain text, only files inside the repository's step and
docs folders. Local only (127.0.0.1); Ctrl-C stops it."""
import functools
import http.server
import pathlib
import sys

TYPES = {".wasm": "application/wasm", ".md": "text/plain; charset=utf-8", ".js": "text/javascript"}


class Handler(http.server.SimpleHTTPRequestHandler):
    def __init__(self, *args, repo, **kwargs):
        self.repo = repo
        super().__init__(*args, **kwargs)

    def guess_type(self, path):
        return TYPES.get(pathlib.Path(path).suffix, None) or super().guess_type(path)

    def translate_path(self, path):
        clean = path.split("?", 1)[0].split("#", 1)[0]
        if clean.startswith("/lessons/"):
            wanted = (self.repo / clean[len("/lessons/"):]).resolve()
            top = wanted.relative_to(self.repo).parts[0] if wanted.is_relative_to(self.repo) else ""
            if top.startswith("step") or top == "docs":
                return str(wanted)
            return str(self.repo / "does-not-exist")  # 404: only the lessons and their pictures
        return super().translate_path(path)

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
