#!/usr/bin/python3
"""Test nmmImageToBlocks on small images made here.

Usage:
    nmmImageToBlocks.py <folder of the applications> <scratch folder>

Images are written with the standard library only (zlib + struct: 8- and
16-bit grey PNGs, uncompressed 16- and 32-bit TIFFs); numpy builds them.
Each case is a scratch case folder; the written block list is parsed with
regular expressions and checked against values counted by hand:

  - two rectangles of labels sharing an edge (16-bit PNG): 2 blocks, the
    upper picture rows at high y, areas = pixels * pixelSize^2, the shared
    edge's vertices (with the T-junction) the same strings in both;
  - a ring (8-bit PNG): one block with one hole, area exact; with a
    grain in the hole: that grain's polygon is the ring's hole;
  - checkerboard corners: four labels meeting at a corner, two labels
    diagonally (4 pieces, grain1_1 ...), areas exact; a grain touching
    itself at a corner (opened: 1/16 pixel^2 less, no hole);
  - binary images: two blobs -> 2 blocks; the threshold at half the
    range; dropBorderGrains and minGrainArea drop what they should and
    say so;
  - TIFF label images (16 and 32 bit): names and areas; a binary TIFF
    stored 'min-is-white';
  - simplification of a disc of radius 20 pixels split between two
    labels by a wavy line, at 1.5 pixels: far fewer vertices than the
    staircase, area within 3 % (each block 5 %), every simplified vertex on the staircase
    and every staircase vertex within the tolerance of the simplified
    boundary, the shared boundary identical in both blocks;
  - repeatable: sandCompaction's 600-grain image, simplified at 1.2
    pixels, traced three times with the memory allocator laid out
    otherwise (GLIBC_TUNABLES: mmap threshold, top pad) gives the same
    block list, byte for byte. CGAL's simplification had taken equal
    costs in an order set by memory addresses: 6,688 and 6,702 vertices
    from this image, and other outlines from a case folder of another
    name;
  - file-name tags: image "<constant>/coins.png", output
    "<constant>/geometry/tagged" and the same with $FOAM_CASE are the
    case's files (a relative name is relative to the case);
  - nmmMesh accepts the written lists through
    blocks ( #include "<constant>/geometry/grains" ); (ends "Mesh OK.");
  - broken input exits 1 naming the problem: missing image, garbage
    bytes, a corrupt PNG, an RGB PNG as label image, an all-zero image,
    every grain dropped, pixelSize 0, a misspelt keyword, an unknown
    type; -help lists the keywords.

Exit code 0 when every check passes, 1 otherwise.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import re
import shutil
import struct
import subprocess
import sys
import zlib
from pathlib import Path

import numpy as np

failures = []


def check(cond, what):
    print("%s: %s" % ("ok  " if cond else "FAIL", what))
    if not cond:
        failures.append(what)


# ---------------------------------------------------------------- images

def write_png(path, image, colour_type=0):
    """Grey (colour type 0) PNG of a 2D uint8 or uint16 array; an
    (n, m, 3) uint8 array with colour_type 2 is RGB."""
    image = np.asarray(image)
    depth = 16 if image.dtype == np.uint16 else 8
    raw = b"".join(b"\x00" + row.astype(">u2" if depth == 16 else "u1").tobytes()
                   for row in image)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", image.shape[1], image.shape[0], depth,
                         colour_type, 0, 0, 0)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
                           + chunk(b"IDAT", zlib.compress(raw))
                           + chunk(b"IEND", b""))


def write_tiff(path, image, photometric=1):
    """Uncompressed little-endian one-strip grey TIFF of a 2D uint8,
    uint16 or uint32 array; photometric 1: 0 is black, 0: 0 is white"""
    image = np.asarray(image)
    bits = image.dtype.itemsize*8
    data = image.astype("<u%d" % image.dtype.itemsize).tobytes()
    rows, cols = image.shape
    tags = [  # (tag, type, value): type 3 SHORT, 4 LONG
        (256, 4, cols), (257, 4, rows), (258, 3, bits), (259, 3, 1),
        (262, 3, photometric), (273, 4, 8), (277, 3, 1), (278, 4, rows),
        (279, 4, len(data)), (339, 3, 1)]
    ifd = struct.pack("<H", len(tags))
    for tag, kind, value in tags:
        packed = struct.pack("<H", value) + b"\0\0" if kind == 3 else struct.pack("<I", value)
        ifd += struct.pack("<HHI", tag, kind, 1) + packed
    ifd += struct.pack("<I", 0)
    Path(path).write_bytes(b"II*\0" + struct.pack("<I", 8 + len(data)) + data + ifd)


# ----------------------------------------------------------------- cases

APPS = None
WORK = None
FOAM_HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      %s;
}
"""


