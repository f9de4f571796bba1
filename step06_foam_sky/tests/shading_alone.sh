#!/usr/bin/env bash
# shading_alone.sh EXE OUT: bench_shading_repeats times the shading pass again on each timed frame
# and prints the median; drawn again on the same G-buffer it writes the same pixels, so the
# picture is the same to the byte as without it.
set -u
exe=$1 out=$2
mkdir -p "$out"
run() {  # run NAME REPEATS
  "$exe" --headless --bench --frames 4 --time 0.5 --dt 0.2 --size 96x64 --set backend=fftw \
    --set bench_shading_repeats="$2" --screenshot "$out/$1.png" > "$out/$1.log" 2>&1 ||
    { cat "$out/$1.log"; echo "FAIL: the run with bench_shading_repeats=$2 failed"; exit 1; }
}
run plain 0
run repeated 3
line=$(grep '^bench: the shading pass alone' "$out/repeated.log")
[ -n "$line" ] || { cat "$out/repeated.log"; echo "FAIL: no shading-alone line with bench_shading_repeats=3"; exit 1; }
echo "$line"
# 4 frames: the last quarter, one frame, is timed: 3 draws.
echo "$line" | grep -q 'drawn again 3 times' || { echo "FAIL: expected 3 timed draws"; exit 1; }
grep -q '^bench: the shading pass alone' "$out/plain.log" && { echo "FAIL: a shading-alone line without the setting"; exit 1; }
grep -q 'shading_alone_ms' "$out/repeated.log" || { echo "FAIL: the figure is not in the bench-csv line"; exit 1; }
cmp -s "$out/plain.png" "$out/repeated.png" || { echo "FAIL: drawing the shading again changed the picture"; exit 1; }
echo "the picture is the same to the byte with and without the repeats"
