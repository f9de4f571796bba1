#!/usr/bin/env python3
"""ocean_tools.py COMMAND [ARGS]: the long commands of ./ocean, which forwards to it after building.

    bench       every step's --bench as one table; or --sweep, --against REV / --baseline-bin PATH,
                --lab NAME (one measurement at a time)
    compare     every step (or those named) headless with the same camera and time, on one contact sheet
    figures     the teaching figures, drawn from the chapters' own code by gnuplot
    animations  each step (or those named) in motion, one animated WebP each
    gallery     docs/gallery/: step06's presets from two cameras and a backlit view

Each has its own --help. It runs from the repository's root (relative paths are taken from there)
on the programs of OCEAN_BUILD_DIR (default build/PRESET, PRESET from OCEAN_PRESET, or ci when
CI=true, else release): it never builds them (./ocean does). OCEAN_DRY_RUN=1: check the arguments,
print "ocean: dry run: ..." and stop. Every failure is one line "ocean: error: COMMAND: ..." on
stderr and exit status 1; when a program it ran failed, that program's output comes first.
Standard library only (Python 3.11).
"""
import argparse
import contextlib
import io
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
sys.dont_write_bytecode = True  # no __pycache__ left in tools/
import bench_pairs  # noqa: E402  (beside this file: the pairs' ratio statistics)

MAX_IMAGE_SIDE = 16384  # common/cli.hpp kMaxImageSide: the steps refuse larger
CAMERAS = ["overview", "deck", "low", "top"]
RESOLUTIONS = ["64", "128", "256", "512"]
ANIMATION_FPS = 15
ANIMATION_MAX_BYTES = 2 * 1024 * 1024  # small enough for a repository
# What a step's animation shows beyond its default view: step10's is a dive, from 1.2 m above a
# moderate sea (8 m/s wind) to 1.8 m below it at 0.75 m/s, through the waterline.
ANIMATION_FLAGS = {
    "step10_underwater": ["--set", "wind_speed=8", "--set", "camera_target_y=1.2", "--set", "camera_distance=0.5",
                          "--set", "camera_pitch=6", "--set", "dive_speed=0.75"],
}


class Failure(Exception):
    """A refusal or a failed program: main prints it as the one error line."""


def shown(text):
    """The user's text fit for a one-line message: quoted, control characters as '?', cut to 40."""
    text = re.sub(r"[\x00-\x1f\x7f]", "?", text)
    if len(text) > 40:
        text = text[:37] + "..."
    return f"'{text}'"


# ---- The steps, the build folder ----

def all_steps():
    """Folders stepNN_* with a CMakeLists.txt, in order: the rule the top CMakeLists.txt applies."""
    return sorted(p.parent.name for p in ROOT.glob("step[0-9][0-9]_*/CMakeLists.txt") if p.is_file())


def preset():
    if os.environ.get("OCEAN_PRESET"):
        return os.environ["OCEAN_PRESET"]
    return "ci" if os.environ.get("CI") == "true" else "release"


def build_dir():
    return Path(os.environ.get("OCEAN_BUILD_DIR") or f"build/{preset()}")


def step_program(step):
    return build_dir() / step / step


def require_built(*programs):
    for program in programs:
        if not (Path(program).is_file() and os.access(program, os.X_OK)):
            raise Failure(f"{program} is not built (./ocean run builds everything; "
                          f"OCEAN_BUILD_DIR is {build_dir()})")


def labs():
    """{NAME: CHAPTER} from the add_lab(NAME CHAPTER STEP ...) lines of lab/CMakeLists.txt."""
    text = (ROOT / "lab/CMakeLists.txt").read_text(encoding="utf-8")
    return dict(re.findall(r"^add_lab\(([a-z0-9_]+) CHAPTER ([a-z0-9_]+) ", text, re.M))


# ---- Argument types: each returns the value or raises ArgumentTypeError, which argparse prints ----

def whole(low, high):
    def parse(text):
        # Digits only: no sign, exponent or point.
        if re.fullmatch(r"[0-9]{1,9}", text) and low <= int(text) <= high:
            return int(text)
        raise argparse.ArgumentTypeError(f"expects a whole number in [{low}, {high}], got {shown(text)}")
    return parse


