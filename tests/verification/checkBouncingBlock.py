#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/bouncingBlock/<scheme>: a 1 x 1
block dropped from h0 = 1 onto a fixed base.

Usage:
    checkBouncingBlock.py <caseDir> trapezoidal|DDA

The block (block 1) height above its start is its mean D_y (cell data,
area-weighted); its bottom touches the base at D_y = -h0. An impact is a
stretch of frames with D_y < -h0; a rebound height is h0 plus the largest
D_y between two impacts (or after the last one, if the block has passed
its apex: D_y falls again before the end). The restitution of a bounce is
its rebound height over the height it fell from.
  trapezoidal: at least one rebound; every rebound height within 3% of h0
      and each bounce losing less than 1% of the energy (1 - restitution,
      the energy being m g times the apex height);
  DDA: at least one rebound; restitutions finite and below 1; reported
      against omega dt, omega = sqrt(n kN/m) with n the closed contacts
      (contacts_<index>.vtp, state 1 or 2) in the frame of deepest
      penetration, when those files are there.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402
from checkIncline import blockDisplacement  # noqa: E402

BLOCK = 1


def closedContacts(path):
    """Number of closed contacts (state 1 or 2) in a contacts_<i>.vtp, or
    None when there is no such file."""
    if not path.is_file():
        return None
    a = nf.nmmVtk.readPolyData(path).GetPointData().GetArray("contactState")
    if a is None:
        return None
    return int((nf.nmmVtk.toNumpy(a) > 0).sum())


def history(caseDir):
    """Times, block heights (mean D_y) and frame paths."""
    series = nf.readSeries(caseDir)
    t = []
    dy = []
    for time, path in series:
        mean, _ = blockDisplacement(nf.readFrame(path), BLOCK)
        t.append(time)
        dy.append(float(mean[1]))
    return np.array(t), np.array(dy), [p for _, p in series]


def bounces(t, dy, h0):
    """Rebound heights above the base (h0 + largest D_y after each impact,
    when the apex is passed within the run) and the frame index of the
    deepest penetration of each impact."""
    inContact = dy < -h0
    heights = []
    deepest = []
    i = 0
    n = len(dy)
    while i < n:
        if not inContact[i]:
            i += 1
            continue
        j = i
        while j < n and inContact[j]:
            j += 1
        deepest.append(i + int(np.argmin(dy[i:j])))
        k = j
        while k < n and not inContact[k]:
            k += 1
        seg = dy[j:k]
        if len(seg) >= 3 and int(np.argmax(seg)) < len(seg) - 1:
            heights.append(h0 + float(seg.max()))
        i = k
    return heights, deepest


def errors(caseDir):
    """Error measures of the rebounds, as numbers (no pass/fail): the
    largest relative error of a rebound height against h0 (reboundError)
    and the largest energy loss of a bounce, |1 - h/h_prev| (energyLoss);
    nan when the block does not rebound within the run."""
    c = cf.bouncingBlock
    t, dy, _ = history(caseDir)
    heights, _ = bounces(t, dy, c.h0)
    if not heights:
        return {"reboundError": float("nan"), "energyLoss": float("nan")}
    previous = [c.h0] + heights[:-1]
    return {"reboundError": max(abs(h - c.h0)/c.h0 for h in heights),
            "energyLoss": max(abs(1 - h/p) for h, p in zip(heights, previous))}


def main(argv):
    if len(argv) != 2 or argv[1] not in ("trapezoidal", "DDA"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    c = cf.bouncingBlock
    scheme = argv[1]
    t, dy, paths = history(argv[0])
    r = nf.report("bouncingBlock %s" % scheme)
    heights, deepest = bounces(t, dy, c.h0)
    r.info("first impact time [s]",
           float(t[deepest[0]]) if deepest else float("nan"), c.impactTime())
    r.info("rebounds", float(len(heights)))
    if not heights:
        r.failed = True
    for k, d in enumerate(deepest):
        n = closedContacts(nf.contactsFile(paths[d]))
        if n:
            r.info("impact %d: closed contacts n" % (k + 1), float(n))
            r.info("impact %d: omega dt" % (k + 1), c.omega(n)*c.deltaT)
        r.info("impact %d: penetration [m]" % (k + 1), float(-c.h0 - dy[d]),
               c.impactSpeed()/c.omega(n) if n else float("nan"))
    previous = c.h0
    for k, h in enumerate(heights):
        e = h/previous
        if scheme == "trapezoidal":
            r.relative("rebound %d height [m]" % (k + 1), h, c.h0, c.trapezoidalTolerance)
            r.upper("bounce %d energy loss |1 - h/h_prev|" % (k + 1), abs(1 - e),
                    c.energyDriftPerBounce)
        else:
            r.info("rebound %d height [m]" % (k + 1), h, c.h0)
            r.upper("bounce %d restitution h/h_prev" % (k + 1), e, 1.0 - 1e-12)
            if not np.isfinite(e) or e <= 0:
                r.failed = True
        previous = h
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
