#!/usr/bin/env bash
# compare_bench.sh compare|bench|sweep|against|lab|bench_all REPO BUILD_DIR OUT_DIR [SHEET_CHECK]: runs
# ./ocean compare, ./ocean bench, ./ocean bench --sweep, --baseline-bin or --lab (tools/ocean_tools.py)
# on what ctest built, then checks the form of what they wrote: a contact sheet with one non-blank
# tile per step; a bench CSV with a numeric row per step (and the FFT backends for step05 and
# step06); a sweep CSV with a row per simulating step, resolution and window; the pairs' table (and
# bench_pairs.py's arithmetic on pairs whose answer is known); a lab/ program against its chapter.
# The bench forms run tiny (96x54, 2 frames, 1 or 2 pairs): they check the tool, not the timings.
# bench_all runs the four bench forms in turn, each into its own folder under OUT_DIR.
set -u
what=$1 repo=$2 build=$3 out=$4 check=${5:-}
cd "$repo" || exit 1
steps=$(ls step[0-9][0-9]_*/CMakeLists.txt | wc -l)  # the rule ./ocean and CMake use
export OCEAN_NO_BUILD=1 OCEAN_BUILD_DIR=$build
rm -rf "$out"
case "$what" in
  compare)
    ./ocean compare --size 160x90 --out "$out" || { echo "FAIL: ./ocean compare"; exit 1; }
    "$check" "$out/contact_sheet.png" "$steps" 160x90 ;;
  bench_all)
    for form in bench sweep against lab; do
      echo "== $form"
      bash "$0" "$form" "$repo" "$build" "$out/$form" || { echo "FAIL: bench_all: $form"; exit 1; }
    done
    echo "bench_all: the table, the sweep, the pairs and the lab, each in its form" ;;
  bench)
    ./ocean bench --size 96x54 --frames 2 --out "$out" || { echo "FAIL: ./ocean bench"; exit 1; }
    [ -s "$out/bench.png" ] || { echo "FAIL: no bench.png"; exit 1; }
    awk -F, -v steps="$steps" '
      NR == 1 { if ($0 != "step,size,fps,total_ms,passes,dft_ms,gpu_fft_ms,gpu_radix2_ms,fftw_ms,simulation_ms,wave_field_ms") { print "FAIL: header " $0; bad = 1 }; next }
      {
        rows++
        if (NF != 11 || $1 !~ /^step[0-9][0-9]_/ || !($3 > 0) || !($4 > 0) || $5 !~ /=[0-9.]+/) { print "FAIL: row " $0; bad = 1 }
        if ($1 ~ /^step0[56]_/ && !($7 > 0 && $8 > 0 && $9 > 0 && $10 > 0)) { print "FAIL: no FFT backends in " $1; bad = 1 }
        if ($1 ~ /^step08_/ && !($11 > 0)) { print "FAIL: no wave field time in " $1; bad = 1 }
      }
      END {
        if (rows != steps) { print "FAIL: " rows " rows for " steps " steps"; bad = 1 }
        if (!bad) print "bench.csv: " rows " rows, one per step, all numeric"
        exit bad
      }' "$out/bench.csv" ;;
  sweep)
    # One resolution and one window, tiny, both at resolution 128 (the quickest to start: at 64,
    # backend=auto's trials of its FFTs run for seconds before it decides): each simulating step
    # (a resolution parameter) 2 runs.
    ./ocean bench --sweep --size 96x54 --frames 2 --resolutions 128 --windows 128x72 --window-resolution 128 --out "$out" ||
      { echo "FAIL: ./ocean bench --sweep"; exit 1; }
    [ -s "$out/sweep.png" ] || { echo "FAIL: no sweep.png"; exit 1; }
    simulating=0
    for exe in "$build"/step[0-9][0-9]_*/step[0-9][0-9]_*; do
      [ -x "$exe" ] && "$exe" --list-params | awk '$1 == "resolution" { found = 1 } END { exit !found }' && simulating=$((simulating + 1))
    done
    awk -F, -v runs=$((simulating * 2)) '
      NR == 1 { if ($0 != "step,size,resolution,fps,total_ms,passes,simulation_ms") { print "FAIL: header " $0; bad = 1 }; next }
      {
        rows++
        if (NF != 7 || $1 !~ /^step[0-9][0-9]_/ || $3 !~ /^(64|128|256)$/ || !($4 > 0) || !($5 > 0) || $6 !~ /=[0-9.]+/ || !($7 > 0)) { print "FAIL: row " $0; bad = 1 }
        seen[$2 " " $3]++
      }
      END {
        if (rows != runs || runs == 0) { print "FAIL: " rows " rows for " runs " runs"; bad = 1 }
        if (!("96x54 128" in seen) || !("128x72 128" in seen)) { print "FAIL: the resolution or the window is missing"; bad = 1 }
        if (!bad) print "sweep.csv: " rows " rows, every resolution and window, all numeric"
        exit bad
      }' "$out/sweep.csv" ;;
  against)
    # The arithmetic first: ratios 1.1, 0.9, 1.1 pair by pair (median 1.1, quartiles 1.0 and 1.1),
    # while the medians of the runs, 200 and 180, would say 0.9.
    mkdir -p "$out"
    printf 'bench-csv: s,1x1,1,%s,draw=%s\n' 100 90 200 200 400 360 > "$out/known_a.csv"
    printf 'bench-csv: s,1x1,1,%s,draw=%s\n' 110 99 180 180 440 396 > "$out/known_b.csv"
    known=$(python3 tools/bench_pairs.py "$out/known_a.csv" "$out/known_b.csv") || { echo "FAIL: bench_pairs.py"; exit 1; }
    echo "$known"
    echo "$known" | grep -Eq '^frame +200\.00 +180\.00 +1\.100 +\[1\.000, 1\.100\]$' || { echo "FAIL: the frame's pairs"; exit 1; }
    echo "$known" | grep -Eq '^  draw +200\.00 +180\.00 +1\.100 ' || { echo "FAIL: a pass's pairs"; exit 1; }
    # A header names a step's own figures (step05's backends); an empty one is not measured.
    printf 'bench-csv-header: step,size,fps,total_ms,passes,alone_ms,unmeasured_ms\nbench-csv: s,1x1,1,100,draw=90,%s,\n' 50 40 > "$out/known_c.csv"
    printf 'bench-csv-header: step,size,fps,total_ms,passes,alone_ms,unmeasured_ms\nbench-csv: s,1x1,1,100,draw=90,%s,\n' 45 30 > "$out/known_d.csv"
    extra=$(python3 tools/bench_pairs.py "$out/known_c.csv" "$out/known_d.csv") || { echo "FAIL: bench_pairs.py with a header"; exit 1; }
    echo "$extra"
    echo "$extra" | grep -Eq '^  alone_ms +45\.00 +37\.50 +0\.825 ' || { echo "FAIL: a figure named by the header"; exit 1; }
    echo "$extra" | grep -q 'unmeasured_ms' && { echo "FAIL: an empty figure was compared"; exit 1; }
    # Then the command, step01 against itself: 2 pairs, a frame row and its pass.
    ./ocean bench --baseline-bin "$build/step01_sine2d/step01_sine2d" --step step01_sine2d --pairs 2 --frames 2 \
      --size 96x54 --out "$out" || { echo "FAIL: ./ocean bench --baseline-bin"; exit 1; }
    [ "$(grep -c '^bench-csv: ' "$out/baseline.csv")" = 2 ] && [ "$(grep -c '^bench-csv: ' "$out/current.csv")" = 2 ] ||
      { echo "FAIL: not 2 runs each"; exit 1; }
    grep -Eq '^2 pairs' "$out/against.txt" && grep -Eq '^frame +[0-9.]+ +[0-9.]+ +[0-9]+\.[0-9]{3} ' "$out/against.txt" ||
      { echo "FAIL: against.txt"; exit 1; }
    # Flags for one side (one build, two variants), and a bad flag stops it with the step's message
    # (a single flag is given as --current-args=--flag: argparse would take --nope for a flag of its own).
    ./ocean bench --baseline-bin "$build/step01_sine2d/step01_sine2d" --step step01_sine2d --pairs 1 --frames 2 \
      --size 96x54 --out "$out/flags" --baseline-args "--time 1" --current-args "--time 2 --dt 0.5" > "$out/flags.log" 2>&1 ||
      { cat "$out/flags.log"; echo "FAIL: --baseline-args / --current-args"; exit 1; }
    grep -q -- "--time 2 --dt 0.5" "$out/flags.log" || { echo "FAIL: the current side's flags are not named"; exit 1; }
    if ./ocean bench --baseline-bin "$build/step01_sine2d/step01_sine2d" --step step01_sine2d --pairs 1 --frames 2 \
      --size 96x54 --out "$out/flags" --current-args=--nope > "$out/bad.log" 2>&1; then
      echo "FAIL: a bad flag for one side did not stop the bench"; exit 1
    fi
    grep -q "unknown flag" "$out/bad.log" || { cat "$out/bad.log"; echo "FAIL: no message for the bad flag"; exit 1; }
    tail -n 1 "$out/bad.log" | grep -q '^ocean: error: bench: .*--nope failed$' ||
      { cat "$out/bad.log"; echo "FAIL: the step's output is not followed by one error line"; exit 1; }
    echo "against.txt: 2 pairs, the frame's ratio; flags for one side; a bad one stops it" ;;
  lab)
    # lab/compute_shading against step06, the chapter it is built from: one pair, the ocean pass
    # (where the two differ) in the table; an unknown lab program is refused, the known ones named.
    mkdir -p "$out"
    ./ocean bench --lab compute_shading --pairs 1 --frames 2 --size 96x54 --out "$out" > "$out/lab.log" 2>&1 ||
      { cat "$out/lab.log"; echo "FAIL: ./ocean bench --lab compute_shading"; exit 1; }
    cat "$out/lab.log"
    grep -Eq '^step06_foam_sky at .*baseline .*/step06_foam_sky/step06_foam_sky .*current .*/lab/lab_compute_shading' "$out/lab.log" ||
      { echo "FAIL: not step06 against the lab program"; exit 1; }
    grep -Eq '^  ocean +[0-9.]+ +[0-9.]+ +[0-9]+\.[0-9]{3} ' "$out/against.txt" || { echo "FAIL: no ocean pass in against.txt"; exit 1; }
    if ./ocean bench --lab nope --out "$out" > "$out/bad.log" 2>&1; then echo "FAIL: --lab nope ran"; exit 1; fi
    grep -q "no lab program 'nope' (lab/CMakeLists.txt: compute_shading" "$out/bad.log" ||
      { cat "$out/bad.log"; echo "FAIL: no message naming the lab programs"; exit 1; }
    echo "bench --lab: compute_shading against step06, one pair; an unknown name refused" ;;
  *) echo "compare_bench.sh: compare, bench, sweep, against, lab or bench_all"; exit 2 ;;
esac