def decimal(low, high):
    def parse(text):
        # Kept as typed (the step reads it): digits and at most one point, no nan, inf or exponent.
        if re.fullmatch(r"[0-9]{1,10}(\.[0-9]{1,9})?", text) and low <= float(text) <= high:
            return text
        raise argparse.ArgumentTypeError(f"expects a decimal number in [{low}, {high}], got {shown(text)}")
    return parse


def size(text):
    match = re.fullmatch(r"([0-9]{1,5})x([0-9]{1,5})", text)
    if match and all(1 <= int(side) <= MAX_IMAGE_SIDE for side in match.groups()):
        return text
    raise argparse.ArgumentTypeError(f"expects WxH, each side in [1, {MAX_IMAGE_SIDE}], got {shown(text)}")


def sizes(text):
    """--windows: WxH words split on whitespace, never evaluated."""
    words = text.split()
    if not words:
        raise argparse.ArgumentTypeError("needs at least one WxH")
    return [size(word) for word in words]


def resolutions(text):
    words = text.split()
    if not words:
        raise argparse.ArgumentTypeError("needs at least one resolution")
    for word in words:
        if word not in RESOLUTIONS:
            raise argparse.ArgumentTypeError(f"{shown(word)} is not 64, 128, 256 or 512")
    return words


def folder(text):
    # A name that would read as a flag to the programs it is given to is refused (./-x says the same).
    if not text:
        raise argparse.ArgumentTypeError("needs a folder, not an empty name")
    if text.startswith("-"):
        raise argparse.ArgumentTypeError(f"{shown(text)} looks like a flag (give a folder so named as ./NAME)")
    return text


def tile_folder(text):
    # The contact sheet takes each tile as LABEL|IMAGE|SCREENSHOT: a '|' would split a path.
    if "|" in folder(text):
        raise argparse.ArgumentTypeError(f"{shown(text)}: a folder name with '|' cannot be a tile's path")
    return text


def step(text):
    if text in all_steps():
        return text
    raise argparse.ArgumentTypeError(f"unknown step {shown(text)} (./ocean list names them)")


def parameter(text):
    # The name only: the step checks the value.
    if re.match(r"[a-z][a-z0-9_]*=", text):
        return text
    raise argparse.ArgumentTypeError(f"expects name=value, got {shown(text)}")


def revision(text):
    # Only what names a commit, never a leading '-': git cannot read it as an option.
    if not re.fullmatch(r"[A-Za-z0-9._/~^@{}+][A-Za-z0-9._/~^@{}+-]{0,199}", text):
        raise argparse.ArgumentTypeError(f"{shown(text)} is not a revision")
    if not git_commit(text):
        raise argparse.ArgumentTypeError(f"{shown(text)} is not a revision of this repository")
    return text


def program(text):
    path = Path(text)
    if not (path.is_file() and os.access(path, os.X_OK)):
        raise argparse.ArgumentTypeError(f"{shown(text)} is not a program")
    return text


def lab(text):
    known = labs()
    if text not in known:
        raise argparse.ArgumentTypeError(f"no lab program {shown(text)} (lab/CMakeLists.txt: {' '.join(known)})")
    return text


def flags(text):
    """--baseline-args, --current-args: split on whitespace into words, never evaluated."""
    return text.split()


def git_commit(rev):
    result = subprocess.run(["git", "rev-parse", "--verify", "--quiet", f"{rev}^{{commit}}"],
                            capture_output=True, text=True)
    return result.stdout.strip() if result.returncode == 0 else ""


# ---- Running programs ----

def run_logged(command, log, what):
    """Runs COMMAND with its output in the file LOG; when it fails, LOG goes to stderr and WHAT is the error."""
    try:
        with open(log, "w", encoding="utf-8") as out:
            status = subprocess.run([str(word) for word in command], stdout=out, stderr=subprocess.STDOUT).returncode
    except OSError as error:
        raise Failure(f"{what}: {error.strerror}") from None
    if status != 0:
        sys.stderr.write(Path(log).read_text(encoding="utf-8", errors="replace"))
        raise Failure(what)


