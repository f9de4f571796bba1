#!/usr/bin/env bash
# window_input.sh CASE STEP_EXE [STEP FLAGS...]: drives a step's real GLFW window on a virtual X server (Xvfb) with
# xdotool, as a person would, and checks what the step does (the lines it prints when a key or the
# mouse acts, its exit). A "tap within one frame" is made certain, not left to timing: the step is
# stopped (SIGSTOP), the press and release are sent, and it goes on (SIGCONT), so both wait for the
# same frame, as a quick tap does at a low frame rate. Cases:
#   keys   F1 tapped once, then twice within one frame: three toggles (panel hidden, shown,
#          hidden); then Esc tapped within one frame closes the window: exit 0 long before
#          --frames runs out.
#   steer_push  (step07) keys; the panel hidden, a right click on the raft within one frame pushes it
#          (its "push:" line); then, after auto's backend trial, the up and right arrows held 1 s
#          (ARROWS_HELD_S: 16 under the sanitizers, whose frames take 4 to 5 s) move the boat
#          and turn it to its right (measured from its exported trajectory).
#   drag   (a 3D step) the cursor jumps across the window and the left button goes down within one
#          frame, then drags 80 px right: the yaw turns by 80 x 0.25 = 20 degrees, not by the jump.
#   plot   (step01) a drag 64 px left pans the plot by 64 / 640 of its 32 m span (x_min -4 -> -0.8),
#          then one wheel step zooms it to 0.9 of the span about the cursor.
#   next   (step01) a click on the panel's Next button ("step02_sine3d >", first row below "F1 hides
#          this panel"; the panel at its first-use place, a fresh XDG_CONFIG_HOME) hands over: the
#          process becomes step02 (exec, same pid) in a 640x360 window. The log (stdout and stderr to
#          a file) holds step01's renderer line, then step02's (lost before the streams were flushed
#          before exec); F1 in step02 hides its panel, Esc quits with 0.
#   quick_drag  (step01, or a 3D step) press, move 64 px left and release, all within one frame (as
#          at 3 to 10 frames a second): the view moves and the line of flags that starts there
#          follows (step01's "plot:", a 3D step's "camera:"), as after a drag over several frames.
#   next_paused  (step01, --paused) next, from a paused step01: step02 starts with --paused (its
#          command line, /proc/PID/cmdline: the exec keeps the pid), so its clock stays where it was.
#   stone  (step08) a left click on the sea in front of the camera (the picture's middle, right of
#          the panel), within one frame, drops a stone there: its "stone: dropped at" line (clicked
#          again while the wave field waits for the first sea); a click near the horizon, on sea
#          far beyond the field's 64 m, and one on the sky each say so and drop nothing; Esc quits.
#   split  (step04, --split) the split view's line names both variants ("left sine | right
#          exp(sin - 1)"), before F1 tapped within one frame hides the panel; Esc quits with 0.
# What reaches the step within one frame must show within FRAME_WAIT_S seconds (default 10; 30
# under the sanitizers, whose frames take 4 to 5 s: tests/cmake/window_input_tests.cmake).
# Exit 77 (ctest: skipped) with the reason printed when xvfb-run or xdotool is missing.
set -u
frame_wait=${FRAME_WAIT_S:-10}
case_name=$1
exe=$2
shift 2
if [ -z "${WINDOW_INPUT_INNER:-}" ]; then
  for tool in xvfb-run xdotool; do
    if ! command -v "$tool" > /dev/null; then
      echo "SKIP: $tool not found, the window's input was not tested (apt-get install xvfb xauth xdotool)"
      exit 77
    fi
  done
  # xvfb-run -a can hand out a display whose server is still going away (the last test's): the
  # step then cannot open it (the inner run exits 75). A fresh server, up to three times.
  for attempt in 1 2 3; do
    WINDOW_INPUT_INNER=1 xvfb-run -a -s "-screen 0 1024x768x24" bash "$0" "$case_name" "$exe" "$@"
    status=$?
    [ "$status" -eq 75 ] || exit "$status"
    echo "attempt $attempt: the X server went away before the step could open it; a fresh one"
  done
  echo "FAIL: no X server the step could open in three tries"
  exit 1
