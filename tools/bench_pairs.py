"""bench_pairs.py BASELINE.csv CURRENT.csv: how much a change costs, from runs taken in pairs.

Each file holds one `bench-csv:` line per run (common/run_support.hpp's line: step, size, fps,
total_ms, passes as name=ms;...), the baseline's i-th run taken next to the current's i-th run
(`./ocean bench --against` alternates them: AB, BA, AB ...). On a shared machine the speed drifts
by 15-25 % within minutes, far more than most changes cost, but two runs taken one after the other
see nearly the same machine: so the figure is the median of the per-pair ratios current/baseline,
with its quartiles, not the ratio of two medians taken minutes apart.

Only the frame (total_ms) is a cost on its own. On llvmpipe the per-pass times are entangled: a
compute dispatch first finishes the drawing queued before it, so a pass's timer can hold some of
the previous pass's work. They are printed as a guide. A `bench-csv-header:` line, where the file
has one, names the columns after the passes (a step's own figures, in ms): those are printed too,
under their names.
"""
import statistics
import sys


def read_runs(path):
    runs = []
    columns = []  # the last header's names, for the figures after the passes
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line.startswith("bench-csv-header:"):
                columns = line[len("bench-csv-header:"):].strip().split(",")
                continue
            if line.startswith("bench-csv:"):
                line = line[len("bench-csv:"):].strip()
            fields = line.split(",")
            if len(fields) < 5 or fields[0] == "step":
                continue
            try:
                run = {"frame": float(fields[3])}
                for entry in filter(None, fields[4].split(";")):
                    name, ms = entry.split("=")
                    run[name] = float(ms)
                for name, value in zip(columns[5:], fields[5:]):
                    if value:  # empty: not measured in this run
                        run[name] = float(value)
            except ValueError:
                sys.exit(f"bench_pairs: {path}: not a bench-csv line: {line}")
            runs.append(run)
    return runs


def quartiles(values):
    if len(values) < 2:
        return values[0], values[0]
    q = statistics.quantiles(values, n=4, method="inclusive")
    return q[0], q[2]


def main(argv):
    if len(argv) != 3:
        sys.exit("usage: bench_pairs.py BASELINE.csv CURRENT.csv")
    baseline, current = read_runs(argv[1]), read_runs(argv[2])
    pairs = min(len(baseline), len(current))
    if pairs == 0:
        sys.exit("bench_pairs: no pair of runs to compare")
    baseline, current = baseline[:pairs], current[:pairs]
    names = ["frame"] + [n for n in current[0] if n != "frame" and all(n in r for r in baseline + current)]
    print(f"{pairs} pairs; ms are medians over the runs; the ratio is current/baseline, pair by pair")
    print(f"{'':20s} {'baseline ms':>12s} {'current ms':>11s} {'ratio':>7s} {'quartiles':>15s}")
    for name in names:
        a = [r[name] for r in baseline]
        b = [r[name] for r in current]
        ratios = [y / x for x, y in zip(a, b) if x > 0]
        if not ratios:
            continue
        low, high = quartiles(ratios)
        label = name if name == "frame" else "  " + name
        print(f"{label:20s} {statistics.median(a):12.2f} {statistics.median(b):11.2f} "
              f"{statistics.median(ratios):7.3f}   [{low:.3f}, {high:.3f}]")


if __name__ == "__main__":
    main(sys.argv)