def run_quiet(command, what, cwd=None):
    """Runs COMMAND with its output shown only when it fails."""
    try:
        result = subprocess.run([str(word) for word in command], cwd=cwd, capture_output=True, text=True, errors="replace")
    except OSError as error:
        raise Failure(f"{what}: {error.strerror}") from None
    if result.returncode != 0:
        sys.stderr.write(result.stdout + result.stderr)
        raise Failure(what)
    return result.stdout


def has_param(step_name, name):
    """True when the step declares the parameter (so --set and --camera go only where they apply)."""
    listing = run_quiet([step_program(step_name), "--list-params"], f"{step_name} --list-params failed")
    return any(line.split()[:1] == [name] for line in listing.splitlines())


def make_folder(path):
    """The folder made, as an absolute path: tools then never take a user's folder for a flag."""
    try:
        Path(path).mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise Failure(f"cannot make the folder {shown(str(path))}: {error.strerror}") from None
    return Path(path).resolve()


def bench_lines(log):
    """The bench-csv-header and bench-csv lines a step printed after --bench, prefixes kept."""
    lines = [line for line in Path(log).read_text(encoding="utf-8", errors="replace").splitlines()
             if line.startswith(("bench-csv: ", "bench-csv-header: "))]
    if not any(line.startswith("bench-csv: ") for line in lines):
        raise Failure(f"{log} holds no bench-csv line")
    return lines


def bench_rows(log):
    """The step's runs as {column: value}: its header names the columns (common/run_support.hpp)."""
    columns = ["step", "size", "fps", "total_ms", "passes"]
    rows = []
    for line in bench_lines(log):
        name, _, value = line.partition(": ")
        if name == "bench-csv-header":
            columns = value.split(",")
        else:
            rows.append(dict(zip(columns, value.split(","))))
    return columns, rows


# ---- bench ----

def bench_table(args, out):
    """Every step's --bench: bench.csv (the steps' columns merged by name), bench.png, a printed table."""
    steps = all_steps()
    require_built(*map(step_program, steps), build_dir() / "tools/bench_chart")
    print(f"{'step':<18} {'fps':>8} {'ms/frame':>10}  wall ms per pass (and the step's extra figures)")
    columns, rows = [], []
    for step_name in steps:
        log = out / f"{step_name}.log"
        run_logged([step_program(step_name), "--headless", "--bench", "--frames", args.frames, "--size", args.size],
                   log, f"{step_name} failed")
        step_columns, step_rows = bench_rows(log)
        columns += [c for c in step_columns if c not in columns]
        row = step_rows[-1]
        rows.append(row)
        extra = "".join(f" {c} {row[c]}" for c in step_columns[5:] if row.get(c))
        print(f"{row['step']:<18} {row['fps']:>8} {float(row['total_ms']):10.1f}  {row['passes']}{extra}")
    with open(out / "bench.csv", "w", encoding="utf-8") as csv:
        csv.write(",".join(columns) + "\n")
        for row in rows:
            csv.write(",".join(row.get(c, "") for c in columns) + "\n")
    run_quiet([build_dir() / "tools/bench_chart", out / "bench.csv", out / "bench.png"], "the bench chart failed")
    print(f"bench: {out}/bench.csv and bench.png")


def bench_sweep(args, out):
    """Each simulating step (a `resolution` parameter) at each FFT resolution at --size, and at each
    window at --window-resolution (256): sweep.csv, sweep_chart.csv (bench_chart's columns) and sweep.png."""
    steps = all_steps()
    require_built(*map(step_program, steps), build_dir() / "tools/bench_chart")
    runs = []  # (step, window, resolution, the chart's label)
    for step_name in filter(lambda s: has_param(s, "resolution"), steps):
        runs += [(step_name, args.size, n, f"N={n}") for n in args.resolutions]
        runs += [(step_name, window, args.window_resolution, window) for window in args.windows]
    if not runs:
        raise Failure("no step simulates (none has a resolution parameter)")
    sweep = ["step,size,resolution,fps,total_ms,passes,simulation_ms"]
    chart = ["step,size,fps,total_ms,passes"]
    print(f"{'step':<18} {'window':>10} {'N':>5} {'fps':>8} {'ms/frame':>10}  wall ms per pass")
    for step_name, window, n, label in runs:
        log = out / f"sweep_{step_name}_{window}_{n}.log"
        run_logged([step_program(step_name), "--headless", "--bench", "--frames", args.frames, "--size", window,
                    "--set", f"resolution={n}"], log, f"{step_name} at {window}, resolution {n} failed")
        for row in bench_rows(log)[1]:
            sweep.append(",".join([row["step"], row["size"], n, row["fps"], row["total_ms"], row["passes"],
                                   row.get("simulation_ms", "")]))
            chart.append(",".join([f"{row['step'][:6]} {label}", row["size"], row["fps"], row["total_ms"], row["passes"]]))
            print(f"{row['step']:<18} {row['size']:>10} {n:>5} {row['fps']:>8} {float(row['total_ms']):10.1f}  {row['passes']}")
    (out / "sweep.csv").write_text("\n".join(sweep) + "\n", encoding="utf-8")
    (out / "sweep_chart.csv").write_text("\n".join(chart) + "\n", encoding="utf-8")
    run_quiet([build_dir() / "tools/bench_chart", out / "sweep_chart.csv", out / "sweep.png"], "the sweep chart failed")
    print(f"bench: {out}/sweep.csv and sweep.png")


