#!/usr/bin/env bash
# driver_platforms.sh OCEAN OUT_DIR: ./ocean where apt is not (issue 69): on macOS without Homebrew
# it names, in one line, the Homebrew formulas and the pip package the build needs; on another
# system without apt or cmake, the packages. Each run sees only a few tools (a PATH of links in
# OUT_DIR, no apt-get, no dpkg-query, no cmake, no brew); macOS is a uname that says Darwin.
set -u
ocean=$1 out=$2
rm -rf "$out"
mkdir -p "$out/mac" "$out/other"
for tool in bash dirname basename cat head sed grep; do
  ln -s "$(command -v "$tool")" "$out/mac/$tool"
  ln -s "$(command -v "$tool")" "$out/other/$tool"
done
printf '#!%s\necho Darwin\n' "$(command -v bash)" > "$out/mac/uname"
chmod +x "$out/mac/uname"
ln -s "$(command -v uname)" "$out/other/uname"

failures=0
# expect_one_line NAME BIN_DIR PATTERN: ./ocean run's stderr is one line matching PATTERN (a glob), status 1.
expect_one_line() {
  local name=$1 bin=$2 expected=$3 errors status=0
  errors=$(env -i PATH="$bin" HOME="$out" "$bin/bash" "$ocean" run step01_sine2d --headless 2>&1 > /dev/null) || status=$?
  # shellcheck disable=SC2053  # a glob on purpose
  if [ "$status" -ne 1 ] || [[ $errors == *$'\n'* ]] || [[ $errors != $expected ]]; then
    printf 'FAIL: %s: status %s, stderr:\n%s\nexpected, alone:\n%s\n' "$name" "$status" "$errors" "$expected"
    failures=$((failures + 1))
  else
    echo "ok: $name: $errors"
  fi
}
expect_one_line "macOS without Homebrew" "$out/mac" \
  "ocean: error: install what the build needs: brew install bash cmake ninja pkg-config glfw glm fftw googletest webp && pip3 install glad2"
expect_one_line "a system without apt or cmake" "$out/other" \
  "ocean: error: not a Debian/Ubuntu system and no cmake: install what the build needs (Debian's names; *): g++ cmake *libglfw3-dev*"
[ "$failures" -eq 0 ]
