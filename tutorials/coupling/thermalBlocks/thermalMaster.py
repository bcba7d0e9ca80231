#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""Heat the two blocks of thermalBlocks.fmu through its FMI 3.0 interface
and compare with the closed forms of thermal expansion.

Usage:
    thermalMaster.py <thermalBlocks.fmu> [dT, default 50]

The importer raises both blocks' temperature by dT in one static step
(blocks.temperature) and reads blocks.stress and the displacements of the
free block's right and top faces. Plane strain, E = 50 GPa, nu = 0.25,
alpha = 8e-6 /K (the case's granite):
  - the free block (1 m x 2 m on rollers) holds only its zz strain, so it
    expands in the plane by (1 + nu) alpha dT with no in-plane stress and
    sigma_zz = -E alpha dT; its hole (the only pore, 0.4 m2) grows by
    (1 + (1 + nu) alpha dT)^2, and the enclosed porosity is the hole over
    both blocks' outer areas (2 (1 + (1 + nu) alpha dT)^2 + 2 m2);
  - the confined block (on rollers all round) cannot strain at all:
    sigma_xx = sigma_yy = sigma_zz = -E alpha dT/(1 - 2 nu).
Then it takes the solid back to the start with fmi3SetFMUState, repeats
the step at 2 dT (the stresses double) and returns to Tref (all zero).
Prints each quantity against its closed form.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import sys
from pathlib import Path

# The importer sits beside the tutorials (or in the project's copy)
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
if os.environ.get("NMM_PROJECT_DIR"):
    sys.path.append(os.path.join(os.environ["NMM_PROJECT_DIR"], "tutorials", "coupling"))
import fmi3Master  # noqa: E402

E, NU, ALPHA, TREF = 50e9, 0.25, 8e-6, 293.15
HOLE = 0.4      # the free block's hole (its only pore) [m2]


def closedForms(dT):
    """(free block's in-plane strain, its sigma_zz, the confined stress)"""
    # + 0.0: no negative zeros at dT = 0
    return (1 + NU)*ALPHA*dT, -E*ALPHA*dT + 0.0, -E*ALPHA*dT/(1 - 2*NU) + 0.0


def heat(solid, t, dT):
    solid.set("blocks.temperature", [TREF + dT, TREF + dT])
    status, _ = solid.doStep(t, 1.0)
    if status != fmi3Master.OK:
        raise SystemExit("the step was not completed: " + solid.lastMessage())
    n = int(solid.get("pores.nPores"))
    return {
        "right": solid.get("freeRight.displacement")[0],
        "top": solid.get("freeTop.displacement")[0],
        "stress": solid.get("blocks.stress"),
        "pores": solid.get("pores.area")[:n],
        "centroids": solid.get("pores.centroid")[:n],
        "porosity": solid.get("pores.porosity"),
    }


def report(r, dT):
    eps, szz, sc = closedForms(dT)
    free, confined = r["stress"]
    rows = [
        ("free: right face ux [m]", r["right"][0], eps*1.0),
        ("free: top face uy [m]", r["top"][1], eps*2.0),
        ("free: |in-plane stress| [Pa]", abs(free[:3]).max(), 0.0),
        ("free: sigma_zz [Pa]", free[3], szz),
        ("confined: sigma_xx [Pa]", confined[0], sc),
        ("confined: sigma_yy [Pa]", confined[1], sc),
        ("confined: sigma_xy [Pa]", confined[2], 0.0),
        ("confined: sigma_zz [Pa]", confined[3], sc),
        ("free: pore area [m2]", r["pores"][0] if len(r["pores"]) == 1 else math.nan,
         HOLE*(1 + eps)**2),
        ("enclosed porosity", r["porosity"], HOLE*(1 + eps)**2/(2*(1 + eps)**2 + 2)),
    ]
    print("dT = %g K" % dT)
    for name, value, exact in rows:
        print("    %-30s %14.6e   closed form %14.6e" % (name, value, exact))
    return rows


def main():
    path = sys.argv[1]
    dT = float(sys.argv[2]) if len(sys.argv) > 2 else 50.0
    fmu = fmi3Master.fmu(path)
    try:
        solid = fmu.initialized("thermal")
        start = solid.getState()
        report(heat(solid, 0.0, dT), dT)
        solid.setState(start)
        report(heat(solid, 0.0, 2*dT), 2*dT)
        report(heat(solid, 1.0, 0.0), 0.0)
        solid.freeState(start)
        solid.terminate()
        solid.free()
    finally:
        fmu.remove()


if __name__ == "__main__":
    main()