def build_at_revision(rev, step_name):
    """STEP built at REV in a detached worktree build/against/SHA (same preset), kept for next time."""
    sha = git_commit(rev)
    source = Path("build/against") / sha
    if not source.is_dir():
        run_quiet(["git", "worktree", "add", "--detach", source, sha], f"could not check out {sha} in {source}")
    if not (source / step_name / "CMakeLists.txt").is_file():
        raise Failure(f"{step_name} does not exist at {shown(rev)}")
    print(f"ocean: building {step_name} at {sha[:12]} in {source}", file=sys.stderr)
    if not (source / f"build/{preset()}/build.ninja").is_file():
        run_quiet(["cmake", "--preset", preset()], f"{step_name} does not configure at {shown(rev)}", cwd=source)
    run_quiet(["cmake", "--build", f"build/{preset()}", "--target", step_name],
              f"{step_name} does not build at {shown(rev)}", cwd=source)
    return source / f"build/{preset()}" / step_name / step_name


def bench_pairs_of(args, out, step_name, baseline, current):
    """BASELINE and CURRENT run by turns, AB then BA, so that each pair sees nearly the same machine;
    bench_pairs prints the median of the per-pair ratios into against.txt."""
    require_built(baseline, current)
    sides = {"baseline": (baseline, args.baseline_args), "current": (current, args.current_args)}
    files = {side: out / f"{side}.csv" for side in sides}
    for path in files.values():
        path.write_text("", encoding="utf-8")
    for i in range(args.pairs):
        for side in (("baseline", "current") if i % 2 == 0 else ("current", "baseline")):
            exe, extra = sides[side]
            log = out / "run.log"
            run_logged([exe, "--headless", "--bench", "--frames", args.frames, "--size", args.size, *extra],
                       log, f"{exe} {' '.join(extra)} failed")
            with open(files[side], "a", encoding="utf-8") as csv:
                csv.writelines(line + "\n" for line in bench_lines(log))
    print(f"{step_name} at {args.size}, {args.frames} frames a run: baseline {baseline} {' '.join(args.baseline_args)}, "
          f"current {current} {' '.join(args.current_args)}")
    table = io.StringIO()
    try:
        with contextlib.redirect_stdout(table):
            bench_pairs.main(["bench_pairs.py", str(files["baseline"]), str(files["current"])])
    except SystemExit as stop:  # bench_pairs ends with sys.exit("message") on bad input
        raise Failure(str(stop.code)) from None
    print(table.getvalue(), end="")
    (out / "against.txt").write_text(table.getvalue(), encoding="utf-8")


def bench(args):
    measurement = "sweep" if args.sweep else "lab" if args.lab else \
                  "against" if args.against or args.baseline_bin else "table"
    plan = ["bench"] + plan_of(args, ["sweep", "against", "baseline_bin", "lab", "step", "pairs", "size", "frames",
                                      "resolutions", "windows", "window_resolution", "out", "baseline_args", "current_args"])
    dry_run_stops(plan)
    out = make_folder(args.out)
    if measurement == "table":
        bench_table(args, out)
    elif measurement == "sweep":
        bench_sweep(args, out)
    elif measurement == "lab":
        chapter = labs()[args.lab]  # the chapter it is built from: the baseline
        bench_pairs_of(args, out, chapter, step_program(chapter), build_dir() / "lab" / f"lab_{args.lab}")
    else:
        baseline = args.baseline_bin or build_at_revision(args.against, args.step)
        bench_pairs_of(args, out, args.step, baseline, step_program(args.step))


