#!/usr/bin/python3
"""Checks nmmVoronoiGrains on small cases:

    nmmVoronoiGrains.py <folder of the applications> <scratch folder>

  - nGrains is honoured (names <namePrefix>0.., the material), and
    meanGrainSize d gives round(box area/(pi d^2/4)) grains;
  - the grains tile the box: their areas sum to the box's to 1e-12
    (relative), every edge is either held by exactly two grains, written
    with the same coordinate text in opposite directions, or lies on a
    side of the box;
  - the same seed writes the same file byte for byte, another seed a
    different one;
  - five Lloyd steps lower the coefficient of variation of the areas;
  - nmmMesh meshes the grains (blocks ( #include "<constant>/geometry/
    grains" ); and a structured cover of a fifth of a grain): "Mesh OK.";
  - broken input exits with code 1 and names the keyword: nGrains 0, a
    box with max <= min, both or neither of nGrains and meanGrainSize, a
    misspelt keyword (with "did you mean"), meanGrainSize larger than the
    box.
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import sys
from pathlib import Path

import utilityCase
from utilityCase import check, run

BOX = (0.0, 0.0, 0.01, 0.005)
BASE = {
    "box": "{ min (0 0); max (0.01 0.005); }",
    "nGrains": "40",
    "seed": "3",
    "lloydIterations": "0",
    "material": "rock",
}

def makeCase(work, name, entries):
    return utilityCase.makeCase(work, name, entries, "nmmVoronoiGrainsDict")


readGrains = utilityCase.blockList
area = utilityCase.polygonArea


def coefficientOfVariation(values):
    mean = sum(values)/len(values)
    return math.sqrt(sum((v - mean)**2 for v in values)/len(values))/mean


def onBoxSide(a, b):
    (ax, ay), (bx, by) = [(float(x), float(y)) for x, y in (a, b)]
    x0, y0, x1, y1 = BOX
    return ((ax == bx and ax in (x0, x1) and y0 <= min(ay, by) and max(ay, by) <= y1)
            or (ay == by and ay in (y0, y1) and x0 <= min(ax, bx) and max(ax, bx) <= x1))


def checkTiling(grains):
    areas = [area(p) for _, _, p in grains]
    boxArea = (BOX[2] - BOX[0])*(BOX[3] - BOX[1])
    rel = abs(math.fsum(areas) - boxArea)/boxArea
    check(rel <= 1e-12 and min(areas) > 0,
          "areas positive, sum to the box area (relative difference %.2e)" % rel)

    owners = {}
    for g, (_, _, pts) in enumerate(grains):
        for a, b in zip(pts, pts[1:] + pts[:1]):
            owners.setdefault((a, b), []).append(g)
    repeated = [e for e, o in owners.items() if len(o) > 1]
    unmatched = [e for e in owners if (e[1], e[0]) not in owners and not onBoxSide(*e)]
    shared = [e for e in owners if (e[1], e[0]) in owners]
    sameGrain = [e for e in shared if owners[e] == owners[(e[1], e[0])]]
    onBoxShared = [e for e in shared if onBoxSide(*e)]
    check(not repeated and not unmatched and not sameGrain and not onBoxShared,
          "%d interior edges each in two grains (same text, reversed), %d on the box"
          " (repeated %d, unmatched %d)" % (len(shared)//2, len(owners) - len(shared),
                                            len(repeated), len(unmatched)))
    return areas


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 1
    binDir, work = Path(argv[0]).resolve(), Path(argv[1]).resolve()
    work.mkdir(parents=True, exist_ok=True)

    # nGrains, tiling, shared edges
    a = makeCase(work, "seed3", BASE)
    r = run(binDir, "nmmVoronoiGrains", a)
    check(r.returncode == 0, "nmmVoronoiGrains runs (exit %d)" % r.returncode)
    if r.returncode != 0:
        print(r.stdout + r.stderr)
        return 1
    grains = readGrains(a/"constant/geometry/grains")
    check(len(grains) == 40 and [g[0] for g in grains] == ["grain%d" % i for i in range(40)]
          and all(g[1] == "rock" for g in grains),
          "nGrains 40: %d grains grain0.., material rock" % len(grains))
    check((a/"constant/geometry/grains.png").stat().st_size > 0, "preview PNG written")
    before = checkTiling(grains)

    # reproducible by seed
    b = makeCase(work, "seed3again", BASE)
    run(binDir, "nmmVoronoiGrains", b)
    c = makeCase(work, "seed4", dict(BASE, seed="4"))
    run(binDir, "nmmVoronoiGrains", c)
    text = (a/"constant/geometry/grains").read_bytes()
    check(text == (b/"constant/geometry/grains").read_bytes(), "same seed, same file")
    check(text != (c/"constant/geometry/grains").read_bytes(), "another seed, another file")

    # Lloyd
    d = makeCase(work, "lloyd", dict(BASE, lloydIterations="5"))
    run(binDir, "nmmVoronoiGrains", d)
    relaxed = readGrains(d/"constant/geometry/grains")
    after = checkTiling(relaxed)
    cvBefore, cvAfter = coefficientOfVariation(before), coefficientOfVariation(after)
    check(len(relaxed) == 40 and cvAfter < cvBefore,
          "5 Lloyd steps: area coefficient of variation %.3f -> %.3f" % (cvBefore, cvAfter))

    # meanGrainSize
    sized = dict(BASE, meanGrainSize="1e-3")
    del sized["nGrains"]
    e = makeCase(work, "meanGrainSize", sized)
    r = run(binDir, "nmmVoronoiGrains", e)
    expected = round(0.01*0.005/(math.pi*1e-6/4))
    n = len(readGrains(e/"constant/geometry/grains")) if r.returncode == 0 else -1
    check(n == expected, "meanGrainSize 1e-3: %d grains (expected %d)" % (n, expected))

    # nmmMesh
    (d/"system/nmmMeshDict").write_text(
        'blocks ( #include "<constant>/geometry/grains" );\n'
        "cover { type structured; cellSize 2e-4; }\n")
    r = run(binDir, "nmmMesh", d)
    check(r.returncode == 0 and "Mesh OK." in r.stdout,
          "nmmMesh accepts the grains (exit %d)" % r.returncode)
    if r.returncode != 0:
        print(r.stdout[-2000:] + r.stderr)

    # broken input
    neither = dict(BASE)
    del neither["nGrains"]
    broken = [
        ("nGrains0", dict(BASE, nGrains="0"), ["nGrains", "out of range"]),
        ("boxEmpty", dict(BASE, box="{ min (0 0); max (0.01 0); }"), ["max", "min"]),
        ("both", dict(BASE, meanGrainSize="1e-3"), ["nGrains", "meanGrainSize", "not both"]),
        ("neither", neither, ["nGrains", "meanGrainSize"]),
        ("misspelt", dict(BASE, lloydIteration="2"),
         ["Unknown keyword 'lloydIteration'", "did you mean 'lloydIterations'"]),
        ("tooLarge", dict(neither, meanGrainSize="0.02"), ["meanGrainSize", "larger than the box"]),
    ]
    utilityCase.checkRejected(binDir, "nmmVoronoiGrains", broken, makeCase, work)

    return utilityCase.report()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