fi

out=$(mktemp -d)
pid=
# next clicks the panel where it first shows: no state remembered from an earlier run moves it.
case "$case_name" in next | next_paused) export XDG_CONFIG_HOME="$out/config" ;; esac
cleanup() {
  [ -n "$pid" ] && kill -CONT "$pid" 2> /dev/null && kill -TERM "$pid" 2> /dev/null
  rm -rf "$out"
}
trap cleanup EXIT
fail() {
  echo "--- the step's output:"
  cat "$out/log"
  echo "FAIL: $*"
  exit 1
}
# Waits up to $2 seconds for a line of the log matching $1 (grep -E); prints it.
wait_for() {
  for _ in $(seq 1 $(($2 * 10))); do
    grep -E -- "$1" "$out/log" && return 0
    sleep 0.1
  done
  return 1
}
# Waits up to $3 seconds for the $2-th log line matching $1 (grep -E); prints it.
nth_line() {
  for _ in $(seq 1 $(($3 * 10))); do
    [ "$(grep -c -E -- "$1" "$out/log")" -ge "$2" ] && grep -E -- "$1" "$out/log" | sed -n "$2p" && return 0
    sleep 0.1
  done
  return 1
}
# Runs "$@" (xdotool commands) while the step is stopped: all of it reaches one frame.
within_one_frame() {
  kill -STOP "$pid"
  "$@"
  sleep 0.2  # the X server has queued the events for the stopped client
  kill -CONT "$pid"
}
# Esc tapped within one frame: the step must close within frame_wait s and exit 0, with no GL error lines.
quit_with_esc() {
  within_one_frame xdotool key Escape
  for _ in $(seq 1 $((frame_wait * 10))); do
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
  done
  kill -0 "$pid" 2> /dev/null && fail "Esc tapped within one frame did not close the window in $frame_wait s"
  wait "$pid"
  status=$?
  pid=
  [ "$status" -eq 0 ] || fail "closed with Esc, the step exited with status $status"
  grep -q '^GL ' "$out/log" && fail "the GL reported errors or warnings"
}
# The line number of the first log line matching $1 (grep -E); empty when none.
line_of() { grep -n -E -- "$1" "$out/log" | head -n 1 | cut -d: -f1; }

extra=()
[ "$case_name" = steer_push ] && extra=(--export "$out/export")  # the bodies' trajectories, at exit
"$exe" --frames 100000 --size 640x360 "${extra[@]}" "$@" > "$out/log" 2>&1 &
pid=$!
# The window, then a frame drawn (the first frames compile the shaders).
window=
for _ in $(seq 1 300); do
  window=$(xdotool search --onlyvisible --name "^$(basename "$exe")" 2> /dev/null | head -n 1)
  [ -n "$window" ] && break
  if ! kill -0 "$pid" 2> /dev/null; then
    grep -q "GLFW cannot start" "$out/log" && exit 75  # the display, not the step: the outer run retries
    fail "the step exited before its window showed"
  fi
  sleep 0.1
done
[ -n "$window" ] || fail "no window in 30 s"
sleep 2
# The pointer on the picture, right of the panel (28 % of the window from x 10), with the keyboard focus.
xdotool mousemove --window "$window" 520 200 windowfocus --sync "$window" 2> /dev/null ||
  xdotool mousemove --window "$window" 520 200
sleep 0.5

