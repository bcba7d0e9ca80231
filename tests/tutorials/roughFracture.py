#!/usr/bin/python3
"""Runs tutorials/paper/roughFracture with './Allrun -reduced' (coarse
cells) from a scratch copy and checks the behaviour the paper reports,
with numbers from summary.py:

    roughFracture.py <binDir> <projectDir> <workDir>

  - all six runs end with End and leave no NaN in their tables;
  - unconfined case 2: the faces first touch in the left half, and the
    upper block slides left (offset below -0.2 mm: the faces are a mated
    pair moved 0.4 mm apart, so it slides back most of the way);
  - unconfined case 3: first touch on the dominant right asperity (right
    half), and the upper block slides right (offset above +0.2 mm);
  - unconfined case 1: the block closes without sliding (offset within
    0.05 mm);
  - confined runs: the columns stop the sliding (every offset within
    0.05 mm), so case 2 closes less than unconfined (the asperities lock);
  - in every run the mean closure is positive and no more than the mean
    aperture at the start plus 1 um: faces cannot pass through each
    other, and the blocks' own compression is below 1 um (strain 1e-3
    over 2.5 mm).
Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (the tutorial's plot step needs numpy,
matplotlib and VTK, which Debian installs for that interpreter only).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import sys

import paperTutorial


def main(argv):
    case = paperTutorial.runReduced(argv, "roughFracture", ["*Case[0-9]"], __doc__)
    if case is None:
        return 1
    check = paperTutorial.checks()
    runs = [s + "Case" + str(n) for s in ("unconfined", "confined") for n in (1, 2, 3)]
    if not check.ended(case, runs):
        return 1
    rows = paperTutorial.summary(case)

    for r in rows.values():
        values = [v for v in r.values() if isinstance(v, float)]
        check(all(math.isfinite(v) for v in values), r["run"] + ": finite results")
        check(0 < r["meanClosure_mm"] <= r["meanAperture_mm"] + 1e-3,
              r["run"] + ": 0 < closure <= initial mean aperture + 1 um")
    u1, u2, u3 = (rows["unconfinedCase%d" % n] for n in (1, 2, 3))
    check(u2["firstContactX_mm"] < 5, "unconfined case 2 first touches on the left")
    check(u2["offset_mm"] < -0.2, "unconfined case 2 slides left")
    check(u3["firstContactX_mm"] > 5, "unconfined case 3 first touches on the right")
    check(u3["offset_mm"] > 0.2, "unconfined case 3 slides right")
    check(abs(u1["offset_mm"]) < 0.05, "unconfined case 1 closes without sliding")
    for n in (1, 2, 3):
        c = rows["confinedCase%d" % n]
        check(abs(c["offset_mm"]) < 0.05, c["run"] + ": the columns stop the sliding")
    check(rows["confinedCase2"]["meanClosure_mm"] < u2["meanClosure_mm"],
          "confined case 2 closes less than unconfined case 2")
    return check.exitCode()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
