#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/plateHole against Kirsch's solution.

Usage:
    checkPlateHole.py <caseDir> [<caseDir> ...]   refinement, coarse first

Quarter plate 5 x 5, hole a = 1, sigma = 1 in x, E = 1000, nu = 0.3, plane
strain. On the last frame:
  - peak sigma_xx at (0, a), expected 3 sigma = 3, within 2%. The element
    stress is constant in a manifold element, so the peak is extrapolated:
    a least squares fit of the cell sigma_xx over the elements whose
    (undeformed) centroid lies within 3h of the hole (r - a < 3h) and
    within 3h of the y axis (a (pi/2 - theta) < 3h), rows weighted by
    sqrt(element area), model c0 + c1 q + c2 q^2 + c3 phi^2 + c4 q phi^2
    with q = 1 - a^2/r^2 (0 on the hole; the stresses near a hole are
    smooth in a^2/r^2, far less curved than in r) and phi = pi/2 - theta
    (sigma_xx is even in phi); the peak is c0. On exact element values of
    a structured mesh cut by the hole this is within 0.5% at h = 0.1 and
    0.05% at h = 0.05 (a fit in r - a: 2% and 0.3%). The point
    value at the vertex nearest (0, a) (an average of the adjacent
    elements) is printed too;
  - relative L2 displacement error and relative energy error, printed;
    with two or more cases their observed rates must be 2 and 1 (+- 0.15).
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

PEAK_TOL = 0.02
RATE_TOL = 0.15


def peakFromCells(f, k):
    h = nf.cellSize(f)
    c = f.cellCentroid
    r = np.hypot(c[:, 0], c[:, 1])
    d = r - k.a
    q = 1 - (k.a/r)**2
    phi = np.pi/2 - np.arctan2(c[:, 1], c[:, 0])
    band = (d < 3*h) & (k.a*np.abs(phi) < 3*h)
    sxx = nf.cellStress(f)[0]
    return nf.extrapolate(q[band], sxx[band],
                          extra=[phi[band]**2, q[band]*phi[band]**2],
                          area=f.cellArea[band])


def peakFromPoints(f, k):
    if "sigma" not in f.pointData:
        return float("nan")
    i = int(np.argmin(np.hypot(f.X[:, 0], f.X[:, 1] - k.a)))
    return float(f.pointData["sigma"][i, 0])


def errors(caseDir):
    """Error measures of one case's last frame, as numbers (no pass/fail):
    h, relative error of the extrapolated peak sigma_xx(0, a), relative L2
    and energy errors."""
    k = cf.kirsch
    lam, mu = cf.planeModuli(k.E, k.nu, k.planeStress)
    f = nf.readFrame(nf.readSeries(caseDir)[-1][1])
    return {"h": nf.cellSize(f),
            "peakError": abs(peakFromCells(f, k) - k.peak())/abs(k.peak()),
            "L2": nf.l2Error(f, k.displacement),
            "energy": nf.energyError(f, k.stress, lam, mu)}


def main(argv):
    if not argv or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    k = cf.kirsch
    lam, mu = cf.planeModuli(k.E, k.nu, k.planeStress)
    r = nf.report("plateHole (Kirsch)")
    hs, l2s, ens = [], [], []
    for caseDir in argv:
        t, path = nf.readSeries(caseDir)[-1]
        f = nf.readFrame(path)
        h = nf.cellSize(f)
        tag = "[%s h=%.3g] " % (Path(caseDir).resolve().name, h)
        r.relative(tag + "sigma_xx(0,a) cells, extrapolated", peakFromCells(f, k),
                   k.peak(), PEAK_TOL, gate=(caseDir == argv[-1]))
        r.info(tag + "sigma_xx(0,a) point value", peakFromPoints(f, k), k.peak())
        l2 = nf.l2Error(f, k.displacement)
        en = nf.energyError(f, k.stress, lam, mu)
        r.info(tag + "relative L2 error of D", l2)
        r.info(tag + "relative energy error", en)
        hs.append(h)
        l2s.append(l2)
        ens.append(en)
    if len(argv) > 1:
        for i, (q2, qe) in enumerate(zip(nf.rate(hs, l2s), nf.rate(hs, ens))):
            r.absolute("L2 rate, levels %d-%d" % (i, i + 1), q2, 2.0, RATE_TOL)
            r.absolute("energy rate, levels %d-%d" % (i, i + 1), qe, 1.0, RATE_TOL)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
