#!/usr/bin/python3
"""Table of the six rough-fracture runs, from their logs and
postProcessing/ tables: where the faces first touch, the initial mean
aperture, the mean closure (mean Dy of the lower face - mean Dy of the
upper face), the horizontal offset and rotation of the upper block, the
closed contacts at the end, and the cost of the run.

    /usr/bin/python3 summary.py [-json]

Only the standard library is used. SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def lastRow(run, name):
    path = os.path.join(HERE, run, "postProcessing", name, "0", name + ".dat")
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    return [float(v) for v in rows[-1]], [float(v) for v in rows[0]]


def summarise(run):
    log = open(os.path.join(HERE, run, "log.nmmRoughFracture")).read()
    m = re.search(r"smallest \S+ m at x = (\S+) m, mean (\S+) m", log)
    upper, lower = lastRow(run, "upperFace")[0], lastRow(run, "lowerFace")[0]
    motion, start = lastRow(run, "upper")
    contacts = lastRow(run, "contacts")[0]
    solver = open(os.path.join(HERE, run, "log.nmmSolidFoam")).read()
    unknowns = re.search(r"unknowns (\d+)", solver).group(1)
    clock = re.findall(r"ClockTime = (\S+) s", solver)[-1]
    return {
        "run": run,
        "firstContactX_mm": 1e3*float(m.group(1)),
        "meanAperture_mm": 1e3*float(m.group(2)),
        "meanClosure_mm": 1e3*(lower[2] - upper[2]),
        "offset_mm": 1e3*(motion[1] - start[1]),
        "rotation_deg": motion[3]*180/3.141592653589793,
        "closedContacts": int(contacts[3] + contacts[4]),
        "steps": len(re.findall(r"^Time = ", solver, re.M)),
        "unknowns": int(unknowns),
        "clockTime_s": float(clock),
    }


def main():
    runs = [s + "Case" + str(n) for s in ("unconfined", "confined") for n in (1, 2, 3)]
    rows = [summarise(r) for r in runs if os.path.isdir(os.path.join(HERE, r))]
    if "-json" in sys.argv:
        print(json.dumps(rows, indent=1))
        return
    print("| run | first touch at x [mm] | mean aperture at start [mm] | mean closure [mm] "
          "| upper block offset [mm] | rotation [deg] | closed contacts | steps | unknowns | wall time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| {run} | {firstContactX_mm:.2f} | {meanAperture_mm:.3f} | {meanClosure_mm:.3f} "
              "| {offset_mm:+.3f} | {rotation_deg:+.3f} | {closedContacts} | {steps} "
              "| {unknowns} | {clockTime_s:.0f} |".format(**r))


main()