def make_case(name, image, writer=write_png, file_name="grains.png", **entries):
    """A case with the image and system/nmmImageToBlocksDict; entries
    override the defaults (None leaves a keyword out)."""
    case = WORK/name
    shutil.rmtree(case, ignore_errors=True)
    (case/"system").mkdir(parents=True)
    if image is not None:
        writer(case/file_name, image)
    settings = {"image": '"%s"' % file_name, "type": "label", "pixelSize": "0.001",
                "simplifyTolerance": "0", "material": "sand"}
    settings.update(entries)
    text = FOAM_HEADER % "nmmImageToBlocksDict" + "".join(
        "%s %s;\n" % (k, v) for k, v in settings.items() if v is not None)
    (case/"system"/"nmmImageToBlocksDict").write_text(text)
    return case


def run(app, case, *extra, env=None):
    p = subprocess.run([str(APPS/app), "-case", str(case), *extra],
                       capture_output=True, text=True, env=env)
    return p.returncode, p.stdout, p.stderr


LOOP = re.compile(r"\(((?:\([^()]*\)\s*)+)\)")
POINT = re.compile(r"\(([^()\s]+) ([^()\s]+)\)")
BLOCK = re.compile(r"^(\S+) \{ material (\S+); polygon (\(.*?\));(?: holes \((.*)\);)? \}$")


def points_of(text):
    return [(a, b) for a, b in POINT.findall(text)]


def read_blocks(case, output="grains"):
    """name -> {material, outer, holes}, points as (x, y) strings"""
    blocks = {}
    for line in (case/"constant"/"geometry"/output).read_text().splitlines():
        if line.startswith("//") or not line.strip():
            continue
        m = BLOCK.match(line)
        if not m:
            raise ValueError("unreadable block line: " + line)
        holes = [points_of(h) for h in LOOP.findall(m.group(4))] if m.group(4) else []
        blocks[m.group(1)] = {"material": m.group(2), "outer": points_of(m.group(3)),
                              "holes": holes}
    return blocks


def numeric(loop):
    return [(float(x), float(y)) for x, y in loop]


def area(loop):
    p = numeric(loop)
    return 0.5*abs(sum(p[i][0]*p[(i + 1) % len(p)][1] - p[(i + 1) % len(p)][0]*p[i][1]
                       for i in range(len(p))))


def block_area(b):
    return area(b["outer"]) - sum(area(h) for h in b["holes"])


def close(a, b, rel=1e-12):
    return abs(a - b) <= rel*max(abs(a), abs(b))


def segment_distance(p, a, b):
    ax, ay = a
    bx, by = b
    px, py = p
    dx, dy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((px - ax)*dx + (py - ay)*dy)/(dx*dx + dy*dy)))
    return math.hypot(px - ax - t*dx, py - ay - t*dy)


def boundary_distance(p, loops):
    return min(segment_distance(p, q[i], q[(i + 1) % len(q)])
               for q in (numeric(l) for l in loops) for i in range(len(q)))


def on_boundary(loop, other_loops, eps):
    """The vertices of loop (as strings) on the other block's boundary"""
    return {v for v in loop if boundary_distance((float(v[0]), float(v[1])), other_loops) < eps}


def all_loops(b):
    return [b["outer"]] + b["holes"]


# ----------------------------------------------------------------- tests

PS = 0.001