def bench_flags_fit(parser, args):
    """Only the flags the chosen measurement reads (a flag that would be ignored is refused), then
    the defaults of those it reads. argparse's group has already refused two measurements at once."""
    pairs_based = args.against or args.baseline_bin or args.lab
    for flag, given, allowed, goes_with in [
            ("--resolutions", args.resolutions, args.sweep, "--sweep"),
            ("--windows", args.windows, args.sweep, "--sweep"),
            ("--window-resolution", args.window_resolution, args.sweep, "--sweep"),
            ("--step", args.step, args.against or args.baseline_bin, "--against or --baseline-bin"),
            ("--pairs", args.pairs, pairs_based, "--against, --baseline-bin or --lab"),
            ("--baseline-args", args.baseline_args, pairs_based, "--against, --baseline-bin or --lab"),
            ("--current-args", args.current_args, pairs_based, "--against, --baseline-bin or --lab")]:
        if given is not None and not allowed:
            parser.error(f"{flag} goes with {goes_with}")
    defaults = {"resolutions": RESOLUTIONS, "windows": ["854x480", "1280x720", "1920x1080"], "window_resolution": "256",
                "step": all_steps()[-1], "pairs": 8, "baseline_args": [], "current_args": []}
    for name, value in defaults.items():
        if getattr(args, name) is None:
            setattr(args, name, value)
    if not args.sweep:
        args.resolutions = args.windows = args.window_resolution = None  # not part of this measurement's plan
    if not (args.against or args.baseline_bin):
        args.step = None
    if not pairs_based:
        args.pairs = args.baseline_args = args.current_args = None


# ---- compare, figures, animations, gallery ----

def compare(args):
    steps = args.steps or all_steps()
    dry_run_stops(["compare", *steps] + plan_of(args, ["time", "size", "camera", "out", "set"]))
    out = make_folder(args.out)
    require_built(*map(step_program, steps), build_dir() / "tools/contact_sheet")
    tiles = []
    for i, step_name in enumerate(steps, 1):
        exe = step_program(step_name)
        command = [exe, "--headless", "--frames", "3", "--time", args.time, "--size", args.size,
                   "--screenshot", out / f"{step_name}.png"]
        if has_param(step_name, "camera_yaw"):
            command += ["--camera", args.camera]
        for setting in args.set:
            if has_param(step_name, setting.split("=")[0]):
                command += ["--set", setting]
        label = (run_quiet([exe, "--help"], f"{step_name} --help failed").splitlines() or [step_name])[0]
        print(f"compare: [{i}/{len(steps)}] {label}", flush=True)
        run_logged(command, out / f"{step_name}.log", f"{step_name} failed")
        tiles.append(f"{label}|{out / step_name}.png|{step_name}/screenshot.png")
    run_quiet([build_dir() / "tools/contact_sheet", out / "contact_sheet.png", args.size, *tiles],
              "the contact sheet failed")
    print(f"contact sheet: {out}/contact_sheet.png")


def figure_programs():
    """Each chapter with figures (a figures.cpp) has its own figure program, BUILD/STEP/STEP_figures."""
    return [build_dir() / step / f"{step}_figures"
            for step in all_steps() if (ROOT / step / "figures.cpp").is_file()]


