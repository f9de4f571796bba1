#!/usr/bin/env bash
# soak.sh STEP_EXE FRAMES WARMUP OUT_DIR [FLAGS...]: runs a step headless for FRAMES frames,
# sampling resident memory and live GL objects every 100 frames, and fails on growth after the
# first WARMUP frames: GL objects must stay exactly constant, memory within 8 MiB (llvmpipe keeps
# some caches of its own) and with no steady climb (the last sample within 2 MiB of the samples'
# median).
set -u
exe=$1 frames=$2 warmup=$3 out=$4
shift 4
mkdir -p "$out"
log="$out/$(basename "$exe").soak.log"
"$exe" --headless --frames "$frames" --dt 0.0333 --resource-log 100 "$@" > "$log" 2>&1
status=$?
grep -E "^resources:|^error|^GL " "$log"
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; exit 1; }
awk -v warmup="$warmup" '
  $1 == "resources:" && $3 >= warmup {
    n++; rss[n] = $5; gl[n] = $7
    if (n == 1) { rss0 = $5; gl0 = $7 }
  }
  END {
    if (n < 3) { print "FAIL: only " n " samples after warm-up"; exit 1 }
    bad = 0
    for (i = 1; i <= n; i++) {
      if (gl[i] != gl0) { print "FAIL: GL objects went from " gl0 " to " gl[i]; bad = 1 }
      if (rss[i] - rss0 > 8192) { print "FAIL: resident memory grew by " rss[i] - rss0 " kB"; bad = 1 }
    }
    # median of the samples
    for (i = 1; i <= n; i++) sorted[i] = rss[i]
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (sorted[j] < sorted[i]) { t = sorted[i]; sorted[i] = sorted[j]; sorted[j] = t }
    median = sorted[int((n + 1) / 2)]
    if (rss[n] - median > 2048) { print "FAIL: memory still climbing: last " rss[n] " kB, median " median " kB"; bad = 1 }
    printf "soak: %d samples after frame %d: GL objects %d (constant: %s), resident %d..%d kB\n", n, warmup, gl0, bad ? "no" : "yes", sorted[1], sorted[n]
    exit bad
  }' "$log"