def test_shared_edge():
    img = np.zeros((6, 8), np.uint16)
    img[1:3, 1:4] = 300         # 6 pixels, top rows
    img[1:5, 4:7] = 7000        # 12 pixels
    case = make_case("sharedEdge", img)
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "two rectangles: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc:
        return
    b = read_blocks(case)
    check(sorted(b) == ["grain300", "grain7000"], "two rectangles: blocks grain300, grain7000")
    check(close(block_area(b["grain300"]), 6*PS*PS) and close(block_area(b["grain7000"]), 12*PS*PS),
          "two rectangles: areas 6 and 12 pixels")
    ys = [y for _, y in numeric(b["grain300"]["outer"])]
    check(close(min(ys), 3*PS) and close(max(ys), 5*PS),
          "two rectangles: row 0 is the top (grain300 spans y = 3..5 pixels)")
    s1 = on_boundary(b["grain300"]["outer"], all_loops(b["grain7000"]), 1e-9)
    s2 = on_boundary(b["grain7000"]["outer"], all_loops(b["grain300"]), 1e-9)
    check(s1 == s2 and len(s1) == 2, "two rectangles: the shared edge's vertices are the "
          "same strings in both blocks: %s" % sorted(s1))
    check(len(b["grain300"]["outer"]) == 4 and len(b["grain7000"]["outer"]) == 5,
          "two rectangles: straight runs merged, T-junction kept (4 and 5 vertices)")
    check("grains.png" in out and (case/"constant/geometry/grains.png").is_file(),
          "two rectangles: preview written")
    return case


def test_ring():
    img = np.zeros((9, 9), np.uint8)
    img[1:8, 1:8] = 5
    img[3:6, 3:6] = 0
    case = make_case("ring", img)
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "ring: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(list(b) == ["grain5"] and len(b["grain5"]["holes"]) == 1,
              "ring: one block with one hole")
        check(close(block_area(b["grain5"]), 40*PS*PS), "ring: area 49 - 9 pixels")

    img[3:6, 3:6] = 6
    case = make_case("ringFilled", img)
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "ring around a grain: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(len(b["grain5"]["holes"]) == 1
              and set(b["grain5"]["holes"][0]) == set(b["grain6"]["outer"]),
              "ring around a grain: the ring's hole is the inner grain's polygon")
        check(close(block_area(b["grain6"]), 9*PS*PS), "ring around a grain: inner area 9 pixels")
    return case


def test_checkerboard():
    img = np.array([[1, 1, 2, 2], [1, 1, 2, 2], [3, 3, 4, 4], [3, 3, 4, 4]], np.uint8)
    case = make_case("fourLabels", img)
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "four labels at a corner: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(sorted(b) == ["grain1", "grain2", "grain3", "grain4"]
              and all(close(block_area(x), 4*PS*PS) for x in b.values()),
              "four labels at a corner: 4 blocks of 4 pixels")

    img = np.array([[1, 1, 2, 2], [1, 1, 2, 2], [2, 2, 1, 1], [2, 2, 1, 1]], np.uint8)
    case = make_case("checkerboard", img)
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "checkerboard of two labels: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(sorted(b) == ["grain1_1", "grain1_2", "grain2_1", "grain2_2"]
              and all(close(block_area(x), 4*PS*PS) for x in b.values()),
              "checkerboard of two labels: 4 pieces (4-connected) of 4 pixels each")
        check("label 1 in pieces" in out and "grain1_1 grain1_2" in out,
              "checkerboard of two labels: the log names the pieces")
        check(all(any(close(x, 2*PS) and close(y, 2*PS) for x, y in numeric(g["outer"]))
                  for g in b.values()),
              "checkerboard of two labels: all four touch at the centre vertex")

    # A grain that touches itself at a corner: row 1 col 3 and row 2 col 4
    img = np.zeros((6, 6), np.uint8)
    img[1, 1:4] = 255
    img[1:5, 1] = 255
    img[4, 1:5] = 255
    img[2:5, 4] = 255
    case = make_case("pinch", img, type="binary")
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "grain touching itself at a corner: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(list(b) == ["grain1"] and not b["grain1"]["holes"]
              and close(block_area(b["grain1"]), (11 - 1/16)*PS*PS),
              "grain touching itself at a corner: opened (no hole, 11 - 1/16 pixels), "
              "area %.6g pixels" % (block_area(b["grain1"])/PS/PS if b else 0))
        check(re.search(r"corners opened:\s+1\b", out) is not None,
              "grain touching itself at a corner: the log counts 1 opened corner")
    return case


