#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/incline/phi<phi>: a block on an
incline at a = 30 degrees with dry friction phi.

Usage:
    checkIncline.py <caseDir> <phi>

The slope is made by tilting gravity, so the slider (block 1) moves along
x: its displacement is the mean D_x of its elements (cell data, weighted
by area). d(t) = g (sin a - cos a tan phi) t^2/2 if tan phi < tan a.
Sliding: d in the last frame (t about 1 s, compared at the frame's own
time) within 1% of d(t). Sticking: |d| and the largest |D| of the
slider's points below the allowed penetration, 0.4 x the search distance
(2.5 x 0.005 x half the larger side of the model's bounding box, the
solver's automatic value). The other frames are reported.
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
SLIDER = 1


def blockCells(f, block):
    """Mask of the cells of a block."""
    if "blockId" not in f.cellData or "D" not in f.cellData:
        raise SystemExit("%s: no cell data blockId and D" % f.path)
    sel = f.cellData["blockId"].astype(int) == block
    if not sel.any():
        raise SystemExit("%s: no cells of block %d" % (f.path, block))
    return sel


def meanDisplacement(f, sel):
    """Area-weighted mean cell D of the selected cells."""
    w = f.cellArea[sel]
    return (f.cellData["D"][sel, :2]*w[:, None]).sum(axis=0)/w.sum()


def blockPoints(f, sel):
    """The points of the selected cells."""
    return np.unique(np.concatenate([f.cells[k] for k in np.flatnonzero(sel)]))


def blockDisplacement(f, block):
    """Area-weighted mean cell D of a block, and its points' largest |D|."""
    sel = blockCells(f, block)
    pts = blockPoints(f, sel)
    return meanDisplacement(f, sel), float(np.linalg.norm(f.D[pts], axis=1).max())


def halfSize(f):
    """Half the larger side of the bounding box of the undeformed model."""
    return 0.5*float((f.X.max(axis=0) - f.X.min(axis=0)).max())


def errors(caseDir, phi):
    """Error measures of the slide, as numbers (no pass/fail), each frame
    compared at its own time. Sliding: the largest relative error of d
    over the frames with t > 0 (dError) and that of the last frame
    (dEndError). Sticking: the largest |mean D| of the slider over the
    allowed penetration (stickRatio)."""
    c = cf.incline
    phi = float(phi)
    series = nf.readSeries(caseDir)
    worst = last = 0.0
    for t, path in series:
        if t <= 0:
            continue
        mean, _ = blockDisplacement(nf.readFrame(path), SLIDER)
        if c.slides(phi):
            d = c.displacement(phi, t)
            last = abs(float(mean[0]) - d)/d
        else:
            last = float(np.linalg.norm(mean))
        worst = max(worst, last)
    if c.slides(phi):
        return {"dError": worst, "dEndError": last}
    limit = cf.allowedPenetration(halfSize(nf.readFrame(series[0][1])),
                                  c.maxDisplacementRatio)
    return {"stickRatio": worst/limit}


def main(argv):
    if len(argv) != 2 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    c = cf.incline
    phi = float(argv[1])
    series = nf.readSeries(argv[0])
    r = nf.report("incline phi = %g" % phi)
    r.absolute("last time [s]", series[-1][0], 1.0, 0.05)
    for t, path in series:
        if t <= 0:
            continue
        f = nf.readFrame(path)
        mean, _ = blockDisplacement(f, SLIDER)
        r.info("d(%.4g) [m]" % t, float(mean[0]), c.displacement(phi, t))
    t, path = series[-1]
    f = nf.readFrame(path)
    mean, largest = blockDisplacement(f, SLIDER)
    if c.slides(phi):
        r.relative("d(t = %.6g) [m]" % t, float(mean[0]), c.displacement(phi, t), TOL)
    else:
        limit = cf.allowedPenetration(halfSize(nf.readFrame(series[0][1])),
                                      c.maxDisplacementRatio)
        r.upper("|mean D| of the sticking block [m]", float(np.linalg.norm(mean)), limit)
        r.upper("largest |D| of its points [m]", largest, limit)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
