#!/usr/bin/env bash
# param_ends.sh STEP_EXE OUT_DIR: every parameter of a step is accepted at both ends of the range
# --list-params prints for it, and kept there: the preset the step saves says that value back.
# (A float range declared as 0.2f was once refused at the 0.2 it printed.) Numbers' ends are the
# printed [low, high]; a choice's are its first and last; a colour's 0,0,0 and 1,1,1; text has none.
set -u
exe=$1 out=$2
mkdir -p "$out"
list=$("$exe" --list-params) || { echo "FAIL: $exe --list-params"; exit 1; }

# name<TAB>low<TAB>high for each parameter with ends: the columns start where the header's words do.
ends=$(awk '
  NR == 1 { range = index($0, "range"); meaning = index($0, "meaning"); next }
  {
    name = $1
    r = substr($0, range, meaning - range); sub(/ +$/, "", r)
    if (r ~ /^\[.*, .*\]$/) { split(substr(r, 2, length(r) - 2), e, ", "); print name "\t" e[1] "\t" e[2] }
    else if (r ~ /^r,g,b/) print name "\t0,0,0\t1,1,1"
    else if (r ~ /\|/) { n = split(r, c, "|"); print name "\t" c[1] "\t" c[n] }
  }' <<< "$list")
[ -n "$ends" ] || { echo "FAIL: no parameter with a range in --list-params"; exit 1; }

status=0 count=0
for end in low high; do
  column=$([ "$end" = low ] && echo 2 || echo 3)
  sets=()
  while IFS=$'\t' read -r name low high; do
    sets+=(--set "$name=$([ "$end" = low ] && echo "$low" || echo "$high")")
  done <<< "$ends"
  preset="$out/$end.preset"
  rm -f "$preset"
  if ! "$exe" "${sets[@]}" --save-preset "$preset" > "$out/$end.log" 2>&1; then
    echo "FAIL: the $end ends refused: $(cat "$out/$end.log")"
    # One at a time, so that every refused end is named, not only the first.
    while IFS=$'\t' read -r name low high; do
      value=$([ "$end" = low ] && echo "$low" || echo "$high")
      "$exe" --set "$name=$value" --save-preset "$out/one.preset" > /dev/null 2>&1 ||
        echo "FAIL: $name=$value (the $end end --list-params prints) is refused"
    done <<< "$ends"
    status=1
    continue
  fi
  # The saved value is the end: numbers equal to 6 significant digits, words exactly.
  while IFS=$'\t' read -r name low high; do
    want=$([ "$end" = low ] && echo "$low" || echo "$high")
    got=$(awk -v n="$name" '$1 == n && $2 == "=" { print $3; exit }' "$preset")
    count=$((count + 1))
    if [[ $want =~ ^-?[0-9.e+-]+$ ]]; then
      [ -n "$got" ] && awk -v a="$got" -v b="$want" 'BEGIN { d = a - b; if (d < 0) d = -d; s = (b < 0 ? -b : b); exit !(d <= 1e-6 * (s > 1 ? s : 1)) }' ||
        { echo "FAIL: $name set to its $end end $want is saved as '$got'"; status=1; }
    elif [ "$got" != "$want" ]; then
      echo "FAIL: $name set to its $end end $want is saved as '$got'"; status=1
    fi
  done <<< "$ends"
done
[ $status -eq 0 ] && echo "$(basename "$exe"): $count ends of $(wc -l <<< "$ends") parameters accepted and kept"
exit $status
