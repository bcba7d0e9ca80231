#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/brazilian against the Brazilian
test's closed form.

Usage:
    checkBrazilian.py <caseDir>

Quarter model of a disc (D = 0.05, t = 1, centre at the origin) squeezed by
P = 1e5 N/m through a platen in contact with it: at the centre
sigma_x = 2P/(pi D t) = 1.273 MPa (tension). On the last frame:
  - sigma_x at the centre: least squares fit of the disc's element values
    (cell data) with centroids within 0.2 R of the centre by
    c0 + c1 x^2 + c2 y^2 (the field is even in x and y), c0 within 3%;
  - sigma_y at the centre and the fit's rms against the point-load closed
    form on those elements are printed;
  - the load went through the contact: the vertical components of the
    normal forces of the closed contacts of the last contact frame add up
    to P/2 (the quarter model) within 1%.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL = 0.03
TOL_LOAD = 0.01


def centreStress(f, R):
    sxx, syy, _ = nf.cellStress(f)
    C = f.cellCentroid
    disc = f.cellData["blockId"] == 0 if "blockId" in f.cellData else np.ones(len(C), bool)
    m = disc & (np.hypot(C[:, 0], C[:, 1]) < 0.2*R)
    if m.sum() < 6:
        raise SystemExit("%s: %d elements within 0.2 R of the centre" % (f.path, m.sum()))
    M = np.column_stack([np.ones(m.sum()), C[m, 0]**2, C[m, 1]**2])
    cx = np.linalg.lstsq(M, sxx[m], rcond=None)[0]
    cy = np.linalg.lstsq(M, syy[m], rcond=None)[0]
    return float(cx[0]), float(cy[0]), m


def errors(caseDir):
    b = cf.brazilian
    f = nf.readFrame(nf.readSeries(caseDir)[-1][1])
    sx, _, _ = centreStress(f, b.D/2)
    return {"h": nf.cellSize(f), "centreError": abs(sx - b.centreTension())/b.centreTension()}


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    b = cf.brazilian
    f = nf.readFrame(nf.readSeries(argv[0])[-1][1])
    sx, sy, m = centreStress(f, b.D/2)
    r = nf.report("brazilian disc, D = %g, P = %g N/m (h = %.3g)" % (b.D, b.P, nf.cellSize(f)))
    r.relative("centre sigma_x (tension)", sx, b.centreTension(), TOL)
    r.info("centre sigma_y", sy, -3*b.centreTension())
    exact = b.stress(f.cellCentroid[m, 0], f.cellCentroid[m, 1])[0]
    rms = float(np.sqrt(np.mean((nf.cellStress(f)[0][m] - exact)**2)))/b.centreTension()
    r.info("rms of sigma_x - closed form within 0.2 R (/ centre value)", rms)
    c = nf.readContacts(nf.readContactSeries(argv[0])[-1][1])
    closed = c.data["contactState"] != 0 if len(c.x) else np.zeros(0, bool)
    # vertical components: contacts on the symmetry line x = 0 (normal
    # along x, between the rollered edges) carry no part of the load
    ny = np.abs(c.data["normal"][:, 1]) if len(c.x) else np.zeros(0)
    total = float((c.data["normalForce"]*ny)[closed].sum()) if len(c.x) else 0.0
    r.relative("vertical contact forces = P/2", total, b.P/2, TOL_LOAD)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
