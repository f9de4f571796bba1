#!/usr/bin/env python3
"""clipmap_addressing.py: draws clipmap_addressing.svg, the foam clipmap's toroidal addressing (foam.md).

One level of the clipmap seen along x, with N = 8 texels instead of 256: the world's cells, the window of
N cells that follows the camera, and the texture, in which world cell i is texel i mod N. Then the
camera moves three cells on: five texels keep their cell and their foam, and the three texels whose
cells left the window are rewritten with the cells that entered, started afresh. The same holds along
z. Standard library only: `python3 step06_foam_sky/clipmap_addressing.py` rewrites the SVG beside it.
"""
import pathlib

N, CELLS, W, H = 8, 20, 34, 30  # texels, world cells drawn, a cell's width and height (pixels)
TW = 48  # a texel's width: not a cell's, so that no texel lines up with a world cell
AHEAD = 0.3  # the window's centre lies 30 % of its side ahead of the camera (foam.hpp)
LEFT = 40
BLUE, ORANGE, GREY, INK = "#9ecae1", "#fdae6b", "#f0f0f0", "#222"
out = []


def text(x, y, s, size=13, anchor="middle", weight="normal", fill=INK):
    out.append(f'<text x="{x}" y="{y}" font-size="{size}" text-anchor="{anchor}" font-weight="{weight}" '
               f'fill="{fill}">{s}</text>')


def box(x, y, w, h, fill, stroke=INK, width=1):
    out.append(f'<rect x="{x}" y="{y}" width="{w}" height="{h}" fill="{fill}" stroke="{stroke}" stroke-width="{width}"/>')


def arrow(x1, y1, x2, y2, colour=INK):
    out.append(f'<line x1="{x1}" y1="{y1}" x2="{x2}" y2="{y2}" stroke="{colour}" stroke-width="1.2" '
               f'marker-end="url(#head)"/>')


def frame(top, origin, previous, title):
    """One frame: the world's cells with the window [origin, origin + N), then the texture."""
    text(LEFT, top, title, 14, "start", "bold")
    y = top + 32
    text(LEFT + CELLS * W + 8, y + 20, "world cells i", 12, "start")
    for c in range(CELLS):
        inside = origin <= c < origin + N
        entered = inside and not (previous <= c < previous + N)
        left = previous <= c < previous + N and not inside
        box(LEFT + c * W, y, W, H, (ORANGE if entered else BLUE) if inside else GREY)
        text(LEFT + c * W + W / 2, y + 20, c, 12, fill="#999" if left else INK)
        if left:
            text(LEFT + c * W + W / 2, y + H + 14, "left", 10, fill="#999")
    out.append(f'<rect x="{LEFT + origin * W}" y="{y - 3}" width="{N * W}" height="{H + 6}" fill="none" '
               f'stroke="{INK}" stroke-width="2.5"/>')
    camera = LEFT + (origin + N / 2 - AHEAD * N) * W  # the window is centred ahead of the camera
    out.append(f'<polygon points="{camera},{y - 4} {camera - 7},{y - 16} {camera + 7},{y - 16}" fill="{INK}"/>')
    text(camera + 10, y - 7, "camera", 11, "start")
    # the texture: a separate image, drawn with its own texel width, so that its place on the page
    # says nothing about the sea; only the arrows link a texel to its cell
    ty = y + H + 62
    text(LEFT + CELLS * W + 8, ty + 13, "the texture:", 12, "start")
    text(LEFT + CELLS * W + 8, ty + 27, "texel t / cell i", 12, "start")
    tx = LEFT + (CELLS * W - N * TW) / 2
    box(tx - 4, ty - 4, N * TW + 8, H + 8, "white", "#888", 1)
    for t in range(N):
        cell = origin + ((t - origin) % N)  # foam.frag: the one cell of the window congruent to t
        before = previous + ((t - previous) % N)
        entered = cell != before
        box(tx + t * TW, ty, TW, H, ORANGE if entered else BLUE)
        text(tx + t * TW + TW / 2, ty + 12, f"t={t}", 10, fill="#555")
        text(tx + t * TW + TW / 2, ty + 26, cell, 12, weight="bold")
        arrow(LEFT + cell * W + W / 2, y + H + 2, tx + t * TW + TW / 2, ty - 6, "#555")
    return ty + H


out.append(f'<defs><marker id="head" markerWidth="8" markerHeight="8" refX="7" refY="4" orient="auto">'
           f'<path d="M0,0 L8,4 L0,8 z" fill="#555"/></marker></defs>')
text(LEFT, 22, "The foam clipmap's addressing, along x (N = 8 texels here; 256 in the chapter)", 15, "start", "bold")
bottom = frame(56, 4, 4, "Frame 1: the window holds cells 4 to 11 (u_origin = 4); cell i is stored in texel i mod 8")
bottom = frame(bottom + 50, 7, 4, "Frame 2: the camera moved 3 cells on; the window holds cells 7 to 14 (u_origin = 7)")
legend = bottom + 30
box(LEFT, legend - 13, 16, 16, BLUE)
text(LEFT + 22, legend, "a cell in the window both frames: same texel, its foam kept and stepped on", 12, "start")
box(LEFT, legend + 9, 16, 16, ORANGE)
text(LEFT + 22, legend + 22, "a cell that entered: it takes the texel of the cell that left (4→12, 5→13, 6→14), "
     "started afresh", 12, "start")
text(LEFT, legend + 44, "In a texel: the small t= is the texel's index, the bold number the world cell i it holds "
     "(i mod 8 = t).", 12, "start")
text(LEFT, legend + 62, "The texture is drawn apart from the cells: its place on the page means nothing, only the "
     "arrows link a cell to its texel.", 12, "start")
legend += 40
text(LEFT, legend + 46, "The renderer reads cell i at (i + ½) / N, its centre, and GL_REPEAT takes the mod; "
     "foam.frag, run once a texel,", 12, "start")
text(LEFT, legend + 64, "finds the cell it holds the other way round: i = origin + ((texel − origin) mod N).", 12, "start")
width, height = LEFT + CELLS * W + 110, legend + 80
svg = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" '
       f'font-family="DejaVu Sans, Arial, sans-serif">\n<rect width="100%" height="100%" fill="white"/>\n'
       + "\n".join(out) + "\n</svg>\n")
pathlib.Path(__file__).with_name("clipmap_addressing.svg").write_text(svg, encoding="utf-8")