def test_binary():
    img = np.zeros((20, 20), np.uint8)
    img[2:6, 2:6] = 255         # 16 pixels
    img[10:13, 10:13] = 200     # 9 pixels
    img[17, 10] = 127           # below half the range: pore
    case = make_case("twoBlobs", img, type="binary")
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "binary, two blobs: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(sorted(b) == ["grain1", "grain2"] and close(block_area(b["grain1"]), 16*PS*PS)
              and close(block_area(b["grain2"]), 9*PS*PS),
              "binary, two blobs: 2 blocks of 16 and 9 pixels (127 of 255 is dark)")

    img[0:3, 15:18] = 255       # on the border: first in row-major order
    img[17, 3] = 128            # one pixel, light (above 127.5)
    case = make_case("filters", img, type="binary", dropBorderGrains="yes",
                     minGrainArea="%g" % (1.5*PS*PS))
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "binary, filters: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(sorted(b) == ["grain2", "grain3"],
              "binary, filters: the border blob (grain1) and the one-pixel grain4 dropped")
        check(re.search(r"dropped at the border:\s+1 \(grain1\)", out) is not None
              and re.search(r"dropped below minGrainArea:\s+1 \(grain4\)", out) is not None,
              "binary, filters: the log says which filter dropped what")
    case = make_case("noFilters", img, type="binary")
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0 and sorted(read_blocks(case)) == ["grain1", "grain2", "grain3", "grain4"],
          "binary, no filters: 4 blocks")


def test_tiff():
    img = np.zeros((5, 7), np.uint32)
    img[1:4, 1:3] = 100000
    img[1:4, 3:6] = 4000000000
    case = make_case("tiff32", img, writer=write_tiff, file_name="labels.tif")
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0, "32-bit TIFF: exit 0" + ("" if rc == 0 else "\n" + out + err))
    if rc == 0:
        b = read_blocks(case)
        check(sorted(b) == ["grain100000", "grain4000000000"]
              and close(block_area(b["grain100000"]), 6*PS*PS)
              and close(block_area(b["grain4000000000"]), 9*PS*PS),
              "32-bit TIFF: labels above 65535, areas 6 and 9 pixels")
    img16 = np.zeros((5, 7), np.uint16)
    img16[1:4, 1:6] = 42
    case = make_case("tiff16", img16, writer=write_tiff, file_name="labels.tif")
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0 and list(read_blocks(case)) == ["grain42"]
          and close(block_area(read_blocks(case)["grain42"]), 15*PS*PS),
          "16-bit TIFF: one label of 15 pixels")
    # Binary, stored 'min-is-white': the grain is the low values
    white = np.full((5, 7), 255, np.uint8)
    white[1:3, 2:6] = 0
    case = make_case("tiffMinIsWhite", white, type="binary", file_name="binary.tif",
                     writer=lambda p, a: write_tiff(p, a, photometric=0))
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc == 0 and list(read_blocks(case)) == ["grain1"]
          and close(block_area(read_blocks(case)["grain1"]), 8*PS*PS),
          "8-bit min-is-white binary TIFF: one grain of 8 pixels")


def disc_image(n=64, radius=20):
    y, x = np.mgrid[0:n, 0:n] + 0.5
    inside = (x - n/2)**2 + (y - n/2)**2 <= radius**2
    img = np.zeros((n, n), np.uint8)
    # Two labels split by a wavy line
    img[inside] = np.where(x[inside] < n/2 + 4*np.sin(y[inside]/4), 1, 2)
    return img


