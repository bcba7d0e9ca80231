#!/usr/bin/python3
"""Checks nmmRoughFracture on small cases against closed forms:

    nmmRoughFracture.py <folder of the applications> <scratch folder>

  - flat faces, 0.1 mm apart, in a 10 mm x 5 mm box: two blocks whose
    areas add up to the box's less the gap, W (H - a);
  - a rough face and its mated copy (shift 0): the gap is a everywhere,
    so the areas again add up to W (H - a), and the lower block's top is
    the profile (its area is not a rectangle's);
  - confining columns: two more blocks of the columns' material, each of
    width x height;
  - broken input (a profile of one point, x not increasing, a misspelt
    keyword, a mated lower face, a negative aperture) exits 1 with a
    message that names the keyword.
Exit 1 when a check fails. Debian's /usr/bin/python3 runs it (numpy).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

import utilityCase
from utilityCase import check, run

W, H, A = 0.01, 0.005, 1e-4
BASE = {
    "box": "{ min (0 0); max (0.01 0.005); }",
    "meanHeight": "0.0025",
    "aperture": "1e-4",
    "material": "rock",
    "lower": "{ type points; points ((0 0) (0.01 0)); }",
    "upper": "{ type points; points ((0 0) (0.01 0)); }",
}
ROUGH = "{ type selfAffine; hurst 0.8; rmsHeight 4e-5; nPoints 101; seed 3; }"

def makeCase(work, name, entries):
    return utilityCase.makeCase(work, name, entries, "nmmRoughFractureDict")


def readBlocks(path):
    """{name: (material, array of points)} of a written block list"""
    return {n: (m, np.array(p, dtype=float)) for n, m, p in utilityCase.blockList(path)}


def area(p):
    return abs(utilityCase.polygonArea(p))


def blocksOf(binDir, work, name, entries):
    case = makeCase(work, name, entries)
    r = run(binDir, "nmmRoughFracture", case)
    check(r.returncode == 0, "%s: exit %d" % (name, r.returncode))
    if r.returncode != 0:
        print(r.stderr)
        return {}
    return readBlocks(case/"constant/geometry/fracture")


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 1
    binDir, work = Path(argv[0]), Path(argv[1])
    work.mkdir(parents=True, exist_ok=True)

    flat = blocksOf(binDir, work, "flat", BASE)
    total = sum(area(p) for _, p in flat.values())
    check(len(flat) == 2 and abs(total - W*(H - A)) < 1e-12*W*H,
          "flat: %d blocks, area %.12g against W (H - a) = %.12g" % (len(flat), total, W*(H - A)))

    mated = blocksOf(binDir, work, "mated", dict(BASE, lower=ROUGH,
                                                 upper="{ type mated; shift 0; }"))
    total = sum(area(p) for _, p in mated.values())
    lower = min(mated.values(), key=lambda b: b[1][:, 1].mean())[1] if mated else None
    check(len(mated) == 2 and abs(total - W*(H - A)) < 1e-9*W*H,
          "mated: area %.12g against W (H - a) = %.12g" % (total, W*(H - A)))
    check(lower is not None and len(lower) > 100,
          "mated: the lower block's top follows the 101-point profile")

    cols = blocksOf(binDir, work, "columns", dict(BASE, columns="{ width 2e-3; material steel; }"))
    steel = [p for m, p in cols.values() if m == "steel"]
    check(len(cols) == 4 and len(steel) == 2
          and all(abs(area(p) - 2e-3*H) < 1e-12*W*H for p in steel),
          "columns: two steel blocks of 2 mm x 5 mm")

    broken = [
        ("onePoint", dict(BASE, lower="{ type points; points ((0 0)); }"),
         ["at least two points", "points"]),
        ("notIncreasing", dict(BASE, lower="{ type points; points ((0 0) (0.006 0) (0.004 0) (0.01 0)); }"),
         ["points", "increas"]),
        ("misspelt", dict(BASE, aperure="1e-4"), ["aperure", "did you mean 'aperture'"]),
        ("matedLower", dict(BASE, lower="{ type mated; shift 0; }"), ["mated", "upper"]),
        ("negativeAperture", dict(BASE, aperture="-1e-4"), ["aperture", "range"]),
    ]
    utilityCase.checkRejected(binDir, "nmmRoughFracture", broken, makeCase, work)

    return utilityCase.report()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
