#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""Thermal expansion through the FMU's C interface
(build/fmu/thermalBlocks.fmu, tutorials/coupling/thermalBlocks):

    fmuThermal.py <fmuDir> <projectDir> <binDir> <workDir>

An importer sets blocks.temperature to Tref + dT for both blocks, does the
static step and reads blocks.stress and the free block's face
displacements (tutorials/coupling/thermalBlocks/thermalMaster.py).
Plane strain, against the closed forms, to 1e-9 of E alpha dT (stresses)
or of the free expansion (displacements):
  - the free block on rollers expands by (1 + nu) alpha dT in x and y,
    with no in-plane stress and sigma_zz = -E alpha dT;
  - the confined block: sigma_xx = sigma_yy = sigma_zz = -E alpha dT/(1 - 2 nu),
    sigma_xy = 0;
  - the free block's hole, the only pore (pores.area, centroid, porosity):
    its sides stretch by 1 + (1 + nu) alpha dT, its centroid moves with the
    material from the rollers, and the enclosed porosity is its area over
    both blocks' outer areas.
The state before the step is restored with fmi3SetFMUState and the step
repeated at 2 dT: every output doubles, to the same tolerance. A last
step back to Tref returns every output to zero. Then, from the start
again, a pressure in the pore (pores.pressure) grows it and pushes the
free block's right face out, twice the pressure twice as far (the unit test couplingInterface.aPorePressure...
checks that it acts as a patch pressure on the hole's edges would).
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fmuChecks  # noqa: E402

TOL = 1e-9


def checkStep(t, tm, r, dT, scaleDT):
    eps, szz, sc = tm.closedForms(dT)
    stressScale = tm.E*tm.ALPHA*scaleDT
    strainScale = (1 + tm.NU)*tm.ALPHA*scaleDT
    free, confined = r["stress"]
    what = "dT = %g: " % dT
    t.close(TOL, r["right"][0], eps*1.0, strainScale*1.0, what + "free block, right face ux")
    t.close(TOL, r["top"][1], eps*2.0, strainScale*2.0, what + "free block, top face uy")
    for k, name in enumerate(("xx", "yy", "xy")):
        t.close(TOL, free[k], 0.0, stressScale, what + "free block, sigma_" + name)
    t.close(TOL, free[3], szz, stressScale, what + "free block, sigma_zz")
    for k, name in enumerate(("xx", "yy", "xy", "zz")):
        t.close(TOL, confined[k], 0.0 if name == "xy" else sc, stressScale,
                what + "confined block, sigma_" + name)
    grown = (1 + eps)**2
    if t.check(len(r["pores"]) == 1, what + "one pore, the free block's hole"):
        t.close(TOL, r["pores"][0], tm.HOLE*grown, tm.HOLE, what + "its area")
        t.close(TOL, r["centroids"][0][0], 0.5*(1 + eps), 1.0, what + "its centroid, x")
        t.close(TOL, r["centroids"][0][1], 1.0*(1 + eps), 1.0, what + "its centroid, y")
    t.close(TOL, r["porosity"], tm.HOLE*grown/(2*grown + 2), 1.0, what + "enclosed porosity")


def main():
    t = fmuChecks.run(__doc__)
    sys.path.insert(0, str(t.project/"tutorials/coupling/thermalBlocks"))
    import fmi3Master
    import thermalMaster as tm

    dT = 50.0
    fmu = fmi3Master.fmu(t.fmus/"thermalBlocks.fmu", t.work/"extracted")
    solid = fmu.instantiate("thermal")
    T0 = solid.get("blocks.temperature")
    t.check(list(T0) == [tm.TREF, tm.TREF], "the temperatures start at Tref: %s" % T0)
    solid.enterInitializationMode(0.0)
    solid.exitInitializationMode()
    start = solid.getState()
    checkStep(t, tm, tm.heat(solid, 0.0, dT), dT, dT)
    solid.setState(start)
    t.check(solid.get("time") == 0.0, "fmi3SetFMUState takes the time back to 0")
    checkStep(t, tm, tm.heat(solid, 0.0, 2*dT), 2*dT, 2*dT)
    checkStep(t, tm, tm.heat(solid, 1.0, 0.0), 0.0, 2*dT)
    # A pressure in the pore pushes its walls out, linearly (small
    # displacements): twice the pressure moves the free faces twice as far
    grow, ux = [], []
    for p in (1e6, 2e6):
        solid.setState(start)
        solid.set("pores.pressure", [p] + [0.0]*(int(solid.get("pores.capacity")) - 1))
        solid.doStep(0.0, 1.0)
        grow.append(solid.get("pores.area")[0] - tm.HOLE)
        ux.append(solid.get("freeRight.displacement")[0][0])
    t.check(grow[0] > 0 and ux[0] > 0, "a pore pressure of 1 MPa grows the pore (by %.3e m2)"
            " and pushes the free block's right face out (%.3e m)" % (grow[0], ux[0]))
    t.close(TOL, ux[1], 2*ux[0], ux[0], "twice the pore pressure, twice the displacement")
    solid.freeState(start)
    solid.terminate()
    solid.free()
    return t.end()


if __name__ == "__main__":
    sys.exit(main())
