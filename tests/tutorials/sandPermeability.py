#!/usr/bin/python3
"""Runs tutorials/coupling/sandPermeability with './Allrun -reduced' from a
scratch copy (the paper's sand compacted with cells of 50 um, then the
pore space at five stages solved by OpenFOAM's simpleFoam) and checks:

    sandPermeability.py <binDir> <projectDir> <workDir>

  - the compaction ends, and each of the five stages has its row in
    postProcessing/poreFlow/<time>/poreFlow.dat;
  - each flow is creeping (Reynolds number below 0.1: Darcy's law holds)
    and conserves mass (|Qout - Qin| below 1e-5 Qout, from the log);
  - the fluid's force on the grains and the walls (pressure and wall
    shear stress) balances the pressure drop times the inlet's width, to
    1% (steady flow: the momentum balance is exact);
  - the narrowest throat has at least cellsAcrossThroat (5) cells across;
  - compaction closes the pore space: the porosity falls from stage to
    stage, and the permeability with it, by at least a factor of two
    overall (the porosity of the box around the grains falls from 0.42
    to 0.27: a factor of 5.9 under Kozeny-Carman's law; the run gives 6);
  - the pictures are there: permeability.png, velocityStart.png and
    velocityEnd.png.
Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (the plot steps need numpy, matplotlib
and VTK, which Debian installs for that interpreter only).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import re
import sys

import paperTutorial

STAGES = ["0", "0.0001", "0.0002", "0.0003", "0.0015"]


def row(case, t):
    path = case/"compaction/postProcessing/poreFlow"/t/"poreFlow.dat"
    if not path.exists():
        return None
    lines = path.read_text().splitlines()
    names = [l for l in lines if l.startswith("# time")][0][1:].split()
    values = [l for l in lines if l and not l.startswith("#")][0].split()
    return {re.sub(r"\[.*\]", "", n): float(v) for n, v in zip(names, values)}


def main(argv):
    case = paperTutorial.runReduced(argv, "sandPermeability", ["compaction"], __doc__,
                                    group="coupling")
    if case is None:
        return 2
    check = paperTutorial.checks()
    if not check.ended(case, ["compaction"]):
        return check.exitCode()
    rows = [row(case, t) for t in STAGES]
    if not check(all(rows), "five stages written (%s)" % ", ".join(
            t for t, r in zip(STAGES, rows) if r)):
        return check.exitCode()
    for t, r in zip(STAGES, rows):
        print("t = %s: porosity %.4f, flow porosity %.4f, k = %.4g m2, Re %.3g, %d cells, "
              "throat %.3g m (%d cells across)" % (t, r["porosity"], r["flowPorosity"],
              r["permeability"], r["Reynolds"], r["cells"], r["throat"], r["cellsAcrossThroat"]))
        check(r["Reynolds"] < 0.1, "t = %s: creeping flow (Re %.3g)" % (t, r["Reynolds"]))
        check(r["cellsAcrossThroat"] >= 5, "t = %s: narrowest throat resolved (%d cells)"
              % (t, r["cellsAcrossThroat"]))
        log = (case/"compaction"/("log.nmmPoreFlow." + t)).read_text()
        balance = float(re.search(r"mass balance\s+(\S+)", log).group(1))
        check(balance < 1e-5, "t = %s: mass conserved (%.2g)" % (t, balance))
        forces = float(re.search(r"dp times the inlet.*\(balance (\S+)\)", log).group(1))
        check(forces < 0.01, "t = %s: the fluid's force on the grains and walls is dp times "
              "the inlet's width, to 1%% (%.2g)" % (t, forces))
    n = [r["porosity"] for r in rows]
    k = [r["permeability"] for r in rows]
    check(all(b < a for a, b in zip(n, n[1:])), "the porosity falls at every stage")
    check(all(b < a for a, b in zip(k, k[1:])), "the permeability falls at every stage")
    check(k[-1] < 0.5*k[0], "the permeability falls by at least half (%.3g)" % (k[-1]/k[0]))
    for png in ("permeability.png", "velocityStart.png", "velocityEnd.png"):
        path = case/"compaction/images"/png
        check(path.exists() and path.stat().st_size > 10000, "picture %s" % png)
    return check.exitCode()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
