#!/usr/bin/env bash
# run.sh TARGET REPO OUT_DIR SECONDS: builds tests/fuzz/TARGET.cpp with clang's libFuzzer (+ ASan,
# UBSan), replays the regressions, then fuzzes for SECONDS from the seed corpus. Exit 77 (ctest:
# skipped) with the reason printed when clang or its fuzzer runtime is missing.
set -u
target=$1 repo=$2 out=$3 seconds=$4
if ! command -v clang++ > /dev/null; then
  echo "SKIP: clang++ not found (apt-get install clang libclang-rt-14-dev)"; exit 77
fi
mkdir -p "$out/corpus"
sources=("$repo/tests/fuzz/$target.cpp" "$repo/common/text.cpp")
case "$target" in
  fuzz_params) sources+=("$repo/common/params.cpp" "$repo/common/presets.cpp" "$repo/common/file_output.cpp"
                         "$repo/common/platform.cpp") ;;
  fuzz_cli) sources+=("$repo/common/cli.cpp") ;;
  fuzz_exercise_args) sources+=("$repo/exercises/arguments.cpp") ;;
  fuzz_exercise_output) sources+=("$repo/exercises/program_output.cpp") ;;
esac
if ! clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
     -I "$repo" "${sources[@]}" -o "$out/$target" 2> "$out/build.log"; then
  if grep -q "libclang_rt.fuzzer\|fuzzer" "$out/build.log"; then
    cat "$out/build.log"; echo "SKIP: clang's libFuzzer runtime is missing (apt-get install libclang-rt-14-dev)"; exit 77
  fi
  cat "$out/build.log"; echo "FAIL: the fuzz target does not build"; exit 1
fi
regressions=("$repo/tests/fuzz/regressions/$target"/*)
if [ -e "${regressions[0]}" ]; then
  "$out/$target" "${regressions[@]}" || { echo "FAIL: a regression input crashes again"; exit 1; }
fi
cd "$out" || exit 1
# Seeds from the repository, new inputs kept in out/corpus; bounded time, no leak noise from libFuzzer.
"./$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  corpus "$repo/tests/fuzz/corpus/${target#fuzz_}" 2>&1 | tail -n 15
status=${PIPESTATUS[0]}
[ "$status" -eq 0 ] || { echo "FAIL: the fuzzer found a crash (crash-* in $out)"; exit 1; }
echo "ok: $target fuzzed for $seconds s without a crash"
