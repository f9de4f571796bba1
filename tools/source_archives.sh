# The libraries some builds compile from source, fetched once into build/sources and checked before
# use. Sourced by ./ocean (its helpers: refuse, say).
#
#   Dear ImGui 1.86   the browser build, the Windows cross-build, and macOS (Homebrew has no 1.86)
#   stb (2022-09-08)  the Windows cross-build and macOS (header-only; Homebrew has none)
#   GLFW 3.3.8        the Windows cross-build (Debian's libglfw3 is Linux's)
#
# On Debian and Ubuntu each comes as Debian packs it: `apt-get source --download-only` with a
# deb-src line made for the call from the machine's own configured archive (its mirrors and proxy
# apply; no archive address is written here), in a private apt state under build/sources/apt, and
# the original tarball is held to its SHA-256. Elsewhere (macOS) ImGui and stb come from their
# upstream repositories' archives. Either way, the files the build compiles are then held one by
# one to tools/sources/NAME.sha256 (hashed from Debian's tarballs): the same release, whatever
# the road, or the build stops.

SOURCES_DIR=build/sources
# NAME  DEBIAN_PACKAGE=VERSION  ORIGINAL_TARBALL  ITS_SHA256  UPSTREAM_ARCHIVE (macOS)
SOURCE_ARCHIVES=(
  "imgui-1.86 imgui=1.86+ds-1 imgui_1.86+ds.orig.tar.xz 0dace0e8e57d298eb6e93af12dc19420cb96330832f6495c733b90aeeef11f64 https://github.com/ocornut/imgui/archive/refs/tags/v1.86.tar.gz"
  "stb-8b5f1f3 libstb=0.0~git20220908.8b5f1f3+ds-1 libstb_0.0~git20220908.8b5f1f3+ds.orig.tar.xz 6949c8ff9f86d982cff1b384f1301a731cbaf3b3fa4d1728c7b48a02386d31d8 https://github.com/nothings/stb/archive/8b5f1f3.tar.gz"
  "glfw-3.3.8 glfw3=3.3.8-1 glfw3_3.3.8.orig.tar.gz f30f42e05f11e5fc62483e513b0488d5bceeab7d9c5da0ffe2252ad81816c713 -"
)

# fetch_sources NAME...: each NAME's tree in build/sources/NAME, fetched and checked if not yet there.
fetch_sources() {
  local name entry candidate
  for name in "$@"; do
    entry=""
    for candidate in "${SOURCE_ARCHIVES[@]}"; do [ "${candidate%% *}" = "$name" ] && entry=$candidate; done
    [ -n "$entry" ] || refuse "no source archive is named $name"
    [ -f "$SOURCES_DIR/$name/.checked" ] && continue
    # shellcheck disable=SC2086  # the entry's fields, split on purpose
    fetch_source_archive $entry
  done
}

