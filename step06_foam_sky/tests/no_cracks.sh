#!/usr/bin/env bash
# no_cracks.sh STEP06_EXE OUT_DIR: the sea seen from above has no holes. With a black sky, the
# patches coloured by their level (view=tessellation: every colour has a channel of 0.9 or more)
# fill the whole picture; a crack between two patches would let the black sky through. A stormy
# sea (the largest displacements, so the widest cracks a mismatch could open) from 30 m up,
# looking straight down, the levels from 8 to 64 in view. The ES build cuts the patches on the
# CPU (patch_lod.hpp), where the finer side of an edge must snap to the coarser; the GL builds'
# tessellator shares edge levels by construction: both are held to it.
set -u
exe=$1 out=$2
rm -rf "$out" && mkdir -p "$out"
shot="$out/from_above.png"
"$exe" --headless --frames 2 --time 3 --size 640x360 --screenshot "$shot" \
  --preset "$(dirname "$0")/../presets/stormy.preset" --set view=tessellation \
  --set zenith_colour=0,0,0 --set horizon_colour=0,0,0 --set cloud_cover=0 \
  --set camera_pitch=89 --set camera_distance=4 --set camera_fov=120 > "$out/run.log" 2>&1 \
  || { cat "$out/run.log"; echo "FAIL: the run exited with an error"; exit 1; }
python3 - "$shot" <<'PY'
import struct, sys, zlib

def read_png(path):  # 8-bit RGB or RGBA, not interlaced: what --screenshot writes
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, chunks = 8, {}
    idat = b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    assert depth == 8 and colour in (2, 6), "an 8-bit RGB(A) PNG"
    channels = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = previous[x], previous[x - channels] if x >= channels else 0
            if kind == 1: line[x] = (line[x] + a) & 255
            elif kind == 2: line[x] = (line[x] + b) & 255
            elif kind == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows

width, height, channels, rows = read_png(sys.argv[1])
holes = [(x, y) for y, row in enumerate(rows) for x in range(width)
         if max(row[x * channels:x * channels + 3]) < 100]
print(f"{len(holes)} of {width * height} pixels show the sky (a crack), first: {holes[:5]}")
sys.exit(1 if holes else 0)
PY
