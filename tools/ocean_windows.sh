# ./ocean windows: every chapter cross-compiled for Windows on Debian. Sourced by ./ocean (its
# helpers: refuse, say, stop_if_dry_run, install_missing_packages, preset, build_dir, shown).
#
#   ./ocean windows [--smoke]
#
# Installs Debian's mingw-w64 (the "posix" compilers, for std::thread), fetches GLFW 3.3.8, Dear
# ImGui 1.86 and stb through apt-get source (tools/source_archives.sh: checked by their hashes),
# and builds every chapter's program as a 64-bit .exe in build/windows (cmake/WindowsCross.cmake:
# GL 4.5, no EGL: headless runs open a hidden window; no FFTW: step05's own radix 2), with
# warnings as errors. --smoke then runs each chapter's smoke test under Debian's wine, with Mesa
# through one Xvfb display: its headless picture against the same golden as on Linux
# (tests/smoke/smoke.sh, image_compare from the native build).
# What this proves and what it does not (MSVC, a real Windows driver): docs/portability.md.

WINDOWS_DIR=build/windows
WINDOWS_PACKAGES=(g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix)
WINE_PACKAGES=(wine wine64 xvfb xauth)

windows() {
  local smoke=0
  while [ $# -gt 0 ]; do
    case "$1" in
      --smoke) smoke=1; shift ;;
      *) refuse "unknown flag $(shown "$1") (--smoke)" ;;
    esac
  done
  stop_if_dry_run windows build "$WINDOWS_DIR" "$([ "$smoke" = 1 ] && echo smoke || echo no-smoke)"
  PACKAGES+=("${WINDOWS_PACKAGES[@]}")
  [ "$smoke" = 0 ] || PACKAGES+=("${WINE_PACKAGES[@]}")
  install_missing_packages
  fetch_sources glfw-3.3.8 imgui-1.86 stb-8b5f1f3
  if [ ! -f "$WINDOWS_DIR/build.ninja" ]; then
    mkdir -p "$WINDOWS_DIR"
    cmake -S . -B "$WINDOWS_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DOCEAN_WERROR=ON \
      -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64.cmake > "$WINDOWS_DIR/configure.log" 2>&1 ||
      { cat "$WINDOWS_DIR/configure.log" >&2; refuse "the Windows build's configuration failed (above)"; }
  fi
  cmake --build "$WINDOWS_DIR" || refuse "the Windows build failed (above)"
  local step missing=()
  while read -r step _; do
    [ -f "$WINDOWS_DIR/$step/$step.exe" ] || missing+=("$step")
  done < "$WINDOWS_DIR/smoke_runs.txt"
  [ ${#missing[@]} -eq 0 ] || refuse "no .exe for: ${missing[*]}"
  say "windows: every chapter built: $WINDOWS_DIR/stepNN_*/stepNN_*.exe"
  [ "$smoke" = 1 ] || return 0
  windows_smoke
}

# Each chapter's smoke test under wine, in a prefix of the build's own (created at the first run),
# all under one Xvfb display (wine's OpenGL is the X server's: Mesa's llvmpipe here).
windows_smoke() {
  local compare
  OCEAN_PRESET=$(preset) build_image_compare
  compare="$(build_dir)/tests/image_compare"
  export WINEPREFIX="$PWD/$WINDOWS_DIR/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
  xvfb-run -a -s "-screen 0 1280x720x24" bash tests/smoke/windows_smoke.sh "$WINDOWS_DIR" "$compare" ||
    refuse "a chapter's smoke test failed under wine (above)"
}

# The native build's image_compare alone (the smoke tests' judge), built if it is not yet.
build_image_compare() {
  [ -x "$(build_dir)/tests/image_compare" ] && return 0
  if [ ! -f "$(build_dir)/build.ninja" ]; then
    cmake --preset "$(preset)" > /dev/null || refuse "cmake configure failed for $(preset)"
  fi
  cmake --build --preset "$(preset)" --target image_compare || refuse "cannot build image_compare"
}
