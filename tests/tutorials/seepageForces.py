#!/usr/bin/python3
"""Runs tutorials/coupling/seepageForces with './Allrun -reduced' from a
scratch copy (12 grains on a grid in upward flow, coupled two way to
OpenFOAM's simpleFoam by nmmSeepageFoam; a run below the critical
hydraulic gradient, then a restart above it) and checks:

    seepageForces.py <binDir> <projectDir> <workDir>

  - both runs end, with a row of postProcessing/seepage/<start>/seepage.dat
    per fluid solve;
  - every flow is creeping (Reynolds number below 0.3) and its force on
    the grains and walls (pressure and wall shear stress) is the pressure
    drop times the column's width, to 1% (steady flow: exact);
  - below: the seepage force on the grains stays under their submerged
    weight (rho_s - rho_w) g A, and the pack stays on the grid: its lowest
    point within a tenth of a grain of the grid's top, at rest (the mean
    rise changes by less than 0.5 um over the last coupling interval,
    crossed in at most 100 steps: a pack held still by steps that
    collapsed would pass the first part);
  - above: the seepage force exceeds the submerged weight at every
    solve, the pack lifts off the grid (its lowest point a quarter of a
    grain above it), reaches the screen and stays against it (its highest
    point within a tenth of a grain of the screen at the last three
    solves). Rest is not asserted there: the grains under the top layer
    still drift, and pressed against the screen for long the contacts
    start to chatter between stuck and sliding, which collapses the steps;
  - each grain's equilibrium at the end of the first run, independent of
    the coupling's own bookkeeping: for every grain at rest (its mean
    displacement moved less than 0.05 um over the last write interval),
    the fluid's force on it (postProcessing/seepage/<time>/blockForces.dat,
    from OpenFOAM's p and wallShearStress), its weight less its buoyancy,
    (rho_s - rho_w) g A, and the forces of its contacts
    (VTK/contacts_*.vtp) add up to zero, to 3% of its submerged weight; at
    least a quarter of the grains must be at rest. A grain still slipping
    is left out: in the quasi-static steps the sum is its mass times its
    acceleration. This holds only if the fluid's forces reach the grains
    in full through the mapping onto their edges and the hydrostatic
    pressure gives them their buoyancy rho_w g A. The same sums at the end
    of the second run are printed, not checked: pressed against the
    screen, some contacts keep switching between stuck and sliding, and in
    the short steps that follows a grain can carry a force its
    displacement does not show;
  - the pictures are there.
Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (VTK and numpy are Debian's packages,
seen by that interpreter only).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import re
import sys
from pathlib import Path

import numpy as np

import paperTutorial

sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
import nmmVtk  # noqa: E402

RUNS = ("below", "above")
PITCH = 75e-6       # makeColumn.py's grain spacing; the grains are 0.65 to 0.85 of it


def rows(case, start):
    path = case/"postProcessing/seepage"/start/"seepage.dat"
    if not path.exists():
        return []
    lines = path.read_text().splitlines()
    names = [re.sub(r"\[.*\]", "", n)
             for n in [l for l in lines if l.startswith("# time")][0][1:].split()]
    return [dict(zip(names, map(float, l.split())))
            for l in lines if l.strip() and not l.startswith("#")]


def lastSteps(case, run, since):
    """The solid's steps after time since, from the run's log"""
    times = re.findall(r"(?m)^Time = (\S+)$", (case/("log.nmmSeepageFoam." + run)).read_text())
    return sum(1 for t in times if float(t) > since + 1e-12)


def column(case):
    """makeColumn.py's printout: the grid's top and the screen's bottom [m]"""
    text = (case/"log.makeColumn").read_text()
    value = (lambda name: float(re.search(name + r" ([0-9.eE+-]+)", text).group(1)))
    return value("grid top"), value("screen bottom")


def physics(case):
    """rho_s (the sand's, constant/mechanicalProperties), rho_w
    (nmmPoreFlowDict's density) [kg/m3] and |g| (constant/g) [m/s2]"""
    def find(pattern, name):
        return re.search(pattern, (case/name).read_text(), re.M).group(1)
    rhoS = float(find(r"sand\s*\{[^}]*\brho\s+([0-9.eE+-]+)", "constant/mechanicalProperties"))
    rhoW = float(find(r"^density\s+([0-9.eE+-]+)", "system/nmmPoreFlowDict"))
    g = [float(v) for v in find(r"value\s*\(([^)]*)\)", "constant/g").split()]
    return rhoS, rhoW, float(np.linalg.norm(g))


def blocks(case):
    """[(name, material, area [m2])] of system/nmmMeshDict, in its order
    (the .vtu's blockId)"""
    out = []
    for m in re.finditer(r"^\s*(\w+)\s*\{\s*material\s+(\w+);\s*polygon\s*\((.*)\);\s*\}",
                         (case/"system/nmmMeshDict").read_text(), re.M):
        pts = [tuple(map(float, p.split())) for p in re.findall(r"\(([^()]*)\)", m.group(3))]
        area = 0.5*abs(sum(x0*y1 - x1*y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1])))
        out.append((m.group(1), m.group(2), area))
    return out


def fluidForces(case, time):
    """{block name: (Fx, Fy)} of the fluid solve at that time [N/m]"""
    folder = [p for p in (case/"postProcessing/seepage").iterdir() if abs(float(p.name) - time) < 1e-9]
    lines = (folder[0]/"blockForces.dat").read_text().splitlines()
    return {l.split()[0]: tuple(map(float, l.split()[1:])) for l in lines if not l.startswith("#")}


def meanDisplacement(path):
    """{blockId: mean D of its points} of a .vtu frame"""
    f = nmmVtk.readFrame(path)
    ids = f.pointData["blockId"].astype(int)
    return {b: f.pointData["D"][ids == b].mean(axis=0) for b in set(ids)}