fetch_source_archive() {  # NAME PACKAGE=VERSION TARBALL SHA256 UPSTREAM
  local name=$1 package=$2 tarball=$3 sha256=$4 upstream=$5 archive
  mkdir -p "$SOURCES_DIR" || refuse "cannot make $SOURCES_DIR"
  if command -v apt-get > /dev/null; then
    archive="$SOURCES_DIR/$tarball"
    [ -f "$archive" ] || apt_source "$package"
    [ -f "$archive" ] || refuse "apt-get source $package did not bring $tarball"
    [ "$(sha256_of "$archive")" = "$sha256" ] ||
      { rm -f "$archive"; refuse "$archive is not Debian's $package (its SHA-256 differs); removed, run again"; }
  elif [ "$upstream" != - ]; then
    archive="$SOURCES_DIR/$name.upstream.tar.gz"
    if [ ! -f "$archive" ]; then
      command -v curl > /dev/null || refuse "curl is needed to fetch $name ($upstream)"
      say "downloading $name: $upstream"
      curl -fsSL -o "$archive.part" "$upstream" || { rm -f "$archive.part"; refuse "cannot download $upstream"; }
      mv "$archive.part" "$archive"
    fi
  else
    refuse "$name comes from Debian's source archive (apt-get source ${package%%=*}): build on Debian or Ubuntu"
  fi
  rm -rf "$SOURCES_DIR/$name" "$SOURCES_DIR/$name.unpacking"
  mkdir -p "$SOURCES_DIR/$name.unpacking"
  tar -xf "$archive" -C "$SOURCES_DIR/$name.unpacking" || refuse "cannot unpack $archive"
  # The tarball holds one folder (imgui-1.86/, stb-<commit>/, libstb-...+ds/): it becomes NAME.
  mv "$SOURCES_DIR/$name.unpacking"/*/ "$SOURCES_DIR/$name" && rmdir "$SOURCES_DIR/$name.unpacking" ||
    refuse "$archive does not hold one folder"
  check_source_files "$name"
  touch "$SOURCES_DIR/$name/.checked"
}

# The files a build compiles, each against its recorded SHA-256 (where a list is kept).
check_source_files() {
  local name=$1 list="tools/sources/$1.sha256" expected file
  [ -f "$list" ] || return 0
  while read -r expected file; do
    [ "$(sha256_of "$SOURCES_DIR/$name/$file")" = "$expected" ] ||
      { rm -rf "${SOURCES_DIR:?}/$name"; refuse "$name's $file is not the recorded one ($list): removed, nothing was built from it"; }
  done < "$list"
}

sha256_of() {  # sha256sum on Linux, shasum on macOS
  if command -v sha256sum > /dev/null; then sha256sum "$1" 2> /dev/null | cut -d' ' -f1
  else shasum -a 256 "$1" 2> /dev/null | cut -d' ' -f1; fi
}

# apt_source PACKAGE=VERSION: its source files into build/sources, through a private apt state whose
# only list is a deb-src line for each archive this machine already uses (so no root is needed and
# the machine's own apt lists are not touched).
apt_source() {
  local state="$SOURCES_DIR/apt" options
  rm -rf "$state"
  mkdir -p "$state/sources.list.d" "$state/lists/partial" "$state/cache/archives/partial"
  debian_source_lines > "$state/sources.list.d/ocean-sources.list" ||
    refuse "no Debian archive is configured in /etc/apt (sources.list or sources.list.d): cannot fetch $1's source"
  options=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$PWD/$state/sources.list.d"
           -o "Dir::State::Lists=$PWD/$state/lists" -o "Dir::Cache=$PWD/$state/cache" -o Debug::NoLocking=1
           -o APT::Sandbox::User=root)
  say "fetching ${1%%=*}'s source through apt-get source"
  apt-get -qq "${options[@]}" update > "$state/log" 2>&1 ||
    { cat "$state/log" >&2; refuse "apt-get update for the source lists failed (above)"; }
  (cd "$SOURCES_DIR" && apt-get -qq "${options[@]}" source --download-only "$1") >> "$state/log" 2>&1 ||
    { cat "$state/log" >&2; refuse "apt-get source $1 failed (above)"; }
  rm -rf "$state"
}

# One deb-src line per "deb" archive the machine is configured with: one-line lists (sources.list,
# *.list) and deb822 files (*.sources) alike.
debian_source_lines() {
  local file found=1
  for file in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$file" ] || continue
    sed -n 's/^[[:space:]]*deb[[:space:]]\{1,\}/deb-src /p' "$file" | grep . && found=0
  done
  for file in /etc/apt/sources.list.d/*.sources; do
    [ -f "$file" ] || continue
    deb822_source_lines "$file" | grep . && found=0
  done
  return "$found"
}

# A deb822 file's stanzas of Types: deb, as one-line deb-src entries (URIs x Suites, Components,
# and its Signed-By key).
deb822_source_lines() {
  awk '
    function flush() {
      if (types ~ /(^| )deb( |$)/ && uris != "" && suites != "") {
        n = split(uris, u, " "); m = split(suites, s, " ")
        for (i = 1; i <= n; i++) for (j = 1; j <= m; j++)
          printf "deb-src %s%s %s %s\n", (key != "" ? "[signed-by=" key "] " : ""), u[i], s[j], components
      }
      types = uris = suites = components = key = ""
    }
    /^[[:space:]]*#/ { next }
    /^[[:space:]]*$/ { flush(); next }
    { field = tolower($1); sub(/^[^:]*:[[:space:]]*/, "") }
    field == "types:" { types = $0 }  field == "uris:" { uris = $0 }  field == "suites:" { suites = $0 }
    field == "components:" { components = $0 }  field == "signed-by:" { key = $0 }
    END { flush() }' "$1"
}