case "$case_name" in
  keys | steer_push)
    within_one_frame xdotool key F1
    wait_for "^panel: hidden" "$frame_wait" || fail "F1 tapped within one frame did not hide the panel"
    within_one_frame xdotool key F1 key F1
    for _ in $(seq 1 $((frame_wait * 10))); do
      [ "$(grep -c '^panel: ' "$out/log")" -ge 3 ] && break
      sleep 0.1
    done
    [ "$(grep -c '^panel: ' "$out/log")" -eq 3 ] || fail "two taps of F1 within one frame did not toggle twice"
    [ "$(grep '^panel: ' "$out/log" | tail -n 1 | cut -c1-13)" = "panel: hidden" ] || fail "the panel did not end hidden"
    if [ "$case_name" = steer_push ]; then  # the raft, 26 m ahead and 5 m right of the "low" camera
      within_one_frame xdotool mousemove --window "$window" 400 190 click 3
      wait_for "^push: " "$frame_wait" || fail "a right click within one frame pushed nothing (no push line)"
      grep -q "^push: the raft" "$out/log" || fail "the right click on the raft did not push the raft"
      # Then the arrows (after the push: the boat they move would cross in front of the raft),
      # held long enough to move the boat, as a learner does. After auto's backend trial (its
      # line): its frames run the slower backend, seconds a frame under the sanitizers.
      wait_for "^backend auto at" 60 > /dev/null || fail "no backend chosen in 60 s"
      xdotool keydown Up keydown Right
      sleep "${ARROWS_HELD_S:-1}"
      xdotool keyup Up keyup Right
      sleep 0.3
    fi
    quit_with_esc
    if [ "$case_name" = steer_push ]; then
      # The boat (body 2) from its first row to its last, against the buoy (body 0), which nothing
      # steered: how far each moved, and how far the boat turned to its right (its heading's
      # angle in x-z, from the bow's direction q (1, 0, 0)), summed frame by frame (each frame's
      # change taken the short way round), so that a turn past half a circle, which a long hold
      # makes, still reads as a turn to the right.
      motion=$(awk -F, '
        NR > 1 && ($2 == 0 || $2 == 2) {
          b = $2; h = heading($6, $7, $8, $9)
          if (!(b in x0)) { x0[b] = $3; z0[b] = $5; previous[b] = h }
          x1[b] = $3; z1[b] = $5
          step = (h - previous[b]) * 180 / 3.14159265; if (step > 180) step -= 360; if (step < -180) step += 360
          turned[b] += step; previous[b] = h
        }
        function heading(w, x, y, z) { return atan2(2 * (x * z - w * y), 1 - 2 * (y * y + z * z)) }
        END {
          printf "%.2f %.2f %.1f\n", sqrt((x1[2] - x0[2])^2 + (z1[2] - z0[2])^2), sqrt((x1[0] - x0[0])^2 + (z1[0] - z0[0])^2), turned[2]
        }' "$out/export/trajectories.csv") || fail "no trajectories were exported"
      read -r boat buoy turn <<< "$motion"
      held="${ARROWS_HELD_S:-1} s"
      echo "the arrows held $held: the boat moved $boat m and turned $turn degrees; the buoy drifted $buoy m"
      awk -v b="$boat" -v d="$buoy" 'BEGIN { exit !(b >= 2 && b >= 2 * d) }' ||
        fail "the up arrow held $held moved the boat $boat m (the buoy drifted $buoy m): not visibly"
      awk -v t="$turn" 'BEGIN { exit !(t >= 8) }' || fail "the right arrow held $held turned the boat $turn degrees, not to its right"
    fi
    echo "ok: F1 toggled the panel on every tap, Esc quit"
    ;;
  drag)
    yaw0=$(grep -oE -- "--set camera_yaw=[-0-9.e]+" "$out/log" | tail -n 1)
    [ -z "$yaw0" ] || fail "a camera line before any drag"
    # The cursor far left, then in one frame: to the start of the drag and the button down there.
    xdotool mousemove --window "$window" 420 250
    sleep 0.5
    within_one_frame xdotool mousemove --window "$window" 620 250 mousedown 1
    for x in 630 640 650 660 670 680 690 700; do
      xdotool mousemove --window "$window" "$x" 250
      sleep 0.1
    done
    sleep 0.3
    xdotool mouseup 1
    line=$(wait_for "^camera: --set camera_yaw=" 10) || fail "no camera line when the drag ended"
    echo "$line"
    # Started with --set camera_yaw=0 --set camera_pitch=20 (the CTest command).
    yaw=$(echo "$line" | sed -E 's/.*camera_yaw=([-0-9.e]+).*/\1/')
    pitch=$(echo "$line" | sed -E 's/.*camera_pitch=([-0-9.e]+).*/\1/')
    awk -v y="$yaw" 'BEGIN { exit !(y > 19 && y < 21) }' ||
      fail "an 80 px drag turned the camera by $yaw degrees, not 20 (0.25 degrees a pixel, from the press)"
    awk -v p="$pitch" 'BEGIN { exit !(p > 19 && p < 21) }' || fail "a level drag changed the pitch to $pitch"
    echo "ok: the drag turned the camera by $yaw degrees for 80 px"
    ;;
  plot)
    within_one_frame xdotool mousemove --window "$window" 560 200 mousedown 1
    for x in 552 544 536 528 520 512 504 496; do
      xdotool mousemove --window "$window" "$x" 200
      sleep 0.1
    done
    sleep 0.3
    xdotool mouseup 1
    line=$(wait_for "^plot: " 10) || fail "a drag did not pan the plot (no plot line)"
    echo "$line"
    x_min=$(echo "$line" | sed -E 's/.*x_min=([-0-9.e]+).*/\1/')
    awk -v x="$x_min" 'BEGIN { exit !(x > -0.9 && x < -0.7) }' ||
      fail "a 64 px drag left moved x_min from -4 to $x_min, not -0.8"
    # One wheel step up (button 4) at x 320, the middle: the span 32 -> 28.8 about x_min + 16.
    xdotool mousemove --window "$window" 320 200
    sleep 0.3
    xdotool click 4
    for _ in $(seq 1 100); do
      [ "$(grep -c '^plot: ' "$out/log")" -ge 2 ] && break
      sleep 0.1
    done
    line=$(grep '^plot: ' "$out/log" | sed -n 2p)
    [ -n "$line" ] || fail "a wheel step did not zoom the plot (no second plot line)"
    echo "$line"
    span=$(echo "$line" | sed -E 's/.*x_span=([-0-9.e]+).*/\1/')
    x_min=$(echo "$line" | sed -E 's/.*x_min=([-0-9.e]+).*/\1/')
    awk -v s="$span" -v x="$x_min" 'BEGIN { exit !(s > 28.7 && s < 28.9 && x > 0.7 && x < 0.9) }' ||
      fail "a wheel step at the middle gave x_min $x_min, span $span, not 0.8 and 28.8"
    echo "ok: drag pans the plot, the wheel zooms it about the cursor"
    ;;
  quick_drag)
    [ -z "$(line_of "^(plot|camera): ")" ] || fail "a view line before any drag"
    within_one_frame xdotool mousemove --window "$window" 560 200 mousedown 1 mousemove --window "$window" 496 200 mouseup 1
    line=$(wait_for "^(plot|camera): " "$frame_wait") ||
      fail "a press, move and release within one frame printed no line of flags (plot: or camera:)"
    echo "$line"
    quit_with_esc
    echo "ok: a drag within one frame printed the flags that start where it left the view"
    ;;
  next | next_paused)
    [ "$(basename "$exe")" = step01_sine2d ] || fail "the next case is step01's (its Next is step02_sine3d)"
    # The Next button: panel at (10, 10), title bar 13 + 2 x 3 = 19, window padding 8, the hint
    # line 13, item spacing 4: the first row's buttons span y 54-72; "< (first)" spans x 18-89,
    # "step02_sine3d >" x 97-208 (measured on a --screenshot of 640x360). Its middle:
    xdotool mousemove --window "$window" 150 63
    sleep 0.5  # hovered for some frames before the press
    xdotool mousedown 1
    sleep 0.3
    xdotool mouseup 1
    window2=
    for _ in $(seq 1 300); do
      window2=$(xdotool search --onlyvisible --name "^step02_sine3d" 2> /dev/null | head -n 1)
      [ -n "$window2" ] && break
      kill -0 "$pid" 2> /dev/null || fail "the step exited after the click, no step02 window showed"
      sleep 0.1
    done
    [ -n "$window2" ] || fail "a click on Next (150, 63) showed no step02_sine3d window in 30 s"
    geometry=$(xdotool getwindowgeometry "$window2" | grep -oE '[0-9]+x[0-9]+$')
    [ "$geometry" = 640x360 ] || fail "step02's window is $geometry, not step01's 640x360"
    if [ "$case_name" = next_paused ]; then  # the same process, step02's command line now
      command_line=$(tr '\0' ' ' < "/proc/$pid/cmdline")
      echo "step02's command line: $command_line"
      case " $command_line " in *" --paused "*) ;; *) fail "step01 was paused, step02 did not start with --paused" ;; esac
    fi
    xdotool mousemove --window "$window2" 520 200 windowfocus --sync "$window2" 2> /dev/null ||
      xdotool mousemove --window "$window2" 520 200
    sleep 0.3
    # step02 takes input (and F1's line flushes its renderer line to the log).
    within_one_frame xdotool key F1
    wait_for "^panel: hidden" 15 || fail "F1 tapped within one frame in step02 did not hide its panel"
    quit_with_esc
    first=$(line_of "^step01_sine2d: ")
    second=$(line_of "^step02_sine3d: ")
    [ -n "$first" ] || fail "step01's renderer line is not in the log (its buffered stdout lost at the exec?)"
    [ -n "$second" ] || fail "step02's renderer line is not in the log"
    [ "$first" -lt "$second" ] || fail "step01's line (line $first) is not before step02's (line $second)"
    [ "$second" -lt "$(line_of "^panel: hidden")" ] || fail "the panel line is not step02's"
    echo "ok: Next handed over to step02 in a 640x360 window, both steps' lines in the log, Esc quit"
    ;;
  stone)
    # The default camera looks down 22 degrees, its field of view 50 degrees high: in a 640x360
    # window the horizon is at row 24. Row 200 is sea about 36 m from the camera, a few metres
    # short of the boat (42 m); row 40 is sea about 470 m out, far beyond the field; row 5 is sky.
    clicks=0
    for _ in $(seq 1 60); do
      within_one_frame xdotool mousemove --window "$window" 420 200 click 1
      clicks=$((clicks + 1))
      line=$(nth_line "^stone: " "$clicks" "$frame_wait") || fail "a left click on the sea said nothing (no stone line)"
      case "$line" in *"not made yet"*) sleep 1 ;; *) break ;; esac  # the field waits for the first sea
    done
    echo "$line"
    echo "$line" | grep -qE "^stone: dropped at \([-0-9.]+, [-0-9.]+\) m, 2 m\^4/s$" ||
      fail "a left click on the sea in front of the camera dropped no stone"
    within_one_frame xdotool mousemove --window "$window" 420 40 click 1
    line=$(nth_line "^stone: " $((clicks + 1)) "$frame_wait") && echo "$line" | grep -q "outside the wave field" ||
      fail "a click on the sea far beyond the field did not say it was outside the field"
    echo "$line"
    within_one_frame xdotool mousemove --window "$window" 420 5 click 1
    line=$(nth_line "^stone: " $((clicks + 2)) "$frame_wait") && echo "$line" | grep -q "on the sky" || fail "a click on the sky did not say it missed the sea"
    echo "$line"
    [ "$(grep -c '^stone: dropped' "$out/log")" -eq 1 ] || fail "a click off the field dropped a stone"
    quit_with_esc
    echo "ok: a click on the sea dropped a stone, clicks beyond the field and on the sky said why they did not"
    ;;
  split)
    within_one_frame xdotool key F1
    wait_for "^panel: hidden" 10 || fail "F1 tapped within one frame did not hide the panel"
    split=$(line_of "^split view: left ")
    [ -n "$split" ] || fail "no 'split view: left ... | right ...' line with --split"
    grep -F -x -q "split view: left sine | right exp(sin - 1)" "$out/log" ||
      fail "the split view's line does not name the variants sine and exp(sin - 1)"
    [ "$split" -lt "$(line_of "^panel: hidden")" ] || fail "the split view's line came only after F1"
    quit_with_esc
    echo "ok: the split view named sine | exp(sin - 1), F1 hid the panel, Esc quit"
    ;;
  *)
    echo "unknown case '$case_name'"
    exit 2
    ;;
esac
