# ./ocean web: the chapters in a browser. Sourced by ./ocean (its helpers: refuse, say,
# stop_if_dry_run, install_missing_packages, hand_over, need_value, shown).
#
#   ./ocean web [--port N] [--no-serve]
#
# Installs what the browser build needs (Debian's emscripten and chromium; from npm, playwright-core
# for the browser tests and marked for the lessons' pages), fetches Dear ImGui 1.86's sources
# through apt-get source (tools/source_archives.sh: checked by their hashes; the native build links
# the same version), builds every
# chapter to WebAssembly in build/web/site (cmake/Web.cmake: the portable profile, without compute
# shaders), renders the lessons as HTML pages (web/render_lessons.mjs, in build/web/site/lessons),
# writes the index page (web/make_index.py) and serves it on http://127.0.0.1:PORT/ (web/serve.py;
# default 8080) until Ctrl-C. --no-serve stops after the build (CI: the tests in tests/web drive the pages then).

WEB_PACKAGES=(emscripten chromium python3)
WEB_DIR=build/web
# From npm, at the versions the tests were written on: playwright-core drives /usr/bin/chromium;
# marked turns the lessons' Markdown into HTML.
NPM_PACKAGES=(playwright-core@1.65.1 marked@18.3.0)

web() {
  local port=8080 serve=1
  while [ $# -gt 0 ]; do
    case "$1" in
      --port) need_value "a port, 1024 to 65535" "$@"
        [[ $2 =~ ^[0-9]{4,5}$ ]] && [ $((10#$2)) -ge 1024 ] && [ $((10#$2)) -le 65535 ] ||
          refuse "--port expects a whole number in [1024, 65535], got $(shown "$2")"
        port=$((10#$2)); shift 2 ;;
      --no-serve) serve=0; shift ;;
      *) refuse "unknown flag $(shown "$1") (--port N, --no-serve)" ;;
    esac
  done
  stop_if_dry_run web build "$WEB_DIR/site" "$([ "$serve" = 1 ] && echo "serve 127.0.0.1:$port" || echo no-serve)"

  PACKAGES+=("${WEB_PACKAGES[@]}")
  command -v npm > /dev/null || PACKAGES+=(npm)  # Debian's Node.js comes without it (NodeSource's has it)
  install_missing_packages
  fetch_sources imgui-1.86
  web_install_npm_packages
  # Debian's emscripten finds its JavaScript tools (acorn, terser) through NODE_PATH.
  export NODE_PATH=/usr/share/nodejs
  if [ ! -f "$WEB_DIR/build.ninja" ]; then
    emcmake cmake -S . -B "$WEB_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$WEB_DIR/configure.log" 2>&1 ||
      { cat "$WEB_DIR/configure.log" >&2; refuse "the web build's configuration failed (above)"; }
  fi
  cmake --build "$WEB_DIR" || refuse "the web build failed (above)"
  web_render_lessons
  python3 web/make_index.py . "$WEB_DIR/site" || refuse "cannot write the index page"
  [ "$serve" = 1 ] || return 0
  hand_over python3 web/serve.py . "$WEB_DIR/site" "$port"
}

# playwright-core for the browser tests (tests/web) and marked for the lessons, in
# build/web/node_modules. Without npm (or offline) the pages still build and serve; the tests then
# say they are skipped, and the lessons are served as their Markdown text.
web_install_npm_packages() {
  local package missing=()
  for package in "${NPM_PACKAGES[@]}"; do
    [ -d "$WEB_DIR/node_modules/${package%@*}" ] || missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if ! command -v npm > /dev/null; then
    say "warning: no npm: the browser tests (tests/web) will be skipped and the lessons shown as Markdown text (install Node.js's npm for them)"
    return 0
  fi
  npm install --silent --no-audit --no-fund --prefix "$WEB_DIR" "${NPM_PACKAGES[@]}" > /dev/null ||
    say "warning: npm could not install ${NPM_PACKAGES[*]}: the browser tests (tests/web) will be skipped and the lessons shown as Markdown text"
}

# The lessons as HTML pages, build/web/site/lessons (web/render_lessons.mjs). Without marked the
# old pages are removed, and web/serve.py serves the READMEs as text from the repository instead.
web_render_lessons() {
  rm -rf "$WEB_DIR/site/lessons"
  if [ ! -d "$WEB_DIR/node_modules/marked" ]; then
    say "warning: no marked in $WEB_DIR/node_modules: the lessons are served as Markdown text"
    return 0
  fi
  node web/render_lessons.mjs . "$WEB_DIR/site" "$WEB_DIR/node_modules" ||
    { rm -rf "$WEB_DIR/site/lessons"; say "warning: the lessons could not be rendered (above): they are served as Markdown text"; }
}