def figures(args):
    """Each chapter's figure program (STEP_figures, from its figures.cpp) computes its figures'
    numbers with the chapter's own code and writes a gnuplot script beside them, in
    BUILD/figures/FOLDER, FOLDER being where the picture belongs in the repository (the chapter
    that shows it, or docs/figures for one several chapters show); gnuplot draws the PNGs, copied
    into --out/FOLDER."""
    dry_run_stops(["figures", "--out", args.out])
    if not shutil.which("gnuplot"):
        raise Failure("gnuplot not found (Debian: apt-get install gnuplot-nox)")
    programs = figure_programs()
    require_built(*programs)
    data = build_dir() / "figures"
    shutil.rmtree(data, ignore_errors=True)
    data = make_folder(data)
    out = make_folder(args.out)
    for program in programs:
        run_quiet([program, data], f"{program.name} failed")
    scripts = sorted(data.rglob("*.gp"))
    if not scripts:
        raise Failure(f"the figure programs wrote no gnuplot script in {data}")
    for script in scripts:
        run_quiet(["gnuplot", script.name], f"gnuplot failed on {script}", cwd=script.parent)
        into = out / script.parent.relative_to(data)
        try:
            into.mkdir(parents=True, exist_ok=True)
            shutil.copy(script.with_suffix(".png"), into)
        except OSError:
            raise Failure(f"gnuplot drew no {script.with_suffix('.png')}, or {shown(str(into))} cannot take it") from None
    print(f"figures: {len(scripts)} in {out}")


def animations(args):
    """Each step recorded headless on a steady clock (--record, --dt) and its frames made into one
    animated WebP by tools/animate, which decodes the result to check it. The READMEs show them."""
    steps = args.steps or all_steps()
    dry_run_stops(["animations", *steps] + plan_of(args, ["out", "size", "seconds"]))
    require_built(*map(step_program, steps), build_dir() / "tools/animate")
    out = make_folder(args.out)
    frames = make_folder(build_dir() / "animations")
    for step_name in steps:
        record = frames / step_name
        shutil.rmtree(record, ignore_errors=True)
        run_logged([step_program(step_name), "--headless", "--size", args.size, "--frames", args.seconds * ANIMATION_FPS,
                    "--time", "2", "--dt", f"{1 / ANIMATION_FPS:.6g}", "--record", record,
                    "--screenshot", f"{record}.png", *ANIMATION_FLAGS.get(step_name, [])], f"{record}.log",
                   f"{step_name} failed")
        webp = out / f"{step_name}.webp"
        try:
            subprocess.run([str(build_dir() / "tools/animate"), str(webp), str(ANIMATION_FPS), "60",
                            *map(str, sorted(record.glob("frame_*.png")))], check=True)
        except (OSError, subprocess.CalledProcessError):
            raise Failure(f"{step_name}'s frames") from None
        if webp.stat().st_size > ANIMATION_MAX_BYTES:
            raise Failure(f"{webp} is over 2 MB")


GALLERY_README = """\
# Gallery: step06 under each preset

Drawn by `./ocean gallery` (tools/ocean_tools.py) from the code as it is: each picture's command is
under it (run from the repository's root after `./ocean run step06_foam_sky --help` has built it).
The clock runs 41 steps of 0.25 s from t = 0, so the foam has grown and decayed for 10 s.
The presets are in `step06_foam_sky/presets/`; the heights they draw are in step06's README.

"""
GALLERY_CLOCK = ["--headless", "--size", "960x540", "--frames", "41", "--time", "0", "--dt", "0.25"]


def gallery(args, out=Path("docs/gallery")):
    """Every step06 preset from the deck (a few metres above the water) and from the overview (40 m up),
    a backlit view, and their README with each picture's command under it. Headless, 960x540, on a
    fixed clock (t = 10 s: the foam has grown and decayed as on screen). Minutes on llvmpipe."""
    dry_run_stops(["gallery"])
    exe = step_program("step06_foam_sky")
    require_built(exe)
    make_folder(out)
    shots = []  # (image, caption, flags)
    for name in ["calm", "breezy", "stormy", "crossing"]:
        preset_file = Path("step06_foam_sky/presets") / f"{name}.preset"
        if not preset_file.is_file():
            raise Failure(f"no preset {preset_file}")
        first, prefix = preset_file.read_text(encoding="utf-8").partition("\n")[0], "# step06_foam_sky preset: "
        about = first[len(prefix):] if first.startswith(prefix) else ""
        shots.append((f"{name}-deck.png", f"{name}, from the deck: {about}", ["--preset", preset_file, "--camera", "deck"]))
        shots.append((f"{name}-overview.png", f"{name}, from 40 m up", ["--preset", preset_file, "--camera", "overview"]))
    shots.append(("backlit.png", "Backlit, 5 m above the water: the sun low ahead, light through the crests beside "
                  "the glitter path", ["--camera", "low", "--set", "sun_elevation=10", "--set", "sun_azimuth=315"]))
    readme = GALLERY_README
    for image, caption, shot_flags in shots:
        run_quiet([exe, *GALLERY_CLOCK, "--screenshot", out / image, *shot_flags], f"step06 failed on {image}")
        # The command as a reader types it: from the repository's root, the release build's program.
        typed = " ".join(["build/release/step06_foam_sky/step06_foam_sky", *GALLERY_CLOCK, "--screenshot",
                          f"docs/gallery/{image}", *map(str, shot_flags)])
        readme += f"## {caption}\n\n![{caption}]({image})\n\n    {typed}\n\n"
        print(f"docs/gallery/{image}")
    (out / "README.md").write_text(readme, encoding="utf-8")


