#!/usr/bin/env python3
"""lab_free.py REPO: no chapter's lesson page is a lab report, nor a porting guide.

A lesson teaches what the code does and why; how fast it ran on which machine, which issue changed
it and what was tried and not kept belong to the maintainers' pages: docs/performance.md (costs,
drivers, what did not pay) and each step's how_we_know.md (tests and their evidence). Where a technique exists for speed the lesson says why in one sentence and links
../docs/performance.md; the figures stay there, so a lesson does not go stale with a driver.

Every line of every lesson page (lessons.py: step*/*.md but how_we_know.md, step_template's too),
code blocks included but their `// from FILE` lines, is checked for six kinds of lab text:
  timing      a number with a unit of time or rate: 3.4 ms, 5 µs, 30 fps, 60 frames per second
              (not an animation's caption: "4 s at 15 frames a second" describes the picture),
              "N times faster/slower", "2.5x faster";
  gpu         a GPU, driver or rasteriser by name, as a whole word: llvmpipe, Mesa, NVIDIA, H100,
              AMD, Intel, SwiftShader, ANGLE (upper case only: "angle" is geometry) ...;
  issue       an issue's number or its stops: "issue 23", "#23", "stop 12", "the fourth stop";
  rejected    a phrase that only a report of what was tried uses (REJECTED below; kept short, so
              that plain lesson words such as "measured" or "slower" stay free);
  report      a test report or a history: "For maintainers", "what went wrong first", "measured
              about", an RMSE, a driver that "miscompiled", "the issue that asked", "we have not
              read", a command line with a build folder or a --gtest_filter;
  profile     the plumbing of the other GL profiles: a "Without GL 4.5" section, a build macro
              (OCEAN_GL_..., __EMSCRIPTEN__), or a paragraph that names GL 4.1, ES 3.0, WebGL or
              macOS without linking docs/portability.md, where that plumbing is taught. A chapter
              says where its code differs by profile in a line, with that link.
It prints `FAIL: path:line: kind: text` for each hit and exits 1 on any. It cannot pass vacuously:
it fails when it finds no README, or when its own patterns misjudge the samples below.
"""
import pathlib
import re
import sys

from lessons import lesson_pages

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
REPORT = [
    re.compile(r"\bfor maintainers\b", re.I),
    re.compile(r"\bwhat went wrong\b|\bwent wrong first\b", re.I),
    re.compile(r"\bmeasured (?:about|around|roughly|at about)\b", re.I),
    re.compile(r"\bRMSE\b"),
    re.compile(r"\bmiscompil", re.I),
    re.compile(r"\bthe issue that\b", re.I),
    re.compile(r"\b(?:we|I) have not read\b", re.I),
    re.compile(r"\bbuild/(?:ci|release|debug|asan|portable|es|web|<preset>)/"),
    re.compile(r"--gtest_filter"),
]
PROFILE = [
    re.compile(r"\bwithout GL 4\.5\b", re.I),
    re.compile(r"\bOCEAN_(?:GL|ES|WEB)_?\w*|__EMSCRIPTEN__"),
]
PROFILE_NAMES = re.compile(r"\bGL 4\.1\b|\bES 3\.0\b|\bWebGL\b|\bmacOS\b")
KINDS = (("timing", TIMING), ("gpu", GPU), ("issue", ISSUE), ("rejected", REJECTED), ("report", REPORT),
         ("profile", PROFILE))


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
    ("report", "## For maintainers"),
    ("report", "**What went wrong first, and why the identity.**"),
    ("report", "the error, measured about 3 × 10⁻⁷, stays below"),
    ("report", "an RMSE of 1.9 against the golden"),
    ("report", "a GPU driver miscompiled the nested loop"),
    ("report", "as the issue that asked for this chapter saw"),
    ("report", "from the paper's abstract (the paper itself we have not read)"),
    ("report", "`./build/release/step08_wakes/step08_wakes_tests --gtest_filter='Step08*'`"),
    ("profile", "## Without GL 4.5: macOS, ES 3.0, the browser"),
    ("profile", "#if OCEAN_GL_BIND_TO_EDIT"),
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
    "the waves' heights, measured from the mean level",
    "the root mean square of the heights",
]
# A paragraph that names another profile must link where its plumbing is taught.
PARAGRAPH_MUST_CATCH = ["The Mac's GL 4.1 has no compute shaders,\nso this pass draws into a float texture."]
PARAGRAPH_MUST_PASS = ["GL 4.1 and ES 3.0 bind the object first\n([docs/portability.md](../docs/portability.md#step02))."]


def unlinked_profile_paragraphs(text):
    """(first line number, text) of each paragraph outside code blocks that names GL 4.1, ES 3.0,
    WebGL or macOS without a link to docs/portability.md."""
    found, paragraph, start, in_block = [], [], 0, False
    for number, line in enumerate(text.splitlines() + [""], 1):
        if line.startswith("```"):
            in_block = not in_block
        if in_block or line.startswith(("```", "#")) or not line.strip():  # a heading is judged as a line
            joined = "\n".join(paragraph)
            if PROFILE_NAMES.search(joined) and "portability.md" not in joined:
                found.append((start, paragraph[0].strip()))
            paragraph = []
            continue
        if not paragraph:
            start = number
        paragraph.append(line)
    return found

failures = []
for kind, sample in MUST_CATCH:
    if kind not in judge(sample):
        failures.append(f"self-check: a lab line not caught as {kind}: {sample}")
for sample in MUST_PASS:
    if judge(sample):
        failures.append(f"self-check: a lesson line caught as {', '.join(judge(sample))}: {sample}")
for sample in PARAGRAPH_MUST_CATCH:
    if not unlinked_profile_paragraphs(sample):
        failures.append(f"self-check: a profile paragraph without its link not caught: {sample!r}")
for sample in PARAGRAPH_MUST_PASS:
    if unlinked_profile_paragraphs(sample):
        failures.append(f"self-check: a linked profile paragraph caught: {sample!r}")

repo = pathlib.Path(sys.argv[1]).resolve()
readmes = lesson_pages(repo)
lines_checked = 0
for readme in readmes:
    text = readme.read_text(encoding="utf-8")
    for number, first in unlinked_profile_paragraphs(text):
        failures.append(f"{readme.relative_to(repo)}:{number}: profile (no link to docs/portability.md): {first}")
    for number, line in enumerate(text.splitlines(), 1):
        if line.startswith("// from "):
            continue  # a code excerpt's file name (excerpts.py checks the rest of the block)
        lines_checked += 1
        for kind in judge(line):
            failures.append(f"{readme.relative_to(repo)}:{number}: {kind}: {line.strip()}")
for failure in failures:
    print("FAIL:", failure)
if not readmes:
    print("FAIL: no lesson page (step*/README.md) found")
print(f"lab_free: {lines_checked} lines of {len(readmes)} lesson pages checked, {len(failures)} with lab text")
sys.exit(1 if failures or not readmes else 0)
