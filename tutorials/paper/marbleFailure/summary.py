#!/usr/bin/python3
"""Table of the four marble runs, from their logs and postProcessing/
tables: the mean vertical displacement of the top, the contacts open at
the start and at the end (a grain boundary that opens is a crack), the
bonds broken, the largest displacement, and the cost of the run.

    /usr/bin/python3 summary.py [-json]

Only the standard library is used. SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = ["load11MPaStrength", "load11MPaNoStrength", "load110MPaStrength", "load110MPaNoStrength"]


def rows(run, name):
    path = os.path.join(HERE, run, "postProcessing", name, "0", name + ".dat")
    return [[float(v) for v in l.split()] for l in open(path)
            if l.strip() and not l.startswith("#")]


def summarise(run):
    contacts = rows(run, "contacts")    # time deltaT open bonded sliding bondsBroken ...
    top = rows(run, "top")              # time Dx Dy length
    solver = open(os.path.join(HERE, run, "log.nmmSolidFoam")).read()
    return {
        "run": run,
        "topDy_um": 1e6*top[-1][2],
        "openFirstStep": int(contacts[0][2]),
        "openEnd": int(contacts[-1][2]),
        "closedEnd": int(contacts[-1][3] + contacts[-1][4]),
        "bondsBroken": int(sum(r[5] for r in contacts)),
        "maxD_um": 1e6*float(re.findall(r"max \|D\| = (\S+)", solver)[-1]),
        "steps": len(re.findall(r"^Time = ", solver, re.M)),
        "unknowns": int(re.search(r"unknowns (\d+)", solver).group(1)),
        "clockTime_s": float(re.findall(r"ClockTime = (\S+) s", solver)[-1]),
    }


def main():
    table = [summarise(r) for r in RUNS if os.path.isdir(os.path.join(HERE, r))]
    if "-json" in sys.argv:
        print(json.dumps(table, indent=1))
        return
    print("| run | top Dy [um] | open contacts, first step | open contacts, end "
          "| closed contacts, end | bonds broken | largest displacement [um] "
          "| steps | unknowns | wall time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in table:
        print("| {run} | {topDy_um:.3f} | {openFirstStep} | {openEnd} | {closedEnd} "
              "| {bondsBroken} | {maxD_um:.3f} | {steps} | {unknowns} | {clockTime_s:.0f} |"
              .format(**r))


main()
