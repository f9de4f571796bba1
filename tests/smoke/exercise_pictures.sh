#!/usr/bin/env bash
# exercise_pictures.sh EXERCISE_EXE IMAGE_COMPARE BUILD_DIR REPO OUT_DIR [STEP [N]]
# Every GLSL exercise's untouched starter visibly changes the picture when the step runs as
# `./ocean exercise STEP N` runs it: on the work folder (--shader-dir) with the exercise's flags
# (`exercise flags STEP N`). For each exercise listed by `exercise list` (the C++ ones aside: they
# are checked, not run), the step renders twice, headless and small (160x90, 2 frames: llvmpipe is
# slow), at one fixed time: once on the starter, once with the chapter's own shader copied over the
# learner's file (the solution). The two pictures must differ beyond image_compare's default
# tolerance (RMSE 2.5/255, or over 0.5 % of the pixels off by more than 24/255): that tolerance is
# what the smoke tests accept as the same picture across drivers, so a difference beyond it is one
# the eye finds side by side, not rounding. With STEP (and N), only that step's (that exercise's).
set -u
exe=$1 compare=$2 build=$3 repo=$4 out=$5
only_step=${6:-} only_number=${7:-}
rm -rf "$out"
mkdir -p "$out"
# The test's own flags come first, the exercise's after (as ./ocean puts them before the learner's):
# a fixed clock, so that the two renders differ by the shader alone; 1/60 s a frame, as on screen.
view=(--headless --frames 2 --size 160x90 --time 1 --dt 0.0166667)
status=0 count=0
while read -r step number rest; do
  [ -n "$step" ] || continue
  [ -z "$only_step" ] || [ "$step" = "$only_step" ] || continue
  [ -z "$only_number" ] || [ "$number" = "$only_number" ] || continue
  file=$(echo "$rest" | sed 's/.*(\(.*\))$/\1/')
  case "$file" in *.cpp) continue ;; esac  # a C++ exercise: ./ocean exercise does not run the step
  count=$((count + 1))
  name="$step-$number" dir="$out/$step-$number"
  started=$SECONDS
  "$exe" prepare "$step" "$number" "$dir" > /dev/null || { echo "FAIL: prepare $name"; status=1; continue; }
  mapfile -t flags < <("$exe" flags "$step" "$number")
  step_exe="$build/$step/$step"
  if ! "$step_exe" --shader-dir "$dir" "${view[@]}" "${flags[@]}" --screenshot "$out/$name.starter.png" \
       > "$out/$name.starter.log" 2>&1; then
    echo "FAIL: $name: the step does not run on the starter (${flags[*]})"; cat "$out/$name.starter.log"; status=1; continue
  fi
  cp "$repo/$step/shaders/$file" "$dir/$file"
  if ! "$step_exe" --shader-dir "$dir" "${view[@]}" "${flags[@]}" --screenshot "$out/$name.solution.png" \
       > "$out/$name.solution.log" 2>&1; then
    echo "FAIL: $name: the step does not run on the solution (${flags[*]})"; cat "$out/$name.solution.log"; status=1; continue
  fi
  # image_compare exits 1 when the pictures differ (and prints its measures), or on an error (a
  # blank solution, sizes that differ: no measures): only the first is a difference.
  "$compare" "$out/$name.solution.png" "$out/$name.starter.png" --diff "$out/$name.diff.png" \
    > "$out/$name.compare.log" 2>&1
  compared=$?
  measures=$(grep '^image_compare: rmse' "$out/$name.compare.log")
  if [ "$compared" -eq 0 ]; then
    echo "FAIL: $name: the starter does not visibly change the picture (flags: ${flags[*]:-none}): $measures"; status=1
  elif [ -z "$measures" ]; then
    echo "FAIL: $name: the pictures could not be compared"; cat "$out/$name.compare.log"; status=1
  else
    echo "$name: the starter changes the picture (flags: ${flags[*]:-none}; $((SECONDS - started)) s): $measures"
  fi
done < <("$exe" list)
[ "$count" -gt 0 ] || { echo "FAIL: no GLSL exercises listed"; status=1; }
exit $status