def test_simplification():
    img = disc_image()
    pixels = {1: int((img == 1).sum()), 2: int((img == 2).sum())}
    stair = make_case("discStaircase", img)
    rc0, out0, err0 = run("nmmImageToBlocks", stair)
    case = make_case("disc", img, simplifyTolerance="%.17g" % (1.5*PS))
    rc, out, err = run("nmmImageToBlocks", case)
    check(rc0 == 0 and rc == 0, "disc: exit 0" + ("" if rc == 0 and rc0 == 0 else "\n" + out0 + err0 + out + err))
    if rc or rc0:
        return
    b0, b = read_blocks(stair), read_blocks(case)
    for g in ("grain1", "grain2"):
        n0, n = len(b0[g]["outer"]), len(b[g]["outer"])
        check(close(block_area(b0[g]), pixels[int(g[-1])]*PS*PS),
              "disc %s: staircase area exact (%d pixels)" % (g, pixels[int(g[-1])]))
        check(n*3 < n0, "disc %s: %d vertices simplified, %d on the staircase" % (g, n, n0))
        # Chords of a convex arc lie inside it: at most about (4/3)(1.5/20)
        # = 10 % less, and the wavy boundary moves area between the two
        rel = abs(block_area(b[g]) - pixels[int(g[-1])]*PS*PS)/(pixels[int(g[-1])]*PS*PS)
        check(rel < 0.05, "disc %s: area within 5 %% of the pixels' (%.2g)" % (g, rel))
        worst = max(boundary_distance(p, all_loops(b[g])) for p in numeric(b0[g]["outer"]))
        check(worst <= 1.5*PS*(1 + 1e-9),
              "disc %s: every staircase vertex within the tolerance of the simplified "
              "boundary (%.3g pixel)" % (g, worst/PS))
        off = max(boundary_distance(p, all_loops(b0[g])) for p in numeric(b[g]["outer"]))
        check(off < 1e-9*PS, "disc %s: every simplified vertex lies on the staircase "
              "(pixel corners and edge midpoints)" % g)
    total = block_area(b["grain1"]) + block_area(b["grain2"])
    rel = abs(total - (pixels[1] + pixels[2])*PS*PS)/((pixels[1] + pixels[2])*PS*PS)
    check(rel < 0.03, "disc: area of both within 3 %% of the pixels' (%.2g)" % rel)
    s1 = on_boundary(b["grain1"]["outer"], all_loops(b["grain2"]), 1e-9)
    s2 = on_boundary(b["grain2"]["outer"], all_loops(b["grain1"]), 1e-9)
    check(s1 == s2 and len(s1) >= 3, "disc: the shared wavy boundary has the same %d "
          "vertices in both blocks" % len(s1))
    return case


def test_repeatable():
    image = Path(__file__).resolve().parents[2]/"tutorials/paper/sandCompaction/sandGrainsLarge.png"
    case = make_case("repeatable", None, file_name=image.name, type="binary",
                     pixelSize="2.5e-6", simplifyTolerance="3e-6")
    shutil.copy(image, case/image.name)
    texts = []
    for tunables in ("", "glibc.malloc.mmap_threshold=4096", "glibc.malloc.top_pad=67108864"):
        code, out, err = run("nmmImageToBlocks", case,
                             env=dict(os.environ, GLIBC_TUNABLES=tunables))
        check(code == 0, "repeatable: exit 0 with GLIBC_TUNABLES '%s'" % tunables
              + ("" if code == 0 else "\n" + out + err))
        texts.append((case/"constant"/"geometry"/"grains").read_text() if code == 0 else None)
    grains = texts[0].count("material") if texts[0] else 0
    check(texts[0] is not None and texts.count(texts[0]) == 3 and grains == 600,
          "repeatable: the same %d blocks, whatever the allocator's layout" % grains)


