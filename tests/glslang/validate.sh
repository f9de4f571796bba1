#!/usr/bin/env bash
# Runs glslangValidator (the Khronos reference front end) on every shader of the repository
# after #include expansion. Usage: validate.sh PREPROCESS GLSLANG SHADER_LIST OUT_DIR
set -u
preprocess=$1 glslang=$2 list=$3 out=$4
mkdir -p "$out"
failures=0 count=0
while IFS= read -r shader; do
  [ -n "$shader" ] || continue
  ext=${shader##*.}
  case "$ext" in vert|frag|comp|geom|tesc|tese) ;; *) continue ;; esac
  resolved="$out/$(echo "${shader#/}" | tr '/' '_')"
  if ! table=$("$preprocess" "$shader" "$resolved"); then
    failures=$((failures + 1)); continue
  fi
  count=$((count + 1))
  if ! log=$("$glslang" -S "$ext" "$resolved" 2>&1); then
    failures=$((failures + 1))
    echo "glslang rejects $shader:"
    # "ERROR: 1:12: ..." -> file:line through the preprocessor's file table.
    echo "$log" | while IFS= read -r line; do
      if [[ $line =~ ^ERROR:\ ([0-9]+):([0-9]+):(.*)$ ]]; then
        file=$(echo "$table" | awk -v n="${BASH_REMATCH[1]}" '$1 == n { print $2 }')
        echo "  ${file:-?}:${BASH_REMATCH[2]}:${BASH_REMATCH[3]}"
      else
        echo "  $line"
      fi
    done
  fi
done < "$list"
echo "glslang: $count shaders checked, $failures rejected"
[ "$count" -gt 0 ] && [ "$failures" -eq 0 ]
