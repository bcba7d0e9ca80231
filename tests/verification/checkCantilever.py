#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/cantilever against Timoshenko and Goodier.

Usage:
    checkCantilever.py <caseDir>                  one mesh
    checkCantilever.py <caseDir> <caseDir> ...    a refinement, coarse first

On the last frame of each case (VTK/<case>.vtu.series):
  - tip deflection: u_y at (L, 0), interpolated linearly along the points
    of the end x = L in y; expected 8.9000e-3 (plane stress), within 2%;
  - relative L2 displacement error over the body (linear field in each
    manifold element through its vertex values, sub-triangle quadrature),
    at most 2%;
  - relative energy error (element stress against the exact stress),
    printed.
With two or more cases, the observed rates between successive levels
(h = sqrt(2 x median element area)): L2 2 +- 0.15, energy 1 +- 0.15.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TIP_TOL = 0.02
L2_TOL = 0.02
RATE_TOL = 0.15


def tipDeflection(f, beam):
    tol = 1e-6*beam.L
    end = np.abs(f.X[:, 0] - beam.L) < tol
    if end.sum() < 2:
        raise SystemExit("%s: fewer than two points on x = L" % f.path)
    y = f.X[end, 1]
    uy = f.D[end, 1]
    order = np.argsort(y)
    return float(np.interp(0.0, y[order], uy[order]))


def errors(caseDir):
    """Error measures of one case's last frame, as numbers (no pass/fail):
    h, relative tip deflection error, relative L2 and energy errors."""
    beam = cf.cantilever
    lam, mu = cf.planeModuli(beam.E, beam.nu, beam.planeStress)
    f = nf.readFrame(nf.readSeries(caseDir)[-1][1])
    tip = tipDeflection(f, beam)
    return {"h": nf.cellSize(f),
            "tipError": abs(tip - beam.tipDeflection())/abs(beam.tipDeflection()),
            "L2": nf.l2Error(f, beam.displacement),
            "energy": nf.energyError(f, beam.stress, lam, mu)}


def main(argv):
    if not argv or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    beam = cf.cantilever
    lam, mu = cf.planeModuli(beam.E, beam.nu, beam.planeStress)
    r = nf.report("cantilever (Timoshenko-Goodier)")
    hs, l2s, ens = [], [], []
    for caseDir in argv:
        t, path = nf.readSeries(caseDir)[-1]
        f = nf.readFrame(path)
        h = nf.cellSize(f)
        tag = "[%s h=%.3g] " % (Path(caseDir).resolve().name, h)
        r.relative(tag + "tip u_y(L,0)", tipDeflection(f, beam),
                   beam.tipDeflection(), TIP_TOL)
        l2 = nf.l2Error(f, beam.displacement)
        en = nf.energyError(f, beam.stress, lam, mu)
        r.upper(tag + "relative L2 error of D", l2, L2_TOL,
                gate=(caseDir == argv[-1]))
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