def equilibrium(case, time, loadTime, rhoS, rhoW, g):
    """Per grain at rest (its mean displacement moved less than 0.05 um
    since the frame before): (name, the sum of the forces on it over its
    submerged weight); and how many grains moved. The forces: the
    fluid's (the solve at loadTime), gravity with buoyancy
    -(rho_s - rho_w) g A, and its contacts' (each acts on its vertex's
    block, blockA, and the opposite on blockB)."""
    frames = nmmVtk.readSeries(case)
    k = min(range(len(frames)), key=lambda i: abs(frames[i][0] - time))
    now, before = meanDisplacement(frames[k][1]), meanDisplacement(frames[k - 1][1])
    contacts = dict(nmmVtk.readContactSeries(case))
    c = nmmVtk.readContacts(contacts[min(contacts, key=lambda t: abs(t - time))])
    total = {}
    for a, b, f in zip(c.data["blockA"].astype(int), c.data["blockB"].astype(int), c.data["force"]):
        total[a] = total.get(a, 0) + f[:2]
        total[b] = total.get(b, 0) - f[:2]
    fluid = fluidForces(case, loadTime)
    residuals, moving = [], 0
    for b, (name, material, area) in enumerate(blocks(case)):
        if material != "sand":
            continue
        if np.linalg.norm((now[b] - before[b])[:2]) > 0.05e-6:
            moving += 1
            continue
        weight = (rhoS - rhoW)*g*area
        F = total.get(b, np.zeros(2)) + np.array(fluid[name]) - np.array((0, weight))
        residuals.append((name, np.linalg.norm(F)/weight))
    return residuals, moving


def main(argv):
    case = paperTutorial.runReduced(argv, "seepageForces", ["[0-9]*.[0-9]*", "VTK", "poreFlow*",
                                    "postProcessing", "images.reduced", "log.*"], __doc__,
                                    group="coupling")
    if case is None:
        return 2
    check = paperTutorial.checks()
    for run in RUNS:
        log = case/("log.nmmSeepageFoam." + run)
        check(log.exists() and "\nEnd" in log.read_text(), "%s ended (%s)" % (run, log))
    starts = sorted((p.parent.name for p in case.glob("postProcessing/seepage/*/seepage.dat")),
                    key=float)
    table = {run: rows(case, s) for run, s in zip(RUNS, starts)}
    if not check(len(starts) == 2 and all(len(table[r]) >= 3 for r in RUNS),
                 "a seepage table per run, with its rows (%s)" % ", ".join(starts)):
        return check.exitCode()
    gridTop, screenBottom = column(case)
    for run in RUNS:
        r = table[run]
        check(max(x["Reynolds"] for x in r) < 0.3, "%s: creeping flow (Re up to %.3g)"
              % (run, max(x["Reynolds"] for x in r)))
        check(max(x["forceBalance"] for x in r) < 0.01, "%s: the fluid's force on the grains "
              "and walls is dp times the width, to 1%% (worst %.2g)"
              % (run, max(x["forceBalance"] for x in r)))
    below, above = table["below"], table["above"]
    check(all(x["liftRatio"] < 1 for x in below), "below: seepage force under the submerged "
          "weight (ratio %.3f to %.3f)" % (min(x["liftRatio"] for x in below),
                                           max(x["liftRatio"] for x in below)))
    check(below[-1]["packBottom"] - gridTop < 0.1*PITCH, "below: the pack rests on the grid "
          "(its lowest point %.2g um above it)" % (1e6*(below[-1]["packBottom"] - gridTop)))
    settle = abs(below[-1]["rise"] - below[-2]["rise"])
    steps = lastSteps(case, "below", below[-1]["time"])
    check(settle < 0.5e-6 and steps <= 100, "below: the pack is at rest (the mean rise moved "
          "%.2g um over the last interval, which the solid crossed in %d steps: not held "
          "still by collapsed steps)" % (1e6*settle, steps))
    check(all(x["liftRatio"] > 1 for x in above), "above: seepage force over the submerged "
          "weight (ratio %.3f to %.3f)" % (min(x["liftRatio"] for x in above),
                                          max(x["liftRatio"] for x in above)))
    check(above[-1]["packBottom"] - gridTop > 0.25*PITCH, "above: the pack has left the grid "
          "(its lowest point %.3g um above it)" % (1e6*(above[-1]["packBottom"] - gridTop)))
    gaps = [1e6*(screenBottom - x["packTop"]) for x in above[-3:]]
    check(max(gaps) < 0.1*PITCH*1e6, "above: the pack has reached the screen and stays "
          "against it (its highest point %s um below it at the last three solves)"
          % ", ".join("%.2g" % g for g in gaps))
    for run in RUNS:
        end = float((case/("log.nmmSeepageFoam." + run)).read_text()
                    .rsplit("\nTime = ", 1)[1].split()[0])
        residuals, moving = equilibrium(case, end, table[run][-1]["time"], *physics(case))
        grains = len(residuals) + moving
        worst = max(residuals, key=lambda r: r[1]) if residuals else ("none", 0)
        what = ("%s: each grain at rest (%d of %d) is in equilibrium under the fluid's force, "
                "gravity and buoyancy and its contacts, to 3%% of its submerged weight (worst "
                "%.2g, %s)" % (run, len(residuals), grains, worst[1], worst[0]))
        if run == "below":
            check(4*len(residuals) >= grains and worst[1] < 0.03, what)
        else:
            print("info: " + what)
    for png in ("seepage.png", "grains_0.1.png", "velocity.png"):
        path = case/"images.reduced"/png
        check(path.exists() and path.stat().st_size > 10000, "picture %s" % png)
    return check.exitCode()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
