#!/usr/bin/python3
"""Table of the sand compaction run, from its log and postProcessing/
tables: how far the platen went down (each half of it and its tilt),
the porosity at the start and at the end, for the whole sample and per
half, the largest displacement and rotation of a grain, how far the
platen moved over the last quarter of the run (a packing at rest: close
to 0), and the cost of the run.

    /usr/bin/python3 summary.py [-json]

The porosity of a half at the end is its grains' area over the area
under that half of the platen. The platen stays straight (a 100 um
quartz plate spanning the whole 1 mm under 1 MPa would bend by 3 um,
against a shortening of hundreds of um), so that area is the half's
width times its starting height plus the mean displacement of the
half's underside. The porosity function object's value, below the
platen's lowest point, misses the grains above that point when the
platen tilts.

Only the standard library is used. SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = ["compaction", "compactionLarge"]


def table(run, name):
    """Header names and rows of a function object's table"""
    path = os.path.join(HERE, run, "postProcessing", name, "0", name + ".dat")
    lines = open(path).read().splitlines()
    header = lines[0].lstrip("#").split()
    rows = [[float(v) for v in l.split()] for l in lines[1:] if l.strip()]
    return header, rows


def at(rows, time):
    """The last row at or before time"""
    return [r for r in rows if r[0] <= time][-1]


def summarise(run):
    _, left = table(run, "platenLeft")          # time Dx Dy length
    _, right = table(run, "platenRight")
    _, platen = table(run, "platen")            # time x y rotation Ux Uy
    _, porosity = table(run, "porosity")        # time solidArea regionArea top porosity
    _, sandLeft = table(run, "sandLeft")
    _, sandRight = table(run, "sandRight")
    header, grains = table(run, "grains")
    _, contacts = table(run, "contacts")        # time deltaT open bonded sliding ...
    solver = open(os.path.join(HERE, run, "log.nmmSolidFoam")).read()
    mesh = open(os.path.join(HERE, run, "system", "nmmMeshDict")).read()

    # The boxes of the function objects: their width is the region's area
    # over its height at the start, when the platen is at their top
    height = sandLeft[0][3]

    def halfPorosity(sand, platenHalf):
        width = sand[0][2]/height
        return 1 - sand[-1][1]/(width*(height + platenHalf[-1][2]))

    names = [h.split(":")[0] for h in header[1::5]]
    moves, turns, dyLeft, dyRight = [], [], [], []
    for k, name in enumerate(names):
        x0, y0 = grains[0][1 + 5*k], grains[0][2 + 5*k]
        x1, y1, turn = grains[-1][1 + 5*k], grains[-1][2 + 5*k], grains[-1][3 + 5*k]
        moves.append((math.hypot(x1 - x0, y1 - y0), name))
        turns.append((abs(turn), name))
        (dyLeft if x0 < sandLeft[0][2]/height else dyRight).append(y1 - y0)

    end = left[-1][0]
    meanDy = 0.5*(left[-1][2] + right[-1][2])
    quarter = 0.5*(at(left, 0.75*end)[2] + at(right, 0.75*end)[2])
    return {
        "run": run,
        "cellSize_um": 1e6*float(re.search(r"^\s*cellSize\s+([^;]+);", mesh, re.M).group(1)),
        "platenDy_um": 1e6*meanDy,
        "platenLeftDy_um": 1e6*left[-1][2],
        "platenRightDy_um": 1e6*right[-1][2],
        "platenTilt_deg": math.degrees(platen[-1][3]),
        "lastQuarterDy_um": 1e6*(meanDy - quarter),
        "porosityStart": porosity[0][4],
        "porosityEnd": 1 - (sandLeft[-1][1] + sandRight[-1][1])
                       / ((sandLeft[0][2] + sandRight[0][2])/height*(height + meanDy)),
        "porosityBelowLowestPointEnd": porosity[-1][4],
        "porosityLeftStart": sandLeft[0][4],
        "porosityLeftEnd": halfPorosity(sandLeft, left),
        "porosityRightStart": sandRight[0][4],
        "porosityRightEnd": halfPorosity(sandRight, right),
        "grainDyLeft_um": 1e6*sum(dyLeft)/len(dyLeft),
        "grainDyRight_um": 1e6*sum(dyRight)/len(dyRight),
        "maxGrainDisplacement_um": 1e6*max(moves)[0],
        "maxGrainDisplacementGrain": max(moves)[1],
        "maxGrainRotation_deg": math.degrees(max(turns)[0]),
        "maxGrainRotationGrain": max(turns)[1],
        "grainsRotatedOver10deg": sum(1 for t, _ in turns if t > math.radians(10)),
        "grains": len(names),
        "closedContactsEnd": int(contacts[-1][3] + contacts[-1][4]),
        "steps": len(re.findall(r"^Time = ", solver, re.M)),
        "cuts": int(sum(r[8] for r in contacts)),
        "unknowns": int(re.search(r"unknowns (\d+)", solver).group(1)),
        "clockTime_s": float(re.findall(r"ClockTime = (\S+) s", solver)[-1]),
        "ended": "\nEnd" in solver,
    }


# One line of the table per quantity: a column per run
LINES = [
    ("cell size [um]", "{cellSize_um:.0f}"),
    ("platen displacement, mean [um]", "{platenDy_um:.1f}"),
    ("platen displacement, left half, right half [um]", "{platenLeftDy_um:.1f}, {platenRightDy_um:.1f}"),
    ("platen tilt [deg]", "{platenTilt_deg:+.2f}"),
    ("platen displacement over the last quarter of the run [um]", "{lastQuarterDy_um:.2f}"),
    ("porosity, start to end (loss)", "{porosityStart:.3f} to {porosityEnd:.3f} ({lossPercent:.0f}%)"),
    ("porosity, left half", "{porosityLeftStart:.3f} to {porosityLeftEnd:.3f}"),
    ("porosity, right half", "{porosityRightStart:.3f} to {porosityRightEnd:.3f}"),
    ("porosity below the platen's lowest point, end", "{porosityBelowLowestPointEnd:.3f}"),
    ("mean vertical displacement of the grains, left half, right half [um]", "{grainDyLeft_um:.1f}, {grainDyRight_um:.1f}"),
    ("largest grain displacement [um]", "{maxGrainDisplacement_um:.1f} ({maxGrainDisplacementGrain})"),
    ("largest grain rotation [deg]", "{maxGrainRotation_deg:.1f} ({maxGrainRotationGrain})"),
    ("grains turned by more than 10 deg", "{grainsRotatedOver10deg} of {grains}"),
    ("closed contacts at the end", "{closedContactsEnd}"),
    ("steps (and attempts cut and redone)", "{steps} ({cuts})"),
    ("unknowns", "{unknowns}"),
    ("wall time [s]", "{clockTime_s:.0f}"),
]


def main():
    rows = [summarise(r) for r in RUNS if os.path.isdir(os.path.join(HERE, r))]
    if "-json" in sys.argv:
        print(json.dumps(rows, indent=1))
        return
    for r in rows:
        r["lossPercent"] = 100*(r["porosityStart"] - r["porosityEnd"])/r["porosityStart"]
    print("| | " + " | ".join(r["run"] for r in rows) + " |")
    print("|---|" + "---|"*len(rows))
    for label, form in LINES:
        print("| " + label + " | " + " | ".join(form.format(**r) for r in rows) + " |")


main()