# ---- The command line ----

def plan_of(args, names):
    """The flags as understood, defaults filled in, for the dry run's line (those set to None left out)."""
    plan = []
    for name in names:
        value = getattr(args, name, None)
        flag = "--" + name.replace("_", "-")
        if value is True:
            plan.append(flag)
        elif name == "set":
            plan += [word for setting in value for word in ("--set", setting)]
        elif isinstance(value, list):
            plan += [flag, " ".join(value)]
        elif value not in (None, False):
            plan += [flag, str(value)]
    return plan


def dry_run_stops(plan):
    """Under OCEAN_DRY_RUN=1 the arguments are checked: print what would run and stop."""
    if os.environ.get("OCEAN_DRY_RUN") == "1":
        print("ocean: dry run: " + shlex.join(plan))
        sys.exit(0)


class Parser(argparse.ArgumentParser):
    """argparse whose refusals are one line, "ocean: error: COMMAND: ...", and exit status 1."""

    def error(self, message):
        command = self.prog.removeprefix("ocean").strip()
        fail(f"{command}: {message}" if command else message)


def fail(message):
    message = re.sub(r"[\x00-\x1f\x7f]", "?", message)  # a newline would split the line in two
    if len(message) > 300:
        message = message[:297] + "..."
    print(f"ocean: error: {message}", file=sys.stderr)
    sys.exit(1)


