#!/usr/bin/env python3
"""lab_free.py REPO: no chapter's README is a lab report.

A lesson teaches what the code does and why; how fast it ran on which machine, which issue changed
it and what was tried and not kept belong to the maintainers' pages: docs/performance.md (costs,
drivers, what did not pay) and each step's how_we_know.md (tests and their evidence). Where a technique exists for speed the lesson says why in one sentence and links
../docs/performance.md; the figures stay there, so a lesson does not go stale with a driver.

Every line of every step*/README.md (step_template's too), code blocks included but their
`// from FILE` lines, is checked for four kinds of lab text:
  timing      a number with a unit of time or rate: 3.4 ms, 5 µs, 30 fps, 60 frames per second
              (not an animation's caption: "4 s at 15 frames a second" describes the picture),
              "N times faster/slower", "2.5x faster";
  gpu         a GPU, driver or rasteriser by name, as a whole word: llvmpipe, Mesa, NVIDIA, H100,
              AMD, Intel, SwiftShader, ANGLE (upper case only: "angle" is geometry) ...;
  issue       an issue's number or its stops: "issue 23", "#23", "stop 12", "the fourth stop";
  rejected    a phrase that only a report of what was tried uses (REJECTED below; kept short, so
              that plain lesson words such as "measured" or "slower" stay free).
It prints `FAIL: path:line: kind: text` for each hit and exits 1 on any. It cannot pass vacuously:
it fails when it finds no README, or when its own patterns misjudge the samples below.
"""
import pathlib
import re
import sys

ORDINALS = ("first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|eleventh|twelfth|"
            "thirteenth|fourteenth|fifteenth|\\d+(?:st|nd|rd|th)")
NUMBER = r"\d+(?:[.,]\d+)?"
TIMING = [
    re.compile(rf"\b{NUMBER}\s*(?:ms|µs|μs|milliseconds?|microseconds?)\b", re.I),
    re.compile(rf"\b{NUMBER}\s*(?:fps|frames? (?:per|a) second)\b", re.I),
    re.compile(rf"\b(?:{NUMBER}|two|three|four|five|six|seven|eight|nine|ten|hundred)\s+times\s+"
               r"(?:faster|slower|cheaper|dearer|as fast|as slow)\b", re.I),
    re.compile(rf"\b{NUMBER}\s*[x×]\s*(?:faster|slower|cheaper)\b", re.I),
]
GPU_WORDS = ("llvmpipe|lavapipe|softpipe|Mesa|NVIDIA|GeForce|Quadro|RTX|H100|H200|A100|AMD|Radeon|"
             "Intel|SwiftShader|Adreno|Mali")
GPU = [re.compile(rf"\b(?:{GPU_WORDS})\b", re.I),
       re.compile(r"\bANGLE\b")]  # case-sensitive: the library, not the geometry
ISSUE = [
    re.compile(r"\b(?:issues?|PR|pull request)\s*#?\d+", re.I),
    re.compile(r"(?<![\w(/&#])#\d+(?![\w-])"),  # "#23", not "#1-waves" (an anchor) nor "&#39;"
    re.compile(r"\bstops?\s+\d+", re.I),
    re.compile(rf"\b(?:{ORDINALS})\s+stop\b", re.I),
]
REJECTED_PHRASES = (
    "did not pay", "does not pay", "didn't pay", "doesn't pay", "not pay for itself",
    "was rejected", "were rejected", "we rejected", "rejected alternative",
    "we tried", "was tried", "were tried", "tried and", "not kept",
    "we measured", "was measured", "were measured", "benchmark",
)
REJECTED = [re.compile(r"\b" + re.escape(p).replace(r"\ ", r"\s+") + r"(?:s|ed|ing)?\b", re.I)
            for p in REJECTED_PHRASES]  # benchmark, benchmarks, benchmarked
KINDS = (("timing", TIMING), ("gpu", GPU), ("issue", ISSUE), ("rejected", REJECTED))