def test_mesh(cases):
    """nmmMesh reads the lists through #include, whose path is relative
    to the including file's folder (system/), so these forms work."""
    forms = ['"<constant>/geometry/grains"', '"$FOAM_CASE/constant/geometry/grains"',
             '"../constant/geometry/grains"']
    for case in cases:
        if case is None:
            continue
        for form in forms:
            (case/"system"/"nmmMeshDict").write_text(
                FOAM_HEADER % "nmmMeshDict" + "blocks ( #include %s );\n" % form
                + "cover { type structured; cellSize %g; }\n" % (2.1*PS))
            rc, out, err = run("nmmMesh", case, "-check")
            check(rc == 0 and "Mesh OK." in out,
                  "nmmMesh on %s with #include %s: Mesh OK." % (case.name, form)
                  + ("" if rc == 0 else "\n" + out[-1500:] + err))


def test_random_meshes(n=60):
    """Traced Voronoi label images (6 grains, 24 x 24 pixels, seeds 0 to
    n-1) mesh with covers whose cells are not whole pixels: every case
    ends with "Mesh OK.". Traced edges run along pixel rows and diagonals,
    so they often lie within rounding of a cover line; seeds 5, 35, 55
    and 56 once gave an element of zero area there."""
    bad = []
    for k in range(n):
        rng = np.random.default_rng(k)
        seeds = rng.uniform(0, 24, size=(6, 2))
        yy, xx = np.mgrid[0:24, 0:24]
        d = (yy[..., None] - seeds[:, 1])**2 + (xx[..., None] - seeds[:, 0])**2
        image = (np.argmin(d, axis=2) + 1).astype(np.uint16)
        case = make_case("random%d" % k, image, pixelSize="0.001",
                         simplifyTolerance=["0", "0.0015", "0.001"][k % 3])
        rc, out, err = run("nmmImageToBlocks", case)
        if rc != 0:
            bad.append("%d (tracing: %s)" % (k, err[-200:]))
            continue
        (case/"system"/"nmmMeshDict").write_text(
            FOAM_HEADER % "nmmMeshDict" + 'blocks ( #include "<constant>/geometry/grains" );\n'
            + "cover { type structured; cellSize %s; }\n" % ["0.0021", "0.003", "0.002"][k % 3])
        rc, out, err = run("nmmMesh", case, "-check")
        if rc != 0 or "Mesh OK." not in out:
            bad.append("%d (%s)" % (k, [l for l in out.splitlines() if "***" in l]))
    check(not bad, "%d random traced images mesh OK%s" % (n, "" if not bad else ": not " + ", ".join(bad)))


def set_image(case, image):
    """The case with its dictionary's image entry replaced by image"""
    d = case/"system"/"nmmImageToBlocksDict"
    d.write_text(d.read_text().replace('image "grains.png";', "image %s;" % image))
    return case


def test_case_tags():
    """OpenFOAM's file-name tags: image "<constant>/coins.png" and output
    "<constant>/geometry/tagged" are the case's constant/ files, and
    "$FOAM_CASE/..." the same; a relative name stays relative to the case."""
    img = np.zeros((4, 6), np.uint8)
    img[1:3, 1:3] = 1
    img[1:3, 3:5] = 2           # two grains of 4 pixels each
    for name, image, output in (
            ("caseTags", '"<constant>/coins.png"', '"<constant>/geometry/tagged"'),
            ("foamCase", '"$FOAM_CASE/constant/coins.png"', '"${FOAM_CASE}/constant/geometry/tagged"'),
            ("relative", '"constant/coins.png"', "tagged")):
        case = set_image(make_case(name, None, output=output), image)
        (case/"constant").mkdir()
        write_png(case/"constant"/"coins.png", img)
        rc, out, err = run("nmmImageToBlocks", case)
        check(rc == 0, "%s: image %s read, exit 0" % (name, image)
              + ("" if rc == 0 else "\n" + out + err))
        if rc:
            continue
        b = read_blocks(case, "tagged")
        check(sorted(b) == ["grain1", "grain2"]
              and all(close(block_area(g), 4*PS*PS) for g in b.values()),
              "%s: output %s is constant/geometry/tagged with the two grains" % (name, output))
        check((case/"constant"/"geometry"/"tagged.png").is_file()
              and not (case/"constant"/"geometry"/"<constant>").exists(),
              "%s: preview constant/geometry/tagged.png, no literal '<constant>' folder" % name)
    # A tag that is not the case's stays literal, so the file is not found
    case = set_image(make_case("otherTag", None), '"<etc>/coins.png"')
    expect_error("an unknown tag", case, "<etc>/coins.png")


