#!/usr/bin/python3
"""nmmImageToBlocks on images a user may hand it by mistake, made here.

Usage:
    hostileImages.py <folder of the applications> <scratch folder>

Each image gets a correct result or a clear error: exit code 1, a FOAM
FATAL message naming system/nmmImageToBlocksDict, the keyword and the
image's file, and saying what is wrong; never a signal, a hang or
unbounded memory (each run is limited to 2 GB of address space and a
timeout, so that a regression fails here instead of taking the machine):

  - an empty file; a PNG cut short inside its image data; a JPEG, a GIF
    and a text file named grains.png (named as what they are);
  - a 16-bit grey label PNG whose labels use the high byte (256, 257,
    65535): three blocks of the right areas;
  - a palette (indexed-colour) PNG as label image: the palette indices
    are the labels (how label images with a colour table are saved),
    whatever colours the palette gives them; as binary image: its
    colours made grey, light grains;
  - all black: no grains, named as such, for a label and a binary image;
    all white (255 everywhere): one block, the image's rectangle, of the
    image's area, for a label and a binary image;
  - 20,000 x 20,000 pixels: refused from the PNG's header, before
    decoding, naming the size and the keyword maxPixels that raises the
    limit; a 3 x 3 image with maxPixels 8: refused the same way;
  - 65,535 labels (a 16-bit image of 256 x 256 pixels, one pixel each but
    pixel 0): 65,535 blocks of one pixel area each.

Exit code 0 when every check passes, 1 otherwise.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import resource
import struct
import subprocess
import sys
import time
import zlib
from pathlib import Path

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parent))
import nmmImageToBlocks as tools  # noqa: E402

PS = 1e-3


def check(ok, what):
    tools.check(ok, what)
    return ok

# Address space of one run: a decoded 20,000 x 20,000 image takes more
MEMORY_LIMIT = 2 << 30
TIMEOUT = 120


def limitMemory():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def run(case):
    start = time.monotonic()
    try:
        p = subprocess.run([str(tools.APPS/"nmmImageToBlocks"), "-case", str(case)],
                           capture_output=True, text=True, timeout=TIMEOUT,
                           preexec_fn=limitMemory)
    except subprocess.TimeoutExpired:
        return None, "", "timed out after %d s" % TIMEOUT, TIMEOUT
    return p.returncode, p.stdout, p.stderr, time.monotonic() - start


def expectError(name, case, *substrings):
    rc, out, err, seconds = run(case)
    missing = [s for s in substrings + ("FOAM FATAL", "nmmImageToBlocksDict",
                                        "keyword: ", str(case/"grains.png"))
               if s not in err]
    check(rc == 1 and not missing,
          "%s: exit 1 naming the problem (%.1f s)" % (name, seconds)
          + ("" if rc == 1 and not missing else
             " (exit code %s, missing %s)\n%s%s" % (rc, missing, out[-2000:], err)))
    return err


def expectBlocks(name, case, areas):
    """The run ends well and writes blocks of these pixel areas, by name"""
    rc, out, err, seconds = run(case)
    if not check(rc == 0, "%s: exit 0 (%.1f s)%s" % (
            name, seconds, "" if rc == 0 else ", not %s:\n%s" % (rc, err))):
        return None
    blocks = tools.read_blocks(case)
    got = {n: round(tools.block_area(b)/(PS*PS), 6) for n, b in blocks.items()}
    check(got == areas, "%s: blocks and pixel areas %s" % (
        name, areas if len(areas) < 10 else "(%d blocks)" % len(areas))
          + ("" if got == areas else ", got %s" % (got if len(got) < 10 else len(got))))
    return blocks


# ------------------------------------------------------------------ images

def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


def pngBytes(width, height, depth, colourType, rows, extra=b""):
    """A PNG of the rows (bytes each, filter byte included), compressed as
    a stream so that a large image never sits in memory whole"""
    z = zlib.compressobj(9)
    data = b"".join(z.compress(r) for r in rows) + z.flush()
    header = struct.pack(">IIBBBBB", width, height, depth, colourType, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + extra
            + chunk(b"IDAT", data) + chunk(b"IEND", b""))


def palettePng(indices, colours):
    """8-bit palette PNG: indices (2D uint8) into colours [(r, g, b)]"""
    plte = b"".join(struct.pack("BBB", *c) for c in colours)
    rows = (b"\x00" + r.astype("u1").tobytes() for r in indices)
    return pngBytes(indices.shape[1], indices.shape[0], 8, 3, rows, chunk(b"PLTE", plte))


def makeCase(name, data, **entries):
    case = tools.make_case(name, None, **entries)
    (case/"grains.png").write_bytes(data)
    return case


# ------------------------------------------------------------------- cases

def brokenFiles():
    valid = np.zeros((40, 40), np.uint8)
    valid[5:20, 5:30] = 1
    tools.write_png(tools.WORK/"valid.png", valid)
    png = (tools.WORK/"valid.png").read_bytes()

    expectError("empty file", makeCase("empty", b""), "the file is empty")
    # Cut inside the IDAT chunk: the header reads, the pixels do not
    idat = png.index(b"IDAT")
    expectError("truncated PNG", makeCase("truncated", png[:idat + 4 + 20]),
                "libpng", "cut short")
    jpeg = b"\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00" + bytes(200)
    expectError("JPEG named .png", makeCase("jpeg", jpeg), "not a PNG or TIFF",
                "it is a JPEG image")
    expectError("GIF named .png", makeCase("gif", b"GIF89a" + bytes(100)),
                "not a PNG or TIFF", "it is a GIF image")
    expectError("text named .png", makeCase("text", b"grain 1 at (3, 4)\nnot an image\n"),
                "not a PNG or TIFF", "by its content it is text")


def sixteenBit():
    img = np.zeros((6, 8), np.uint16)
    img[0:3, 0:4] = 256
    img[0:3, 4:8] = 257
    img[3:6, 2:6] = 65535
    case = tools.make_case("sixteenBit", img)
    expectBlocks("16-bit labels 256, 257, 65535", case,
                 {"grain256": 12, "grain257": 12, "grain65535": 12})


def palette():
    indices = np.zeros((6, 8), np.uint8)
    indices[1:3, 1:4] = 1
    indices[1:5, 5:7] = 2
    indices[4:6, 0:3] = 3
    # Index 1 and 3 the same colour, index 2 darker than the pore's:
    # labels are indices, not colours
    colours = [(40, 40, 40), (200, 30, 30), (0, 0, 0), (200, 30, 30)]
    case = makeCase("paletteLabels", palettePng(indices, colours))
    expectBlocks("palette PNG as label image", case,
                 {"grain1": 6, "grain2": 8, "grain3": 6})

    # As a binary image: grey of the colours, light (> 127) is grain
    bw = np.zeros((6, 8), np.uint8)
    bw[1:4, 1:4] = 1
    case = makeCase("paletteBinary", palettePng(bw, [(0, 0, 0), (250, 250, 250)]),
                    type="binary")
    expectBlocks("palette PNG as binary image", case, {"grain1": 9})


def blackAndWhite():
    black = np.zeros((30, 20), np.uint8)
    expectError("all-black label image", tools.make_case("blackLabel", black),
                "has no grains", "every pixel is 0")
    expectError("all-black binary image", tools.make_case("blackBinary", black, type="binary"),
                "has no grains", "no pixel is light")
    white = np.full((30, 20), 255, np.uint8)
    for kind in ("label", "binary"):
        blocks = expectBlocks("all-white %s image" % kind,
                              tools.make_case("white" + kind, white, type=kind),
                              {"grain255" if kind == "label" else "grain1": 600})
        if blocks:
            b = next(iter(blocks.values()))
            corners = sorted(tools.numeric(b["outer"]))
            check(corners == [(0, 0), (0, 0.03), (0.02, 0), (0.02, 0.03)] and not b["holes"],
                  "all-white %s image: the block is the image's rectangle %s" % (kind, corners))


def largeImages():
    side = 20000
    row = b"\x00" + bytes(side)
    big = makeCase("huge", pngBytes(side, side, 8, 0, (row for _ in range(side))))
    err = expectError("20,000 x 20,000 pixels", big, "20000 x 20000",
                      "400000000 pixels", "maxPixels")
    check("keyword: maxPixels" in err or "keyword: image" in err,
          "20,000 x 20,000 pixels: the error points at image or maxPixels")

    small = np.zeros((3, 3), np.uint8)
    small[1, 1] = 1
    expectError("3 x 3 pixels, maxPixels 8", tools.make_case("overLimit", small, maxPixels="8"),
                "3 x 3", "9 pixels", "maxPixels 8")
    expectBlocks("3 x 3 pixels, maxPixels 9", tools.make_case("atLimit", small, maxPixels="9"),
                 {"grain1": 1})


def manyLabels():
    img = np.arange(256*256, dtype=np.uint32).reshape(256, 256).astype(np.uint16)
    case = tools.make_case("manyLabels", img)
    rc, out, err, seconds = run(case)
    if not check(rc == 0, "65,535 labels: exit 0 (%.1f s)%s" % (
            seconds, "" if rc == 0 else ", not %s:\n%s" % (rc, err[-2000:]))):
        return
    blocks = tools.read_blocks(case)
    areas = {round(tools.block_area(b)/(PS*PS), 6) for b in blocks.values()}
    check(len(blocks) == 65535 and areas == {1.0},
          "65,535 labels: %d blocks of pixel areas %s" % (len(blocks), sorted(areas)[:5]))
    check("grain65535" in blocks and "grain1" in blocks and "grain0" not in blocks,
          "65,535 labels: named grain1 .. grain65535")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    tools.APPS, tools.WORK = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
    tools.WORK.mkdir(parents=True, exist_ok=True)
    brokenFiles()
    sixteenBit()
    palette()
    blackAndWhite()
    largeImages()
    manyLabels()
    failures = tools.failures
    print("\n%d failure%s" % (len(failures), "" if len(failures) == 1 else "s"))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
