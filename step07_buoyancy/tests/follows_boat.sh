#!/usr/bin/env bash
# follows_boat.sh STEP07_EXE OUT_DIR: the camera keeps the boat in the view. The program, headless,
# the boat at full throttle for 6 s of frames of 0.1 s, with --export: the camera's target at the
# end (export.txt) has moved from where it started (--save-preset) as the boat moved along the
# water (trajectories.csv, from its first row to its last), within 5 cm: the first row is the boat
# after its first step, which the camera followed too (a boat starting from rest moves about 2 cm
# in it). The boat has gone more than 10 m. It follows by default (follow_boat is on from the
# start); with follow_boat=false the target has not moved at all.
set -u
exe=$1 out=$2
rm -rf "$out" && mkdir -p "$out"
flags=(--size 96x54 --time 0 --dt 0.1 --set resolution=64 --set patch_count=24 --set boat_throttle=1)
run() {  # run NAME FLAGS...: the start's parameters, then 60 frames and their export
  local name=$1
  shift
  "$exe" "${flags[@]}" "$@" --save-preset "$out/$name.preset" > "$out/$name.log" 2>&1 &&
    "$exe" --headless --frames 60 "${flags[@]}" "$@" --export "$out/$name" >> "$out/$name.log" 2>&1 ||
    { cat "$out/$name.log"; echo "FAIL: $name exited with an error"; exit 1; }
}
run following  # the default: a learner's first view follows the boat
run still --set follow_boat=false
python3 - "$out" <<'PY'
import csv, sys
out = sys.argv[1]
def values(path, sep):  # "name = value" or "name=value" lines
    found = {}
    for line in open(path):
        line = line.split("#")[0]
        if sep in line:
            name, value = line.split(sep, 1)
            found[name.strip()] = value.strip()
    return found
def target(path, sep):
    v = values(path, sep)
    return float(v["camera_target_x"]), float(v["camera_target_z"])
failed = False
for name, follows in (("following", True), ("still", False)):
    start = target(f"{out}/{name}.preset", "=")
    end = target(f"{out}/{name}/export.txt", "=")
    boat = [r for r in csv.DictReader(open(f"{out}/{name}/trajectories.csv")) if r["body"] == "2"]
    sailed = (float(boat[-1]["x"]) - float(boat[0]["x"]), float(boat[-1]["z"]) - float(boat[0]["z"]))
    moved = (end[0] - start[0], end[1] - start[1])
    want = sailed if follows else (0.0, 0.0)
    miss = max(abs(moved[0] - want[0]), abs(moved[1] - want[1]))
    far = (sailed[0] ** 2 + sailed[1] ** 2) ** 0.5
    ok = miss < 0.05 and far > 10
    failed |= not ok
    print(f"{name}: the boat sailed {far:.2f} m, the camera's target moved ({moved[0]:.3f}, {moved[1]:.3f}) m, "
          f"wanted ({want[0]:.3f}, {want[1]:.3f}){'' if ok else '  FAIL'}")
sys.exit(1 if failed else 0)
PY