def expect_error(name, case, *substrings):
    rc, out, err = run("nmmImageToBlocks", case)
    missing = [s for s in substrings if s not in err]
    check(rc == 1 and not missing and "FOAM FATAL" in err,
          "%s: exit 1 naming the problem" % name
          + ("" if rc == 1 and not missing else " (rc %d, missing %s)\n%s" % (rc, missing, err)))


def test_errors():
    img = np.zeros((4, 4), np.uint8)
    img[1:3, 1:3] = 1
    case = make_case("missingImage", None)
    expect_error("missing image", case, "cannot read the image", "grains.png",
                 "No such file", "keyword: image", "nmmImageToBlocksDict")

    case = make_case("garbage", None)
    (case/"grains.png").write_bytes(bytes(range(256))*4)
    expect_error("garbage bytes", case, "not a PNG or TIFF", "keyword: image")

    case = make_case("corruptPng", None)
    (case/"grains.png").write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(range(200)))
    expect_error("corrupt PNG", case, "libpng", "keyword: image")

    case = make_case("rgbLabels", np.zeros((4, 4, 3), np.uint8),
                     writer=lambda p, a: write_png(p, a.reshape(4, 12), colour_type=2))
    expect_error("RGB PNG as label image", case, "one grey channel", "RGB", "keyword: image")

    case = make_case("allZero", np.zeros((4, 4), np.uint16))
    expect_error("all-zero label image", case, "has no grains", "every pixel is 0",
                 "keyword: image")

    case = make_case("allDropped", img, dropBorderGrains="yes", minGrainArea="%g" % (5*PS*PS))
    expect_error("every grain dropped", case, "every grain of the image is dropped",
                 "0 touch the image's border", "1 are smaller than minGrainArea",
                 "keyword: minGrainArea")
    border = np.zeros((4, 4), np.uint8)
    border[0, 0:2] = 1
    case = make_case("allOnBorder", border, dropBorderGrains="yes")
    expect_error("every grain on the border", case, "every grain of the image is dropped",
                 "1 touch the image's border", "keyword: dropBorderGrains")

    case = make_case("zeroPixel", img, pixelSize="0")
    expect_error("pixelSize 0", case, "out of range", "pixelSize")
    case = make_case("negativePixel", img, pixelSize="-1e-3")
    expect_error("negative pixelSize", case, "out of range", "pixelSize")

    case = make_case("misspelt", img, pixelSize=None, pixelSise="0.001")
    expect_error("misspelt keyword", case, "pixelSise", "did you mean 'pixelSize'")

    case = make_case("badType", img, type="labels")
    expect_error("unknown type", case, "'labels' is not a valid choice", "label", "binary")

    case = make_case("noTolerance", img, simplifyTolerance=None)
    expect_error("missing simplifyTolerance", case, "simplifyTolerance")

    p = subprocess.run([str(APPS/"nmmImageToBlocks"), "-help"], capture_output=True, text=True)
    check(p.returncode == 0 and all(k in p.stdout for k in (
        "image", "type", "pixelSize", "simplifyTolerance", "minGrainArea",
        "dropBorderGrains", "material", "output")), "-help lists every keyword")


def main():
    global APPS, WORK
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    APPS, WORK = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
    WORK.mkdir(parents=True, exist_ok=True)

    mesh_cases = [test_shared_edge(), test_ring(), test_checkerboard()]
    test_binary()
    test_tiff()
    mesh_cases.append(test_simplification())
    test_case_tags()
    test_repeatable()
    if (APPS/"nmmMesh").exists():
        test_mesh(mesh_cases)
        test_random_meshes()
    else:
        check(False, "nmmMesh is in " + str(APPS))
    test_errors()

    print("\n%d failure%s" % (len(failures), "" if len(failures) == 1 else "s"))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
