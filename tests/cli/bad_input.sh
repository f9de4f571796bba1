#!/usr/bin/env bash
# bad_input.sh CASE STEP_EXE STEP_DIR OUT_DIR [EXPECT ARGS...]
# Runs one step with one kind of bad input and checks the contract every step keeps: a non-zero
# exit that is not a crash (1, 2 or 3; a signal would be 128+), exactly one line on stderr,
# starting with "error: " and saying what was wrong. The cases below are every step's; a chapter
# adds its own from its CMakeLists.txt (step_bad_input): EXPECT, the regular expression the line
# must match, and the ARGS that should cause it; or (step_broken_shader) a case broken_NAME_shader
# with the shader file to break and the ARGS to run with.
set -u
case_name=$1 exe=$2 step_dir=$3 out=$4
shift 4
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
  broken_shader | broken_*_shader)
    # A copy of the step's shaders with a syntax error after the first line of one: by default one
    # the first frame uses (ocean.frag where there is one); a chapter may name another, such as
    # one its own classes load by repository path (OceanSimulation's evolve.comp): --shader-dir must
    # replace those too, or the learner's copy (./ocean exercise) would never be run.
    shaders="$out/$case_name.shaders"
    rm -rf "$shaders" && cp -r "$step_dir/shaders" "$shaders"
    if [ $# -ge 1 ]; then
      victim="$shaders/$1"
      [ -f "$victim" ] || { echo "bad_input.sh: $step_dir/shaders has no $1"; exit 2; }
    else
      victim="$shaders/ocean.frag"
      [ -f "$victim" ] || victim=$(ls "$shaders"/*.frag "$shaders"/*.vert 2>/dev/null | head -n 1)
    fi
    sed -i '2i this is not GLSL;' "$victim"
    args=(--shader-dir "$shaders" --frames 1 --size 64x64 "${@:2}")
    expect="shader program '[a-z_]+( \[[^]]*\])?' does not build: .*$(basename "$victim"):2:"
    [ $# -ge 1 ] && expect="shader program '$(basename "$victim")( \[[^]]*\])?' does not build: .*$(basename "$victim"):2:" ;;
  *)
    [ $# -ge 2 ] || { echo "bad_input.sh: case $case_name needs EXPECT and ARGS"; exit 2; }
    expect=$1 args=("${@:2}") ;;
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
