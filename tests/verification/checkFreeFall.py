#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/freeFall: y = y0 - g t^2/2.

Usage:
    checkFreeFall.py <caseDir>

g = 9.81, ten steps of 0.01 s from rest. In every frame with t > 0 (not
only the last): every point's D_y against -g t^2/2 and, when written,
U_y against -g t, relative error at most 1e-10; |D_x| at most 1e-10 of
g t^2/2. The last time must be 0.1 (ten steps).
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL = 1e-10


def errors(caseDir):
    """Error measures over all frames with t > 0, as numbers (no
    pass/fail): the largest relative errors of D_y and U_y."""
    c = cf.freeFall
    worstD = worstU = 0.0
    for t, path in nf.readSeries(caseDir):
        if t <= 0:
            continue
        f = nf.readFrame(path)
        dy = c.displacementY(t)
        worstD = max(worstD, float(np.abs(f.D[:, 1] - dy).max()/abs(dy)))
        if f.U is not None:
            vy = c.velocityY(t)
            worstU = max(worstU, float(np.abs(f.U[:, 1] - vy).max()/abs(vy)))
    return {"DyError": worstD, "UyError": worstU}


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    c = cf.freeFall
    series = nf.readSeries(argv[0])
    r = nf.report("freeFall")
    tEnd = c.deltaT*c.nSteps
    r.absolute("last time", series[-1][0], tEnd, 1e-12*tEnd)
    worstD = worstX = worstU = 0.0
    n = 0
    for t, path in series:
        if t <= 0:
            continue
        f = nf.readFrame(path)
        dy = c.displacementY(t)
        worstD = max(worstD, float(np.abs(f.D[:, 1] - dy).max()/abs(dy)))
        worstX = max(worstX, float(np.abs(f.D[:, 0]).max()/abs(dy)))
        if f.U is not None:
            vy = c.velocityY(t)
            worstU = max(worstU, float(np.abs(f.U[:, 1] - vy).max()/abs(vy)))
        else:
            worstU = float("nan")
        n += 1
    r.info("frames checked", float(n), float(c.nSteps))
    r.info("D_y at the last time (exact)", c.displacementY(series[-1][0]))
    r.upper("max |D_y + g t^2/2|/(g t^2/2)", worstD, TOL)
    r.upper("max |D_x|/(g t^2/2)", worstX, TOL)
    r.upper("max |U_y + g t|/(g t)", worstU, TOL)
    if n == 0:
        r.failed = True
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
