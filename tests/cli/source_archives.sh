#!/usr/bin/env bash
# source_archives.sh REPO OUT_DIR: tools/source_archives.sh's two checks, on files made here (no
# network): a source tree whose file differs from its recorded SHA-256 is refused in one line and
# removed; and a deb822 apt source becomes the deb-src lines apt-get source is given.
set -u
repo=$1 out=$2
rm -rf "$out"
mkdir -p "$out/tools/sources" "$out/build/sources/fake-1.0"
cd "$out" || exit 1
say() { echo "say: $*"; }
refuse() { echo "refused: $*"; exit 1; }
# shellcheck source=../../tools/source_archives.sh
source "$repo/tools/source_archives.sh"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

echo 'int recorded;' > build/sources/fake-1.0/fake.h
echo "$(sha256_of build/sources/fake-1.0/fake.h)  fake.h" > tools/sources/fake-1.0.sha256
(check_source_files fake-1.0) > check.log 2>&1 || fail "the recorded file was refused: $(cat check.log)"

echo 'int changed;' > build/sources/fake-1.0/fake.h
if (check_source_files fake-1.0) > check.log 2>&1; then fail "a changed file was taken"
elif [ "$(wc -l < check.log)" -ne 1 ] || ! grep -q "^refused: fake-1.0's fake.h is not the recorded one" check.log; then
  fail "the refusal is not one line naming the file: $(cat check.log)"
elif [ -e build/sources/fake-1.0 ]; then fail "the changed tree was left for a build to use"
fi

cat > debian.sources <<'SOURCES'
# a comment
Types: deb
URIs: http://deb.example.org/debian http://mirror.example.org/debian
Suites: bookworm bookworm-updates
Components: main contrib
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb-src
URIs: http://deb.example.org/debian
Suites: bookworm
Components: main
SOURCES
expected="deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.example.org/debian bookworm main contrib
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.example.org/debian bookworm-updates main contrib
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://mirror.example.org/debian bookworm main contrib
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://mirror.example.org/debian bookworm-updates main contrib"
got=$(deb822_source_lines debian.sources)
[ "$got" = "$expected" ] || fail "deb822 to deb-src lines: got
$got"
[ "$failures" -eq 0 ] && echo "ok: a changed source file is refused and removed; deb822 sources become deb-src lines"
[ "$failures" -eq 0 ]
