#!/usr/bin/python3
"""Make sandGrains.png: a binary image of a loose sand packing.

Usage:
    ./makeImage.py [--seed N] [--output sandGrains.png] [--size PIXELS]
                   [--grains N]

The picture is 400 x 400 pixels of 2.5 um, a 1 mm x 1 mm domain, grains
white (255) on black pore (0): the input of nmmImageToBlocks with
'type binary; pixelSize 2.5e-6;'. --size and --grains (default 400 and
40) make a larger packing of the same sand: 1800 pixels (4.5 mm) and 600
grains, all placed, make sandGrainsLarge.png (the tutorial's large run).

Each grain is convex: a core polygon (the convex hull of 5 to 11 points
on a randomly stretched and turned ellipse) grown by a disc of radius
rho (the Minkowski sum), so rho = 0 gives an angular grain with sharp
corners and a larger rho a rounded one. Equivalent diameters are drawn
between 120 and 250 um, the larger more seldom. The grains are placed
largest first by random sequential addition: a grain is tried at random
positions until it keeps at least 2 pore pixels from every grain placed
and from the image's border (so that every grain is its own 4-connected
region and none touches the border), and is skipped after too many
tries. The placing stops at 40 grains (--grains). In an image larger
than 400 pixels the positions are looked for in a window of 400 x 400
pixels at a random place, a few windows before the whole image: the
search is a correlation over the window, which over the whole of a
large image would take minutes. The porosity of such a packing is
about 0.45: loose, as poured sand, before compaction.

Everything random comes from Python's random.Random(seed), whose stream
is the same on every machine and Python 3 version, so the same seed
gives the same image. numpy only rasterises; it is Debian's
python3-numpy, hence /usr/bin/python3 (a python3 elsewhere on the PATH
may lack it). The PNG is written with zlib and struct.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import random
import struct
import zlib
from pathlib import Path

import numpy as np

SIZE = 400              # pixels a side
PIXEL = 2.5e-6          # m
GAP = 2                 # pore pixels kept between grains and to the border
CANDIDATES = 40         # grain sizes drawn; those that find no room are left out
WINDOW = 400            # pixels a side of the windows a large image is searched in
WINDOW_TRIES = 8        # windows tried before the whole image


def convex_hull(points):
    """Andrew's monotone chain; counter-clockwise, no repeated end"""
    points = sorted(points)

    def half(seq):
        h = []
        for p in seq:
            while len(h) >= 2 and ((h[-1][0] - h[-2][0])*(p[1] - h[-2][1])
                                   - (h[-1][1] - h[-2][1])*(p[0] - h[-2][0])) <= 0:
                h.pop()
            h.append(p)
        return h[:-1]

    return half(points) + half(reversed(points))


def grain_shape(rng, diameter):
    """(core polygon about (0, 0), rho) in pixels, of the given
    equivalent diameter (the area of the core grown by rho is
    A + P rho + pi rho^2 for a convex core of area A and perimeter P)"""
    angular = rng.random() < 0.4
    rho = 0.0 if angular else rng.uniform(0.15, 0.45)*diameter/2
    stretch = rng.uniform(1.0, 1.5)
    turn = rng.uniform(0, math.pi)
    n = rng.randint(5, 11)
    points = []
    for k in range(n):
        t = 2*math.pi*(k + rng.uniform(-0.35, 0.35))/n
        r = rng.uniform(0.85, 1.1)
        x, y = r*math.sqrt(stretch)*math.cos(t), r/math.sqrt(stretch)*math.sin(t)
        points.append((x*math.cos(turn) - y*math.sin(turn), x*math.sin(turn) + y*math.cos(turn)))
    core = convex_hull(points)
    edges = list(zip(core, core[1:] + core[:1]))
    area = 0.5*sum(ax*by - bx*ay for (ax, ay), (bx, by) in edges)
    perimeter = sum(math.hypot(bx - ax, by - ay) for (ax, ay), (bx, by) in edges)
    # Scale s of the core: area s^2 + perimeter rho s + pi rho^2 = target
    target = math.pi*diameter*diameter/4
    b, c = perimeter*rho, math.pi*rho*rho - target
    scale = (-b + math.sqrt(b*b - 4*area*c))/(2*area)
    return [(scale*x, scale*y) for x, y in core], rho