def parsers():
    top = Parser(prog="ocean", description=__doc__.split("\n\n")[0], allow_abbrev=False)
    commands = top.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)

    def command(name, summary, epilog=None):
        return commands.add_parser(name, help=summary, description=summary, epilog=epilog, allow_abbrev=False,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)

    p = command("bench", "Time the steps: one of four measurements.", epilog=BENCH_EPILOG)
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--sweep", action="store_true", help="how the cost grows with the FFT resolution and the window")
    mode.add_argument("--against", metavar="REV", type=revision, help="the working tree against revision REV")
    mode.add_argument("--baseline-bin", metavar="PATH", type=program, help="against a program already built")
    mode.add_argument("--lab", metavar="NAME", type=lab, help="a lab/ program against its chapter")
    p.add_argument("--size", metavar="WxH", type=size, default="1280x720", help="WxH (default 1280x720)")
    p.add_argument("--frames", metavar="N", type=whole(1, 100000), default=20, help="frames a run, 1 to 100000 (default 20)")
    p.add_argument("--out", metavar="DIR", type=folder, default="build/bench", help="the folder written (default build/bench)")
    p.add_argument("--resolutions", metavar='"N ..."', type=resolutions, help='--sweep: "64 128 256 512" (the default), any of them')
    p.add_argument("--windows", metavar='"WxH ..."', type=sizes, help='--sweep: "WxH ..." (default "854x480 1280x720 1920x1080")')
    p.add_argument("--window-resolution", metavar="N", choices=RESOLUTIONS,
                   help="--sweep: the FFT resolution of the window runs (default 256)")
    p.add_argument("--step", type=step, help="--against, --baseline-bin: the step (default the newest)")
    p.add_argument("--pairs", metavar="N", type=whole(1, 1000), help="AB/BA pairs of runs, 1 to 1000 (default 8)")
    p.add_argument("--baseline-args", metavar='"FLAGS"', type=flags, help="flags for the baseline's runs only")
    p.add_argument("--current-args", metavar='"FLAGS"', type=flags, help="flags for the current program's runs only")
    p.set_defaults(run=bench, check=bench_flags_fit)

    p = command("compare", "Every step (or those named) headless with the same camera and time, "
                "on one contact sheet: OUT/contact_sheet.png.")
    p.add_argument("steps", metavar="STEP", nargs="*", type=step, help="a name ./ocean list prints (default all)")
    p.add_argument("--time", metavar="T", type=decimal(0, 10**9), default="1.5", help="seconds (default 1.5)")
    p.add_argument("--size", metavar="WxH", type=size, default="480x270", help="each tile's WxH (default 480x270)")
    p.add_argument("--camera", metavar="NAME", choices=CAMERAS, default="overview", help="overview, deck, low or top, for the 3D steps (default overview)")
    p.add_argument("--set", metavar="NAME=VALUE", type=parameter, action="append", default=[],
                   help="a parameter, for the steps that have it (repeatable)")
    p.add_argument("--out", metavar="DIR", type=tile_folder, default="build/compare", help="default build/compare")
    p.set_defaults(run=compare)

    p = command("figures", "The teaching figures, drawn from the chapters' own code (STEP/figures.cpp) by "
                "gnuplot into the chapters' folders (their numbers and scripts in BUILD/figures).")
    p.add_argument("--out", metavar="DIR", type=folder, default=str(ROOT),
                   help="the repository, or a copy of its layout (default: this repository; each figure "
                        "goes to the chapter that shows it, or docs/figures)")
    p.set_defaults(run=figures)

    p = command("animations", f"Each step (or those named) in motion: --record's frames, {ANIMATION_FPS} a second "
                "from t = 2 s, made into one animated WebP under 2 MB: OUT/STEP.webp.")
    p.add_argument("steps", metavar="STEP", nargs="*", type=step, help="a name ./ocean list prints (default all)")
    p.add_argument("--out", metavar="DIR", type=folder, default="docs/animations", help="default docs/animations")
    p.add_argument("--size", metavar="WxH", type=size, default="480x270", help="WxH (default 480x270)")
    p.add_argument("--seconds", metavar="S", type=whole(1, 20), default=4, help="1 to 20 (default 4)")
    p.set_defaults(run=animations)

    p = command("gallery", "docs/gallery/: step06's presets from the deck and from 40 m up, a backlit view, "
                "and their README with each picture's command.")
    p.set_defaults(run=gallery)
    return top, commands.choices


BENCH_EPILOG = """\
measurements (one at a time; the results go into --out):
  (none)               every step's --bench in one table: bench.csv and the bar chart bench.png
  --sweep              each step that simulates at each FFT resolution (--resolutions, at --size)
                       and each window (--windows, at --window-resolution: 256): sweep.csv and sweep.png
  --against REV        the working tree's --step against the same step at REV (built in
                       build/against/SHA): the two alternate run by run (AB, BA, ...) and each pass
                       is the median of the per-pair ratios (tools/bench_pairs.py): against.txt
  --baseline-bin PATH  the same against a program already built
  --lab NAME           a program of lab/ (lab/README.md) against the chapter it is built from

--baseline-args and --current-args add flags to one side (one build, two --shader-dir or --set
variants), split on whitespace, never evaluated; a single flag is given as --current-args=--flag."""


def main(argv):
    os.chdir(ROOT)  # paths are taken from the repository's root, as ./ocean does
    sys.stdout.reconfigure(errors="backslashreplace")  # a word that is not UTF-8, printed in the dry run's line
    try:
        parse_and_run(argv)
    except OSError as error:  # a file it writes: --out on a full disk, a folder without permission
        fail(f"{argv[0] if argv else 'ocean'}: cannot write {error.filename or 'a file'}: {error.strerror}")
    except KeyboardInterrupt:
        sys.exit(130)


def parse_and_run(argv):
    top, commands = parsers()
    # A command's own parser, intermixed: steps and flags in any order (./ocean compare STEP --size S STEP).
    if argv and argv[0] in commands:
        parser = commands[argv[0]]
        args = parser.parse_intermixed_args(argv[1:])
    else:
        parser, args = top, top.parse_args(argv)
        if args.command is None:
            top.print_help()
            return
    if hasattr(args, "check"):
        args.check(parser, args)
    try:
        args.run(args)
    except Failure as failure:
        fail(f"{argv[0]}: {failure}")


if __name__ == "__main__":
    main(sys.argv[1:])
