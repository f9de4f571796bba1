#!/usr/bin/env bash
# Runs glslangValidator (the Khronos reference front end) on every shader of the repository after
# #include expansion, as each profile's build compiles it (common/gl_profile.hpp): GL 4.5 core
# (every shader), GL 4.1 core (macOS; no compute shaders) and OpenGL ES 3.0 (WebGL 2; neither
# compute nor tessellation shaders). A shader that a portable profile cannot take yet is listed,
# with why, in needs_gl45.txt beside this script.
# Usage: validate.sh PREPROCESS GLSLANG SHADER_LIST OUT_DIR
set -u
preprocess=$1 glslang=$2 list=$3 out=$4
root=$(cd "$(dirname "$0")/../.." && pwd)
exceptions="$(dirname "$0")/needs_gl45.txt"
mkdir -p "$out"
failures=0
# listed PROFILE RELATIVE_PATH: whether needs_gl45.txt lists that shader for that profile.
listed() { awk -v p="$1" -v s="$2" '$1 == p && $2 == s { found = 1 } END { exit !found }' "$exceptions"; }
for profile in 450 410 300es; do
  count=0 skipped=0 expected=0
  while IFS= read -r shader; do
    [ -n "$shader" ] || continue
    ext=${shader##*.}
    case "$ext" in vert|frag|comp|geom|tesc|tese) ;; *) continue ;; esac
    if [ "$profile" != 450 ] && { [ "$ext" = comp ] || { [ "$profile" = 300es ] && [[ $ext == tes[ce] ]]; }; }; then
      skipped=$((skipped + 1)); continue
    fi
    relative=${shader#"$root"/}
    resolved="$out/$profile.$(echo "$relative" | tr '/' '_')"
    if ! table=$("$preprocess" --profile "$profile" "$shader" "$resolved"); then
      failures=$((failures + 1)); continue
    fi
    count=$((count + 1))
    if log=$("$glslang" -S "$ext" "$resolved" 2>&1); then
      if listed "$profile" "$relative"; then
        failures=$((failures + 1))
        echo "$relative now compiles at $profile: take it off tests/glslang/needs_gl45.txt"
      fi
      continue
    fi
    if listed "$profile" "$relative"; then expected=$((expected + 1)); continue; fi
    failures=$((failures + 1))
    echo "glslang rejects $relative at $profile:"
    # "ERROR: 1:12: ..." -> file:line through the preprocessor's file table.
    echo "$log" | while IFS= read -r line; do
      if [[ $line =~ ^ERROR:\ ([0-9]+):([0-9]+):(.*)$ ]]; then
        file=$(echo "$table" | awk -v n="${BASH_REMATCH[1]}" '$1 == n { print $2 }')
        echo "  ${file:-?}:${BASH_REMATCH[2]}:${BASH_REMATCH[3]}"
      else
        echo "  $line"
      fi
    done
  done < "$list"
  case "$profile" in 450) absent="" ;; 410) absent=" (compute)" ;; *) absent=" (compute, tessellation)" ;; esac
  echo "glslang $profile: $count shaders checked, $expected listed as needing 4.5, $skipped not in this profile$absent"
  [ "$count" -gt 0 ] || failures=$((failures + 1))
done
echo "glslang: $failures failure(s)"
[ "$failures" -eq 0 ]
