#!/usr/bin/python3
"""Checks nmmPlatelets on small cases:

    nmmPlatelets.py <folder of the applications> <scratch folder>

  - 'number' platelets are written (names <namePrefix>0.., the material);
  - rectangles: area = length*thickness (thickness = length/aspectRatio)
    to rounding (1e-12 relative); ellipses: the area of the inscribed
    n-gon, (n/2) a b sin(2 pi/n), to 1e-12;
  - with lengthSpread, each rectangle's length lies in
    length*(1 +- lengthSpread) and its sides keep aspectRatio;
  - no two platelets overlap or come closer than minGap (distances
    computed here with numpy: vertex-to-segment both ways, plus a test for
    crossing edges and vertices inside the other), every vertex is at
    least minGap inside the box;
  - orientationSpread 0 puts every long axis at 'orientation';
  - the same seed writes the same file, another seed a different one;
  - nmmMesh meshes the platelets ("Mesh OK.");
  - too many platelets exit with code 1 and "do not fit" within seconds;
    aspectRatio < 1 and a misspelt keyword are rejected naming the keyword.
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import sys
import time
from pathlib import Path

import numpy as np

import utilityCase
from utilityCase import check, run

BOX = (0.0, 0.0, 1e-5, 1e-5)
BASE = {
    "box": "{ min (0 0); max (1e-5 1e-5); }",
    "shape": "rectangle",
    "number": "50",
    "length": "2e-6",
    "aspectRatio": "8",
    "orientation": "30",
    "minGap": "1e-7",
    "seed": "1",
    "material": "clay",
}

def makeCase(work, name, entries):
    return utilityCase.makeCase(work, name, entries, "nmmPlateletsDict")


def readBlocks(path):
    """[(name, material, array of points)] of a written block list"""
    return [(n, m, np.array(p, dtype=float)) for n, m, p in utilityCase.blockList(path)]


def area(p):
    return utilityCase.polygonArea(p)


def pointSegmentDistances(v, p):
    """Distance of each point v to each edge of polygon p: (len v, len p)"""
    a, b = p, np.roll(p, -1, axis=0)
    e = b - a
    w = v[:, None, :] - a[None, :, :]
    t = np.clip((w*e[None]).sum(-1)/(e*e).sum(-1)[None], 0, 1)
    return np.linalg.norm(w - t[..., None]*e[None], axis=-1)


def cross(o, a, b):
    return (a[..., 0] - o[..., 0])*(b[..., 1] - o[..., 1]) \
        - (a[..., 1] - o[..., 1])*(b[..., 0] - o[..., 0])


def overlap(p, q):
    """Edges crossing or touching, or a vertex of one inside the other"""
    a, b = p[:, None, :], np.roll(p, -1, axis=0)[:, None, :]
    c, d = q[None, :, :], np.roll(q, -1, axis=0)[None, :, :]
    d1, d2 = cross(a, b, c), cross(a, b, d)
    d3, d4 = cross(c, d, a), cross(c, d, b)
    if np.any((d1*d2 <= 0) & (d3*d4 <= 0)):
        return True

    def inside(v, poly):     # poly counter-clockwise and convex
        s = cross(poly[None, :, :], np.roll(poly, -1, axis=0)[None, :, :], v[:, None, :])
        return np.any(np.all(s >= 0, axis=1))
    return inside(p, q) or inside(q, p)


def smallestGap(blocks):
    polys = [b[2] for b in blocks]
    centres = np.array([p.mean(axis=0) for p in polys])
    radii = np.array([np.linalg.norm(p - p.mean(axis=0), axis=1).max() for p in polys])
    gap, overlapping = math.inf, 0
    for i in range(len(polys)):
        for j in range(i + 1, len(polys)):
            if np.linalg.norm(centres[i] - centres[j]) > radii[i] + radii[j] + gap:
                continue
            if overlap(polys[i], polys[j]):
                overlapping += 1
                gap = 0.0
                continue
            gap = min(gap, pointSegmentDistances(polys[i], polys[j]).min(),
                      pointSegmentDistances(polys[j], polys[i]).min())
    return gap, overlapping


def wallGap(blocks):
    pts = np.vstack([b[2] for b in blocks])
    return min(pts[:, 0].min() - BOX[0], BOX[2] - pts[:, 0].max(),
               pts[:, 1].min() - BOX[1], BOX[3] - pts[:, 1].max())


def checkPlacement(blocks, minGap, what):
    gap, overlapping = smallestGap(blocks)
    wall = wallGap(blocks)
    check(overlapping == 0 and gap >= minGap*(1 - 1e-9) and wall >= minGap*(1 - 1e-9),
          "%s: no overlap (%d), smallest gap %.4g, to the walls %.4g (minGap %.4g)"
          % (what, overlapping, gap, wall, minGap))


def axisAngles(blocks, rectangle):
    """Angle of each long axis from x in degrees, in [0, 180)"""
    angles = []
    for _, _, p in blocks:
        if rectangle:
            e = [p[(i + 1) % 4] - p[i] for i in range(4)]
            v = max(e, key=np.linalg.norm)
        else:
            v = p[0] - p[len(p)//2]     # vertex 0 and its opposite, on the long axis
        angles.append(math.degrees(math.atan2(v[1], v[0])) % 180)
    return angles


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 1
    binDir, work = Path(argv[0]).resolve(), Path(argv[1]).resolve()
    work.mkdir(parents=True, exist_ok=True)
    length, aspect, minGap = 2e-6, 8.0, 1e-7

    # rectangles at one angle
    a = makeCase(work, "rectangles", BASE)
    r = run(binDir, "nmmPlatelets", a)
    check(r.returncode == 0, "nmmPlatelets runs (exit %d)" % r.returncode)
    if r.returncode != 0:
        print(r.stdout + r.stderr)
        return 1
    blocks = readBlocks(a/"constant/geometry/platelets")
    check(len(blocks) == 50 and [b[0] for b in blocks] == ["platelet%d" % i for i in range(50)]
          and all(b[1] == "clay" for b in blocks),
          "number 50: %d platelets platelet0.., material clay" % len(blocks))
    check((a/"constant/geometry/platelets.png").stat().st_size > 0, "preview PNG written")
    expected = length*length/aspect
    err = max(abs(area(b[2]) - expected)/expected for b in blocks)
    check(err <= 1e-12, "rectangle areas = length*thickness (largest relative error %.2e)" % err)
    angles = axisAngles(blocks, True)
    err = max(abs(x - 30) for x in angles)
    check(err <= 1e-9, "orientationSpread 0: long axes at 30 deg (largest error %.2e deg)" % err)
    checkPlacement(blocks, minGap, "rectangles")

    # reproducible by seed
    b = makeCase(work, "rectanglesAgain", BASE)
    run(binDir, "nmmPlatelets", b)
    c = makeCase(work, "seed2", dict(BASE, seed="2"))
    run(binDir, "nmmPlatelets", c)
    text = (a/"constant/geometry/platelets").read_bytes()
    check(text == (b/"constant/geometry/platelets").read_bytes(), "same seed, same file")
    check(text != (c/"constant/geometry/platelets").read_bytes(), "another seed, another file")

    # spread of length and angle
    spread = dict(BASE, number="60", lengthSpread="0.25", orientationSpread="40",
                  minGap="5e-8", seed="5")
    d = makeCase(work, "spread", spread)
    r = run(binDir, "nmmPlatelets", d)
    blocks = readBlocks(d/"constant/geometry/platelets") if r.returncode == 0 else []
    sides = [sorted(np.linalg.norm(np.roll(p, -1, axis=0) - p, axis=1)) for _, _, p in blocks]
    lengths = [s[-1] for s in sides]
    ok = len(blocks) == 60 and all(
        0.75*length*(1 - 1e-12) <= s[-1] <= 1.25*length*(1 + 1e-12)
        and abs(s[-1]/s[0] - aspect) <= 1e-9*aspect
        and abs(area(p) - s[-1]*s[0]) <= 1e-12*area(p)
        for s, (_, _, p) in zip(sides, blocks))
    angles = axisAngles(blocks, True)
    dev = [((x - 30 + 90) % 180) - 90 for x in angles]
    check(ok and max(map(abs, dev)) <= 40 + 1e-9 and max(dev) - min(dev) > 40,
          "lengthSpread 0.25, orientationSpread 40: lengths %.3g..%.3g, angles 30%+.1f..%+.1f deg"
          % (min(lengths, default=0), max(lengths, default=0), min(dev, default=0),
             max(dev, default=0)))
    checkPlacement(blocks, 5e-8, "spread")

    # ellipses
    ell = dict(BASE, shape="ellipse", ellipseVertices="16", number="40", orientation="-20")
    e = makeCase(work, "ellipses", ell)
    r = run(binDir, "nmmPlatelets", e)
    blocks = readBlocks(e/"constant/geometry/platelets") if r.returncode == 0 else []
    aa, bb, n = length/2, length/aspect/2, 16
    expected = n/2*aa*bb*math.sin(2*math.pi/n)
    err = max((abs(area(p) - expected)/expected for _, _, p in blocks), default=1)
    check(len(blocks) == 40 and all(len(p) == 16 for _, _, p in blocks) and err <= 1e-12,
          "ellipses: 16-gons of area (n/2) a b sin(2 pi/n) = %.4f pi a b (largest relative"
          " error %.2e)" % (expected/(math.pi*aa*bb), err))
    angles = axisAngles(blocks, False)
    err = max((abs(x - 160) for x in angles), default=1)
    check(err <= 1e-9, "ellipses: long axes at -20 deg (largest error %.2e deg)" % err)
    checkPlacement(blocks, minGap, "ellipses")

    # nmmMesh
    (d/"system/nmmMeshDict").write_text(
        'blocks ( #include "<constant>/geometry/platelets" );\n'
        "cover { type structured; cellSize 1e-7; }\n")
    r = run(binDir, "nmmMesh", d)
    check(r.returncode == 0 and "Mesh OK." in r.stdout,
          "nmmMesh accepts the platelets (exit %d)" % r.returncode)
    if r.returncode != 0:
        print(r.stdout[-2000:] + r.stderr)

    # they do not fit
    start = time.monotonic()
    r = run(binDir, "nmmPlatelets", makeCase(work, "tooMany", dict(BASE, number="500")),
            timeout=30)
    seconds = time.monotonic() - start
    check(r.returncode == 1 and "do not fit" in r.stderr and "of 500 platelets" in r.stderr
          and seconds < 5,
          "500 platelets: exit %d in %.2f s, 'do not fit'" % (r.returncode, seconds))

    # broken input
    broken = [
        ("aspectRatio", dict(BASE, aspectRatio="0.5"), ["aspectRatio", "out of range"]),
        ("misspelt", dict(BASE, minGapp="1e-7"),
         ["Unknown keyword 'minGapp'", "did you mean 'minGap'"]),
        ("shape", dict(BASE, shape="elipse"), ["elipse", "did you mean 'ellipse'"]),
    ]
    utilityCase.checkRejected(binDir, "nmmPlatelets", broken, makeCase, work)

    return utilityCase.report()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