def rasterise(core, rho, cx, cy):
    """Boolean mask of the grain (core grown by rho) centred at pixel
    coordinates (cx, cy), and the row and column of its corner"""
    reach = max(math.hypot(x, y) for x, y in core) + rho + 1
    r0, c0 = int(math.floor(cy - reach)), int(math.floor(cx - reach))
    n = int(2*reach) + 3
    y, x = np.mgrid[r0:r0 + n, c0:c0 + n] + 0.5       # pixel centres
    x, y = x - cx, y - cy
    inside = np.ones(x.shape, bool)
    distance = np.full(x.shape, np.inf)
    for (ax, ay), (bx, by) in zip(core, core[1:] + core[:1]):
        ex, ey = bx - ax, by - ay
        # The hull turns counter-clockwise: inside is left of every edge
        inside &= ex*(y - ay) - ey*(x - ax) >= 0
        t = np.clip(((x - ax)*ex + (y - ay)*ey)/(ex*ex + ey*ey), 0, 1)
        distance = np.minimum(distance, np.hypot(x - ax - t*ex, y - ay - t*ey))
    return inside | (distance <= rho), r0, c0


def grow(mask, radius):
    """Binary dilation by a disc of the given radius (pixels)"""
    out = np.zeros((mask.shape[0] + 2*radius, mask.shape[1] + 2*radius), bool)
    for dr in range(-radius, radius + 1):
        for dc in range(-radius, radius + 1):
            if dr*dr + dc*dc <= radius*radius:
                out[radius + dr:radius + dr + mask.shape[0],
                    radius + dc:radius + dc + mask.shape[1]] |= mask
    return out


def free_spots(region, halo):
    """Offsets (r, c) of the halo inside the region, one pixel off its
    edges, where it meets no grain: the grain pixels under it at every
    offset by FFT correlation (integers, rounding far below 1/2)"""
    size = region.shape[0]
    h, w = halo.shape
    if h > size - 2 or w > size - 2:
        return None
    shape = (2*size, 2*size)
    under = np.fft.irfft2(np.fft.rfft2(region, shape)*np.conj(np.fft.rfft2(halo, shape)), shape)
    return under[1:size - h, 1:size - w] < 0.5


def place(rng, image, mask):
    """Put the mask at a random position where it fits; False if none"""
    # A pixel within GAP + 1 (Euclidean) of a grain is too close: grown
    # by that, the mask must meet no grain and stay off the border
    halo = grow(mask, GAP + 1)
    size = image.shape[0]
    windows = [(0, 0, size)] if size <= WINDOW else \
        [(rng.randrange(size - WINDOW + 1), rng.randrange(size - WINDOW + 1), WINDOW)
         for _ in range(WINDOW_TRIES)] + [(0, 0, size)]
    for r0, c0, n in windows:
        free = free_spots(image[r0:r0 + n, c0:c0 + n], halo)
        spots = np.flatnonzero(free) if free is not None else np.empty(0)
        if spots.size:
            break
    if spots.size == 0:
        return False
    r, c = divmod(int(spots[rng.randrange(spots.size)]), free.shape[1])
    r, c = r0 + r + 1, c0 + c + 1
    m = GAP + 1
    image[r + m:r + m + mask.shape[0], c + m:c + m + mask.shape[1]] |= mask
    return True


def write_png(path, grey):
    raw = b"".join(b"\x00" + row.tobytes() for row in grey.astype(np.uint8))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", grey.shape[1], grey.shape[0], 8, 0, 0, 0, 0)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
                           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=2024)
    parser.add_argument("--output", default=str(Path(__file__).with_name("sandGrains.png")))
    parser.add_argument("--size", type=int, default=SIZE, help="pixels a side")
    parser.add_argument("--grains", type=int, default=CANDIDATES,
                        help="grain sizes drawn (those that find no room are left out)")
    args = parser.parse_args()
    if args.size < 50 or args.grains < 1:
        parser.error("--size is at least 50 pixels and --grains at least 1")

    rng = random.Random(args.seed)
    # Equivalent diameters 120-250 um, the large ones fewer (120 + 130 u^4
    # um, u uniform), placed largest first
    diameters = sorted((120e-6 + 130e-6*rng.random()**4 for _ in range(args.grains)),
                       reverse=True)
    size = args.size
    image = np.zeros((size, size), bool)
    placed = []
    for d in diameters:
        core, rho = grain_shape(rng, d/PIXEL)
        mask, _, _ = rasterise(core, rho, 0.0, 0.0)
        if place(rng, image, mask):
            placed.append((2*math.sqrt(mask.sum()/math.pi)*PIXEL, rho > 0))

    write_png(args.output, np.where(image, 255, 0))
    sizes = [d*1e6 for d, _ in placed]
    print("%s: %d x %d pixels of %g m, %d grains (%d angular), equivalent "
          "diameters %.0f-%.0f um, porosity %.3f"
          % (args.output, size, size, PIXEL, len(placed),
             sum(1 for _, rounded in placed if not rounded),
             min(sizes), max(sizes), 1 - image.mean()))


if __name__ == "__main__":
    main()
