#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/lame against Lame's thick cylinder.

Usage:
    checkLame.py <caseDir>

Quarter ring a = 0.1, b = 0.2, inner pressure p = 10 MPa, E = 10 GPa,
nu = 0.25, plane strain: sigma_r = A - B/r^2, sigma_t = A + B/r^2,
A = p a^2/(b^2 - a^2), B = p a^2 b^2/(b^2 - a^2),
u_r = (1 + nu)/E ((1 - 2 nu) A r + B/r). On the last frame:
  - u_r(a) = 1.875e-4 m: mean of D.X/|X| over the points on r = a
    (|r - a| < 1e-6 b), within 1%; the largest deviation of a single point
    is printed;
  - u_r(b) = 1.25e-4 m the same way on r = b, within 1%;
  - sigma_t(a) = 16.667 MPa within 1%: the element (cell) hoop stress
    sigma_t = (s_xx y^2 + s_yy x^2 - 2 s_xy x y)/r^2 at the undeformed
    centroids within 3h of the inner arc, fitted by least squares
    (rows weighted by sqrt(element area)) with c0 + c1 q + c2 q^2,
    q = 1 - a^2/r^2, and taken at q = 0 (c0) (the same estimator as
    checkPlateHole.py; the exact sigma_t is linear in q). The mean point value on r = a is
    printed too.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL = 0.01


def hoop(x, y, sxx, syy, sxy):
    r2 = x*x + y*y
    return (sxx*y*y + syy*x*x - 2*sxy*x*y)/r2


def errors(caseDir):
    """Error measures of one case's last frame, as numbers (no pass/fail):
    h and the relative errors of the mean u_r(a), u_r(b) and of the
    extrapolated sigma_t(a), as main() computes them."""
    c = cf.lame
    f = nf.readFrame(nf.readSeries(caseDir)[-1][1])
    h = nf.cellSize(f)
    R = np.hypot(f.X[:, 0], f.X[:, 1])
    ur = (f.D*f.X).sum(axis=1)/R
    out = {"h": h}
    for name, rad in (("a", c.a), ("b", c.b)):
        on = np.abs(R - rad) < 1e-6*c.b
        exact = float(c.radialDisplacement(rad))
        out["urError_" + name] = abs(float(ur[on].mean()) - exact)/abs(exact)
    cc = f.cellCentroid
    rc = np.hypot(cc[:, 0], cc[:, 1])
    band = rc - c.a < 3*h
    sxx, syy, sxy = nf.cellStress(f)
    st = hoop(cc[:, 0], cc[:, 1], sxx, syy, sxy)
    sta = nf.extrapolate((1 - (c.a/rc)**2)[band], st[band], area=f.cellArea[band])
    exact = float(c.polarStress(c.a)[1])
    out["sigmaTError"] = abs(sta - exact)/abs(exact)
    return out


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    c = cf.lame
    t, path = nf.readSeries(argv[0])[-1]
    f = nf.readFrame(path)
    h = nf.cellSize(f)
    r = nf.report("lame (thick cylinder, h=%.3g)" % h)
    R = np.hypot(f.X[:, 0], f.X[:, 1])
    ur = (f.D*f.X).sum(axis=1)/R
    for name, rad in (("a", c.a), ("b", c.b)):
        on = np.abs(R - rad) < 1e-6*c.b
        if on.sum() < 2:
            raise SystemExit("%s: no points on r = %s" % (path, name))
        exact = float(c.radialDisplacement(rad))
        r.relative("u_r(%s), mean of %d points" % (name, on.sum()),
                   float(ur[on].mean()), exact, TOL)
        r.info("u_r(%s), worst point" % name,
               float(ur[on][np.argmax(np.abs(ur[on] - exact))]), exact)
    cc = f.cellCentroid
    d = np.hypot(cc[:, 0], cc[:, 1]) - c.a
    band = d < 3*h
    sxx, syy, sxy = nf.cellStress(f)
    st = hoop(cc[:, 0], cc[:, 1], sxx, syy, sxy)
    q = 1 - (c.a/np.hypot(cc[:, 0], cc[:, 1]))**2
    sta = nf.extrapolate(q[band], st[band], area=f.cellArea[band])
    exact = float(c.polarStress(c.a)[1])
    r.relative("sigma_t(a), cells extrapolated", sta, exact, TOL)
    if "sigma" in f.pointData:
        on = np.abs(R - c.a) < 1e-6*c.b
        s = f.pointData["sigma"]
        r.info("sigma_t(a), mean point value",
               float(hoop(f.X[on, 0], f.X[on, 1], s[on, 0], s[on, 1], s[on, 3]).mean()),
               exact)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
