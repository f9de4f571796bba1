#!/usr/bin/env bash
# bad_input.sh CASE STEP_EXE STEP_DIR OUT_DIR
# Runs one step with one kind of bad input and checks the contract every step keeps: a non-zero
# exit that is not a crash (1, 2 or 3; a signal would be 128+), exactly one line on stderr,
# starting with "error: " and saying what was wrong.
set -u
case_name=$1 exe=$2 step_dir=$3 out=$4
mkdir -p "$out"

# A number parameter of this step to feed bad values to: `amplitude` where the step has one (the
# issue's cases), else its first parameter with a numeric range.
number=$("$exe" --list-params | awk 'NR > 1 && $1 == "amplitude" { print $1; exit }')
[ -n "$number" ] || number=$("$exe" --list-params | awk 'NR > 1 && $3 ~ /^\[/ { print $1; exit }')

case "$case_name" in
  unknown_flag)     args=(--definitely-not-a-flag);       expect="unknown flag '--definitely-not-a-flag'" ;;
  unknown_param)    args=(--set nope=1);                   expect="unknown parameter 'nope'" ;;
  not_a_number)     args=(--set "$number=abc");            expect="parameter '$number' expects a number in \[" ;;
  nan_value)        args=(--set "$number=nan");            expect="parameter '$number' must be a finite number" ;;
  zero_size)        args=(--size 0x0);                     expect="--size expects each side in \[1, " ;;
  missing_preset)   args=(--preset "$out/no-such.preset"); expect="cannot read preset '.*no-such.preset': No such file" ;;
  malformed_preset)
    printf '%s = 1\nthis line is not an assignment\n' "$number" > "$out/malformed.preset"
    args=(--preset "$out/malformed.preset"); expect="malformed.preset:2: expected 'name = value'" ;;
  broken_shader)
    # A copy of the step's shaders with a syntax error after the first line of one the first
    # frame uses (ocean.frag where there is one).
    rm -rf "$out/shaders" && cp -r "$step_dir/shaders" "$out/shaders"
    victim="$out/shaders/ocean.frag"
    [ -f "$victim" ] || victim=$(ls "$out"/shaders/*.frag "$out"/shaders/*.vert 2>/dev/null | head -n 1)
    sed -i '2i this is not GLSL;' "$victim"
    args=(--shader-dir "$out/shaders" --frames 1 --size 64x64)
    expect="shader program '[a-z_]+( \[[^]]*\])?' does not build: .*$(basename "$victim"):2:" ;;
  broken_evolve_shader | broken_foam_shader)
    # A copy of the shaders with a compute shader broken that the chapter's own classes load by its
    # repository path (GpuOcean's evolve.comp, FoamSimulation's foam.comp): --shader-dir must
    # replace those too, or the learner's copy (./ocean exercise) would never be run.
    rm -rf "$out/shaders" && cp -r "$step_dir/shaders" "$out/shaders"
    victim="$out/shaders/$([ "$case_name" = broken_evolve_shader ] && echo evolve.comp || echo foam.comp)"
    sed -i '2i this is not GLSL;' "$victim"
    args=(--shader-dir "$out/shaders" --frames 1 --size 64x64 --set resolution=64)
    [ "$case_name" = broken_evolve_shader ] && args+=(--set backend=gpu_fft)
    expect="shader program '$(basename "$victim")' does not build: .*$(basename "$victim"):2:" ;;
  resolution_100)   args=(--set resolution=100);         expect="parameter 'resolution' expects one of 64\|128\|256\|512, got '100'" ;;
  resolution_4096)  args=(--set resolution=4096);        expect="parameter 'resolution' expects one of 64\|128\|256\|512, got '4096'" ;;
  fetch_0)          args=(--set fetch=0);                  expect="parameter 'fetch' = 0 is outside its range \[1000, " ;;
  negative_depth)   args=(--set depth=-5);                 expect="parameter 'depth' = -5 is outside its range \[1, " ;;
  *) echo "bad_input.sh: unknown case $case_name"; exit 2 ;;
esac

"$exe" --headless "${args[@]}" > "$out/$case_name.stdout" 2> "$out/$case_name.stderr"
status=$?
stderr=$(cat "$out/$case_name.stderr")
lines=$(grep -c '' "$out/$case_name.stderr")
echo "$(basename "$exe") ${args[*]}"
echo "  exit status $status; stderr ($lines line(s)): $stderr"

fail() { echo "FAIL: $*"; exit 1; }
[ "$status" -ne 0 ] || fail "bad input was accepted (exit 0)"
[ "$status" -lt 128 ] || fail "the program crashed (signal $((status - 128)))"
[ "$status" -le 3 ] || fail "unexpected exit status $status (the steps use 1, 2, 3)"
[ "$lines" -eq 1 ] || fail "expected exactly one line on stderr, got $lines"
[[ $stderr == "error: "* ]] || fail "the line does not start with 'error: '"
echo "$stderr" | grep -Eq -- "$expect" || fail "the line does not match /$expect/"
echo "ok"
