#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/sneddon/* against Sneddon's crack opening.

Usage:
    checkSneddon.py <caseDir> <crackAngleDeg>

Crack of half-length a = 0.1 centred at the origin, at the given angle to
the x axis, pressure p = 1 on both faces, E = 1, nu = 0.15, plane strain:
w(s) = 4 p (1 - nu^2)/E sqrt(a^2 - s^2), w(0) = 0.391. On the last frame:
  - the points on the crack (undeformed distance to its line below 1e-6 a,
    |s| < a (1 - 1e-6)) are split into the two faces by the side of the
    undeformed centroid of an element holding them (points are duplicated
    across a joint); on each face the normal displacement D.n is
    interpolated linearly in s to s = 0; w(0) = upper - lower, within 2%;
  - no spurious contact: the opening is positive at every point of the
    faces with |s| < 0.95 a (both faces interpolated to the same s);
  - w(s) at s = a/2 is printed.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL = 0.02


def faces(f, a, angle):
    t = np.array([math.cos(angle), math.sin(angle)])
    n = np.array([-t[1], t[0]])
    s = f.X @ t
    dn = f.X @ n
    on = (np.abs(dn) < 1e-6*a) & (np.abs(s) < a*(1 - 1e-6))
    side = np.zeros(len(f.X))
    cside = f.cellCentroid @ n
    for k, c in enumerate(f.cells):
        for i in c:
            if on[i] and side[i] == 0 and abs(cside[k]) > 1e-12*a:
                side[i] = np.sign(cside[k])
    upper = on & (side > 0)
    lower = on & (side < 0)
    if upper.sum() < 2 or lower.sum() < 2:
        raise SystemExit("%s: found %d and %d points on the two crack faces"
                         % (f.path, upper.sum(), lower.sum()))
    Dn = f.D @ n

    def profile(mask):
        o = np.argsort(s[mask])
        return s[mask][o], Dn[mask][o]
    return profile(upper), profile(lower)


def errors(caseDir, angleDeg):
    """Error measures of one case's last frame, as numbers (no pass/fail):
    h and the relative errors of w(0) and w(a/2)."""
    c = cf.sneddon
    f = nf.readFrame(nf.readSeries(caseDir)[-1][1])
    (su, wu), (sl, wl) = faces(f, c.a, math.radians(angleDeg))

    def opening(s):
        return float(np.interp(s, su, wu) - np.interp(s, sl, wl))
    w2 = float(c.opening(np.float64(c.a/2)))
    return {"h": nf.cellSize(f),
            "w0Error": abs(opening(0.0) - c.centreOpening())/c.centreOpening(),
            "wHalfError": abs(opening(c.a/2) - w2)/w2}


def main(argv):
    if len(argv) != 2 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    c = cf.sneddon
    angleDeg = float(argv[1])
    t, path = nf.readSeries(argv[0])[-1]
    f = nf.readFrame(path)
    (su, wu), (sl, wl) = faces(f, c.a, math.radians(angleDeg))
    r = nf.report("sneddon, crack at %g deg (h=%.3g)" % (angleDeg, nf.cellSize(f)))
    r.info("points on upper/lower face", float(len(su)), float(len(sl)))

    def opening(s):
        return np.interp(s, su, wu) - np.interp(s, sl, wl)
    r.relative("w(0)", float(opening(0.0)), c.centreOpening(), TOL)
    r.info("w(a/2)", float(opening(c.a/2)), float(c.opening(np.float64(c.a/2))))
    ss = np.concatenate([su, sl])
    ss = ss[np.abs(ss) < 0.95*c.a]
    wmin = float(opening(ss).min()) if len(ss) else float("nan")
    r._add("min opening on |s| < 0.95a (> 0)", wmin, float("nan"), wmin,
           0.0, wmin > 0, True)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
