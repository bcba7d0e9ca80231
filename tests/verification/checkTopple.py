#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/topple/<regime>: a b x h block on
an incline at a = 30 degrees with dry friction phi, from rest; stable,
sliding without toppling, or toppling without sliding.

Usage:
    checkTopple.py <caseDir> stable|sliding|toppling

The slope is made by tilting gravity, so x is downslope. The block is
block 1; its slide is the mean D_x of its elements (cell data, weighted by
area), its rotation the angle of the least squares rigid fit of its points
(undeformed X to deformed x = X + D), clockwise (downhill) positive.
    stable    in the last frame, |mean D| and the largest |D| of the
              block's points below the allowed penetration (0.4 x the
              search distance, 2.5 x 0.005 x half the larger side of the
              model's bounding box), |rotation| below 1e-3 rad
    sliding   in the last frame (t about 1 s, compared at the frame's own
              time), the slide within 1% of g (sin a - cos a tan phi)
              t^2/2, |rotation| below 1e-3 rad
    toppling  in the last frame (t about 0.15 s), the rotation within 3%
              of theta(t) = alpha0/k (cosh(sqrt(k) t) - 1) (closedForms.
              topple), and the x displacement of the pivot (the downhill
              bottom corner) below 5% of that of the downhill top corner
The other frames are reported. Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402
from checkIncline import blockCells, blockPoints, halfSize, meanDisplacement  # noqa: E402

BLOCK = 1
SLIDE_TOL = 0.01


def clockwiseRotation(f, pts):
    """Angle of the least squares rigid fit X -> x of the points, clockwise
    positive (exact for a rigid motion of any size)."""
    X = f.X[pts] - f.X[pts].mean(axis=0)
    x = f.x[pts] - f.x[pts].mean(axis=0)
    cross = (X[:, 0]*x[:, 1] - X[:, 1]*x[:, 0]).sum()
    dot = (X*x).sum()
    return -float(np.arctan2(cross, dot))


def corner(f, pts, target):
    """The point of pts whose undeformed position is nearest target."""
    d = np.linalg.norm(f.X[pts] - np.asarray(target), axis=1)
    return pts[int(np.argmin(d))]


def errors(caseDir, regime):
    """Error measures of the block's motion, as numbers (no pass/fail),
    each frame compared at its own time. Toppling: the relative error of
    the rotation in the last frame (thetaError), the largest over the
    frames with t >= 0.05 s (thetaMaxError; earlier the rotation is still
    of the order of the contact springs' settling) and |pivot D_x| over
    |top corner D_x| in the last frame (slipRatio). Sliding: the relative
    error of the slide in the last frame (dError) and |rotation| (rad).
    Stable: |mean D| over the allowed penetration (stickRatio) and
    |rotation|."""
    c = cf.topple
    b, h, phi = c.regimes[regime]
    series = nf.readSeries(caseDir)
    if regime == "toppling":
        worst = 0.0
        for t, path in series:
            if t < 0.05 - 1e-9:
                continue
            f = nf.readFrame(path)
            pts = blockPoints(f, blockCells(f, BLOCK))
            theta = c.rotation(regime, t)
            worst = max(worst, abs(clockwiseRotation(f, pts) - theta)/theta)
        t, path = series[-1]
        f = nf.readFrame(path)
        pts = blockPoints(f, blockCells(f, BLOCK))
        theta = c.rotation(regime, t)
        pivot = corner(f, pts, (c.x0 + b, 0.0))
        top = corner(f, pts, (c.x0 + b, h))
        dTop = abs(float(f.D[top, 0]))
        return {"thetaError": abs(clockwiseRotation(f, pts) - theta)/theta,
                "thetaMaxError": worst,
                "slipRatio": abs(float(f.D[pivot, 0]))/dTop if dTop > 0 else float("inf")}
    t, path = series[-1]
    f = nf.readFrame(path)
    sel = blockCells(f, BLOCK)
    rotation = abs(clockwiseRotation(f, blockPoints(f, sel)))
    mean = meanDisplacement(f, sel)
    if regime == "sliding":
        d = c.displacement(regime, t)
        return {"dError": abs(float(mean[0]) - d)/d, "rotation": rotation}
    limit = cf.allowedPenetration(halfSize(nf.readFrame(series[0][1])),
                                  c.maxDisplacementRatio)
    return {"stickRatio": float(np.linalg.norm(mean))/limit, "rotation": rotation}


def main(argv):
    c = cf.topple
    if len(argv) != 2 or argv[1] not in c.regimes:
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    regime = argv[1]
    b, h, phi = c.regimes[regime]
    series = nf.readSeries(argv[0])
    r = nf.report("topple %s (b = %g, h = %g, phi = %g)" % (regime, b, h, phi))
    if regime == "toppling":
        r.absolute("last time [s]", series[-1][0], 0.15, 0.01)
    else:
        r.absolute("last time [s]", series[-1][0], 1.0, 0.05)
    pivotX = (c.x0 + b, 0.0)
    topX = (c.x0 + b, h)
    for t, path in series:
        if t <= 0:
            continue
        f = nf.readFrame(path)
        sel = blockCells(f, BLOCK)
        pts = blockPoints(f, sel)
        if regime == "toppling":
            r.info("theta(%.4g) [rad]" % t, clockwiseRotation(f, pts), c.rotation(regime, t))
        else:
            r.info("d(%.4g) [m]" % t, float(meanDisplacement(f, sel)[0]),
                   c.displacement(regime, t))
    t, path = series[-1]
    f = nf.readFrame(path)
    sel = blockCells(f, BLOCK)
    pts = blockPoints(f, sel)
    theta = clockwiseRotation(f, pts)
    if regime == "stable":
        limit = cf.allowedPenetration(halfSize(nf.readFrame(series[0][1])),
                                      c.maxDisplacementRatio)
        mean = meanDisplacement(f, sel)
        largest = float(np.linalg.norm(f.D[pts], axis=1).max())
        r.upper("|mean D| of the block [m]", float(np.linalg.norm(mean)), limit)
        r.upper("largest |D| of its points [m]", largest, limit)
        r.upper("|rotation| [rad]", abs(theta), c.maxRotation)
    elif regime == "sliding":
        r.relative("d(t = %.6g) [m]" % t, float(meanDisplacement(f, sel)[0]),
                   c.displacement(regime, t), SLIDE_TOL)
        r.upper("|rotation| [rad]", abs(theta), c.maxRotation)
    else:
        r.info("alpha0 t^2/2 [rad]", 0.5*c.alpha0(regime)*t*t)
        r.relative("theta(t = %.6g) [rad]" % t, theta, c.rotation(regime, t),
                   c.rotationTolerance)
        pivot = corner(f, pts, pivotX)
        top = corner(f, pts, topX)
        r.info("pivot D_x [m]", float(f.D[pivot, 0]))
        r.info("pivot D_y [m]", float(f.D[pivot, 1]))
        r.info("top corner D_x [m]", float(f.D[top, 0]), h*np.sin(c.rotation(regime, t)))
        dTop = abs(float(f.D[top, 0]))
        ratio = abs(float(f.D[pivot, 0]))/dTop if dTop > 0 else float("inf")
        r.upper("|pivot D_x|/|top corner D_x|", ratio, c.slipRatio)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
