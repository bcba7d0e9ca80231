#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/bondedTension and bondedShear/*
against the strength of a Mohr-Coulomb bond.

Usage:
    checkBondedInterface.py <caseDir> tension
    checkBondedInterface.py <caseDir> shear <sigmaN [MPa]>

Bonded interfaces of length L = 1 (closedForms.bondedInterface: T = 1 MPa,
c = 2 MPa, phi = 30 deg) loaded in quasi-static steps. From every contact
frame (VTK/contacts_<i>.vtp, time order) the interface forces are the sums
over its closed contacts of normalForce (tension: -sum) and shearForce:
  tension (one interface, y = 0):
    - the bond breaks during the run (no bondIntact left);
    - the peak tensile force is T L within one load step, the load step
      being the median increase of the force per step before the break;
    - after the break the interface carries no tension (< 1e-3 T L);
  shear (two interfaces, y = 0 and y = 0.2, each checked):
    - the bond breaks; the peak shear force is c L + sigma_n L tan(phi)
      within one load step (as above);
    - after the break the shear force is the residual
      sigma_n L tan(phi), within 2% of the peak, at every later frame;
    - before the break the normal force is sigma_n L within 2% of the peak.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL_RESIDUAL = 0.02
TOL_BROKEN = 1e-3


def histories(caseDir, levels):
    """Per interface (contacts nearest to each y level): arrays of time,
    tensile normal force, |shear force|, number of intact bonds."""
    out = {y: {"t": [], "N": [], "S": [], "intact": [], "contacts": []} for y in levels}
    lv = np.array(levels)
    for t, path in nf.readContactSeries(caseDir):
        c = nf.readContacts(path)
        which = (np.abs(c.x[:, 1][:, None] - lv[None, :]).argmin(axis=1)
                 if len(c.x) else np.zeros(0, int))
        for k, y in enumerate(levels):
            m = which == k
            closed = m & (c.data["contactState"] != 0)
            h = out[y]
            h["t"].append(t)
            h["N"].append(-float(c.data["normalForce"][closed].sum()))
            h["S"].append(abs(float(c.data["shearForce"][closed].sum())))
            h["intact"].append(int((c.data["bondIntact"][m] != 0).sum()))
            h["contacts"].append(int(m.sum()))
    return {y: {k: np.array(v) for k, v in h.items()} for y, h in out.items()}


def peakCheck(r, name, force, intact, expected):
    """Break, peak within one load step; returns the index of the first
    frame without an intact bond (or None)."""
    broken = np.nonzero(intact == 0)[0]
    first = int(broken[0]) if len(broken) else None
    r._add("%s: bond broken during the run" % name, float(first is not None),
           1.0, float("nan"), float("nan"), first is not None and first > 0, True)
    if first is None or first == 0:
        return None
    before = force[:first]
    steps = np.diff(before)
    dF = float(np.median(steps[steps > 0])) if (steps > 0).any() else 0.0
    r.info("%s: load step (median increase before the break)" % name, dF)
    r.absolute("%s: peak force" % name, float(force.max()), expected, dF)
    r.info("%s: frames with a partly broken bond" % name,
           float(((intact > 0) & (intact < intact[0])).sum()))
    return first


def tension(caseDir):
    b = cf.bondedInterface
    h = histories(caseDir, [0.0])[0.0]
    r = nf.report("bonded interface in tension: breaks at T L = %g N/m" % b.tensionPeak())
    first = peakCheck(r, "tension", h["N"], h["intact"], b.tensionPeak())
    if first is not None:
        after = h["N"][first:]
        r.upper("tension after the break (/ T L)",
                float(np.abs(after).max())/b.tensionPeak(), TOL_BROKEN)
    return r.finish()


def shear(caseDir, sigmaMPa):
    b = cf.bondedInterface
    sigma = sigmaMPa*1e6
    peak, residual = b.shearPeak(sigma), b.shearResidual(sigma)
    hs = histories(caseDir, [0.0, 0.2])
    r = nf.report("bonded interface in shear, sigma_n = %g MPa: peak %g, residual %g N/m"
                  % (sigmaMPa, peak, residual))
    for y, h in hs.items():
        name = "y = %g" % y
        first = peakCheck(r, name, h["S"], h["intact"], peak)
        if first is None:
            continue
        r.absolute("%s: normal force before the break" % name,
                   float(np.median(h["N"][:first]*-1)), sigma*b.L, TOL_RESIDUAL*peak)
        after = h["S"][first:]
        worst = float(after[np.argmax(np.abs(after - residual))])
        r.absolute("%s: shear force after the break (worst frame)" % name,
                   worst, residual, TOL_RESIDUAL*peak)
    return r.finish()


def main(argv):
    if len(argv) == 2 and argv[1] == "tension":
        return tension(argv[0])
    if len(argv) == 3 and argv[1] == "shear":
        return shear(argv[0], float(argv[2]))
    print(__doc__)
    return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