# Not lab text, removed before judging: an animation's caption gives its length and playback rate
# ("4 s at 15 frames a second"), which describe the picture, not a measurement; a link's target
# (an address such as how_we_know.md#what-it-costs-benchmarks-not-tests) is not the lesson's prose.
PICTURE = re.compile(r"\b\d+ s at \d+ frames a second\b")
TARGET = re.compile(r"\]\([^)\s]*\)")


def judge(line):
    """The kinds of lab text on a line, in KINDS order (empty: a lesson's line)."""
    line = TARGET.sub("]()", PICTURE.sub("", line))
    return [kind for kind, patterns in KINDS if any(p.search(line) for p in patterns)]


# The self-check: lab lines that must be caught (with their kind) and lesson lines that must not.
MUST_CATCH = [
    ("timing", "three bodies take **3.4 ms of a 264 ms frame**"),
    ("timing", "a dispatch costs 5 µs however little it does"),
    ("timing", "step05 draws 1080p at ~920 frames per second"),
    ("timing", "runs at 60 fps"),
    ("timing", "The FFT is 105 times faster than the DFT"),
    ("timing", "the compute shader is 2.5x faster"),
    ("gpu", "FFTW on llvmpipe, where the GPU is the CPU"),
    ("gpu", "On an NVIDIA H200 it was most of the simulation"),
    ("gpu", "ANGLE translates it to Direct3D"),
    ("gpu", "Mesa unrolls the loop to its bound"),
    ("issue", "until issue 23's fourth stop"),
    ("issue", "fixed in #42"),
    ("issue", "measured at stop 12"),
    ("issue", "the thirteenth stop ran the tests again"),
    ("rejected", "What was tried and did not pay:"),
    ("rejected", "a shared twiddle table (we tried: normals flipped sign)"),
    ("rejected", "which is a benchmark"),
    ("rejected", "the cost (benchmarks, not tests)"),
]
MUST_PASS = [
    "A crest sits where the angle x w − t φ is constant",
    "deep-water dispersion: short waves travel slower",
    "its peak is γ = 3.3 times sharper",
    "k̂ times the height's phase turned by 90°",
    "the wind at 30 m/s raises waves 4.4 m high",
    "#version 430 core",
    "see [choppiness](#4-choppy-waves-gerstner-then-fourier)",
    "Measured on the notes' version of the default sea, corr(height, J) was +0.81",
    "the GPU timer queries each pass; a stop sign; the first wave",
    "Fragments the depth test rejects are never shaded",
    "float ms = 1.0; // a variable named ms",
    "the rounds: [how_we_know.md](how_we_know.md#what-it-costs-benchmarks-not-tests)",
    "![step01_sine2d in motion: 4 s at 15 frames a second](../docs/animations/step01_sine2d.webp)",
]

failures = []
for kind, sample in MUST_CATCH:
    if kind not in judge(sample):
        failures.append(f"self-check: a lab line not caught as {kind}: {sample}")
for sample in MUST_PASS:
    if judge(sample):
        failures.append(f"self-check: a lesson line caught as {', '.join(judge(sample))}: {sample}")

repo = pathlib.Path(sys.argv[1]).resolve()
readmes = sorted(repo.glob("step*/README.md"))
lines_checked = 0
for readme in readmes:
    for number, line in enumerate(readme.read_text(encoding="utf-8").splitlines(), 1):
        if line.startswith("// from "):
            continue  # a code excerpt's file name (excerpts.py checks the rest of the block)
        lines_checked += 1
        for kind in judge(line):
            failures.append(f"{readme.relative_to(repo)}:{number}: {kind}: {line.strip()}")
for failure in failures:
    print("FAIL:", failure)
if not readmes:
    print("FAIL: no step*/README.md found")
print(f"lab_free: {lines_checked} lines of {len(readmes)} READMEs checked, {len(failures)} with lab text")
sys.exit(1 if failures or not readmes else 0)
