#!/usr/bin/env bash
# floats.sh STEP07_EXE OUT_DIR: the program itself, headless, on the FFTW maps it draws: 8 s of
# frames of 0.1 s with --export. In trajectories.csv every body ends afloat (its centre within
# 4 m of the mean level in a 14 m/s sea whose crests reach about 3 m) and still moves with the sea (the buoy's
# height varies over the last 3 s), the buoy has not tumbled (under 1 degree); a buoy denser than
# water (1500 kg/m^3) is 3 m down by then.
# The bodies read the sea from its maps, not from the mesh: 24 patches a side instead of 96 give
# the same trajectories to the byte, and spare llvmpipe's tessellator, which under ASan reallocates
# its buffers patch by patch (5 minutes a run on a machine whose page faults are slow; 7 s without).
set -u
exe=$1 out=$2
rm -rf "$out" && mkdir -p "$out"
run() {  # run NAME FLAGS...: the trajectories of one run
  local name=$1
  shift
  "$exe" --headless --size 96x54 --frames 80 --time 0 --dt 0.1 --set resolution=64 --set patch_count=24 \
    --export "$out/$name" "$@" \
    > "$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "FAIL: $name exited with an error"; exit 1; }
  [ -s "$out/$name/trajectories.csv" ] || { echo "FAIL: $name wrote no trajectories.csv"; exit 1; }
}
run afloat
run sinking --set buoy_density=1500
python3 - "$out/afloat/trajectories.csv" "$out/sinking/trajectories.csv" <<'PY'
import csv, math, statistics, sys
def rows(path):
    with open(path) as f:
        return [dict((k, float(v)) for k, v in r.items()) for r in csv.DictReader(f)]
afloat, sinking = rows(sys.argv[1]), rows(sys.argv[2])
end = max(r["time"] for r in afloat)
failed = False
for body, name in enumerate(["buoy", "raft", "boat"]):
    last = [r for r in afloat if r["body"] == body and r["time"] > end - 3]
    y = [r["y"] for r in last]
    print(f"{name}: last 3 s, height {min(y):.3f} .. {max(y):.3f} m")
    if not all(abs(v) < 4 for v in y):
        print(f"FAIL: the {name} is not afloat"); failed = True
buoy = [r["y"] for r in afloat if r["body"] == 0 and r["time"] > end - 3]
if statistics.pstdev(buoy) < 0.005:
    print("FAIL: the buoy does not move with the sea"); failed = True
# A uniform sphere feels no torque from buoyancy or drag through its centre: it does not tumble.
tilt = max(2 * math.degrees(math.acos(min(1.0, abs(r["qw"])))) for r in afloat if r["body"] == 0)
print(f"buoy: turned at most {tilt:.2f} degrees")
if tilt > 1:
    print("FAIL: the buoy tumbles"); failed = True
sunk = [r["y"] for r in sinking if r["body"] == 0][-1]
print(f"dense buoy: {sunk:.2f} m at the end")
if sunk > -3:
    print("FAIL: a buoy denser than water did not sink"); failed = True
sys.exit(1 if failed else 0)
PY
