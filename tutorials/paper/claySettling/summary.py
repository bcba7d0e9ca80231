#!/usr/bin/python3
"""Table of the clay settling run(s), from their logs, postProcessing/
tables and last VTK frame: the porosity of the sediment at the start and
at the end and its loss, the pseudo-time by which it settled, the
largest vertical displacement of a platelet, the contacts closed at the
end, and the cost of the run.

    /usr/bin/python3 summary.py [-json]

The largest displacement is read from the last frame with VTK, which is
Debian's python3-vtk9, seen by /usr/bin/python3 only.
SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# bin/tools/nmmVtk.py reads the frames; a copy of the tutorial finds it
# through etc/bashrc's NMM_PROJECT_DIR, the tutorial in place without it
sys.path.insert(0, os.path.join(
    os.environ.get("NMM_PROJECT_DIR") or os.path.join(HERE, "..", "..", ".."),
    "bin", "tools"))
import nmmVtk  # noqa: E402
RUNS = ["settling", "settlingReduced"]


def rows(run, name):
    path = os.path.join(HERE, run, "postProcessing", name, "0", name + ".dat")
    return [[float(v) for v in l.split()] for l in open(path)
            if l.strip() and not l.startswith("#")]


def lastFrameDisplacements(run):
    """Downward and horizontal extremes of the point displacements of the
    platelets (material 0, clay) in the last frame [m]."""
    f = nmmVtk.readFrame(nmmVtk.latestFrame(
        os.path.join(HERE, run, "VTK", run + ".vtu.series")))
    D = f.pointData["D"]
    material = f.cellData["materialId"]
    clay = set()
    for cell, ids in enumerate(f.cells):
        if material[cell] == 0:
            clay.update(ids)
    clay = sorted(clay)
    return -D[clay, 1].min(), abs(D[clay, 0]).max()


def settledAt(porosity, tolerance=1e-3):
    """First time from which the porosity stays within tolerance of its
    final value."""
    final = porosity[-1][4]
    t = porosity[-1][0]
    for r in reversed(porosity):
        if abs(r[4] - final) > tolerance:
            break
        t = r[0]
    return t


def summarise(run):
    porosity = rows(run, "porosity")    # time solidArea regionArea top porosity
    contacts = rows(run, "contacts")    # time deltaT open bonded sliding ...
    solver = open(os.path.join(HERE, run, "log.nmmSolidFoam")).read()
    down, side = lastFrameDisplacements(run)
    n0, n1 = porosity[0][4], porosity[-1][4]
    return {
        "run": run,
        "porosityStart": n0,
        "porosityEnd": n1,
        "porosityLoss": (n0 - n1)/n0,
        "solidAreaStart": porosity[0][1],
        "solidAreaEnd": porosity[-1][1],
        "topStart_um": 1e6*porosity[0][3],
        "topEnd_um": 1e6*porosity[-1][3],
        "settledAt": settledAt(porosity),
        "endTime": porosity[-1][0],
        "maxDown_um": 1e6*down,
        "maxSideways_um": 1e6*side,
        "closedEnd": int(contacts[-1][3] + contacts[-1][4]),
        "maxPenetration": max(r[6] for r in contacts),
        "steps": len(re.findall(r"^Time = ", solver, re.M)),
        "cuts": len(re.findall(r"step cut", solver)),
        "unknowns": int(re.search(r"unknowns (\d+)", solver).group(1)),
        "clockTime_s": float(re.findall(r"ClockTime = (\S+) s", solver)[-1]),
    }


def main():
    table = [summarise(r) for r in RUNS if os.path.isdir(os.path.join(HERE, r))]
    if "-json" in sys.argv:
        print(json.dumps(table, indent=1))
        return
    print("| run | porosity, start | porosity, end | porosity loss "
          "| sediment top [um] | settled at | largest vertical displacement [um] "
          "| largest horizontal displacement [um] | closed contacts, end "
          "| largest penetration [m] | steps (cut) | unknowns | wall time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in table:
        print("| {run} | {porosityStart:.3f} | {porosityEnd:.3f} | {porosityLoss:.0%} "
              "| {topStart_um:.2f} -> {topEnd_um:.2f} | {settledAt:.2g} of {endTime:.2g} "
              "| {maxDown_um:.2f} | {maxSideways_um:.2f} | {closedEnd} "
              "| {maxPenetration:.1e} | {steps} ({cuts}) | {unknowns} | {clockTime_s:.0f} |"
              .format(**r))


main()
