#!/usr/bin/env bash
# test_names.sh BUILD_DIR STEP...: a chapter's tests are the tests named after it. For each step,
# the tests labelled STEP (ctest -L) are exactly the tests whose name starts with "STEP." (ctest
# -R), and there is at least one of each kind every step has (smoke, bad input, catalogue); no
# test outside the chapters carries a step's label.
set -u
build=$1
shift
list() { ctest --test-dir "$build" -N "$@" | sed -n 's/^ *Test *#[0-9]*: //p' | sort; }
status=0
for step in "$@"; do
  by_label=$(list -L "^$step\$")
  by_name=$(list -R "^$step\\.")
  count=$(echo "$by_label" | grep -c .)
  if [ "$by_label" != "$by_name" ]; then
    echo "FAIL $step: ctest -L and ctest -R '^$step\\.' differ:"
    diff <(echo "$by_label") <(echo "$by_name") | sed 's/^/  /'
    status=1
  fi
  for kind in smoke bad_input.unknown_flag catalogue; do
    echo "$by_name" | grep -qx "$step\\.$kind" || echo "$by_name" | grep -q "^$step\\.$kind" ||
      { echo "FAIL $step: no $step.$kind test"; status=1; }
  done
  echo "$step: $count tests, each named $step.* and labelled $step"
done
exit $status
