#!/usr/bin/python3
# Debian's /usr/bin/python3: the contact frames are read through
# bin/tools/nmmVtk, which needs python3-vtk9 and numpy.
"""Runs tutorials/contact/grainsInBox with its Allrun from a scratch copy,
to endTime (default the tutorial's), and checks the pile against the
energy balance and the contact limits:

    grainsInBox.py <binDir> <projectDir> <workDir> [endTime]

  - nmmSolidFoam ends with End, the logs and tables hold no NaN or inf,
    and Allrun rendered the last frame (grainsInBox.png);
  - energy (postProcessing/balance): the total, kinetic + strain +
    contact - work of gravity, starts at 0 and can only be dissipated:
    it never rises by more than 1e-3 of the work done by the end in one
    step, and ends below 0;
  - the write times: every time directory is a multiple of the
    controlDict's writeInterval (to 1e-9 of it). A step fitted to end on
    a write time and cut and redone 0.7 times as long once wrote where it
    ended: "0.199538";
  - statics at rest (the last contact frame): the forces the box carries
    add up to the grains' weight, rho g times their areas in the first
    frame, within 1e-3 of it, vertically and sideways (measured: 3e-5
    and 4e-5);
  - the pile rests on its springs: at every closed contact of the last
    frame the normal force is the spring's, kN times the penetration,
    within 1e-6 of the weight (kN = normalPenalty x max(l/lRef, 0.05),
    l the contact's tributary length, normalPenalty and lRef as the log
    prints them: docs/case-reference.md), and no spring carries more than
    the whole weight. So no contact has sunk further than the pile's
    weight would push it on its own spring. (Until 2026-12-08 the bound
    was 1e-6 m on every contact; a corner resting on the floor has a
    spring 0.2 of the reference and sank 1.07e-6 m under 0.19 of the
    weight once the write times were mended);
  - the law (VTK/contacts.vtp.series, every written frame): no sliding
    contact carries tension. Mohr-Coulomb slides a contact without
    cohesion only while it is pressed; a sliding contact pulled apart
    would drag its friction along (before the contact-space solve
    opened such contacts, two frames had one, at -26 and -18 N/m).
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
import nmmVtk  # noqa: E402
import numpy  # noqa: E402


def table(path):
    rows = []
    for line in path.read_text().splitlines():
        if line and not line.startswith("#"):
            rows.append([float(x) for x in line.split()])
    return rows


def slidingInTension(frames):
    """(frame, normal force) of each sliding contact point pulled apart."""
    found = []
    for _, path in frames:
        c = nmmVtk.readContacts(path)
        for state, fn in zip(c.data["contactState"], c.data["normalForce"]):
            if state == 2 and fn < 0:
                found.append((path.name, fn))
    return found


def offTheWriteGrid(case):
    """Time directories that are not multiples of writeInterval."""
    control = (case/"system/controlDict").read_text()
    interval = float(re.search(r"(?m)^writeInterval\s+([^;\s]+)\s*;", control).group(1))
    found = []
    for d in case.iterdir():
        try:
            t = float(d.name)
        except ValueError:
            continue
        if abs(t/interval - round(t/interval)) > 1e-9:
            found.append("time directory %s is not a multiple of writeInterval %g"
                         % (d.name, interval))
    return found


def grainWeight(case):
    """rho g times the grains' areas in the first frame [N/m]: every block
    but the box (block 0), of the tutorial's single grain material."""
    first = nmmVtk.readSeries(case)[0][1]
    f = nmmVtk.readFrame(first)
    props = (case/"constant/mechanicalProperties").read_text()
    rho = float(re.search(r"rock\s*\{[^}]*\brho\s+([^;\s]+)", props).group(1))
    g = abs(float(re.search(r"value\s*\(\s*\S+\s+(\S+)",
                            (case/"constant/g").read_text()).group(1)))
    area = 0.0
    for cell, block in zip(f.cells, f.cellData["blockId"]):
        if int(block) == 0:
            continue
        x, y = f.x[cell, 0], f.x[cell, 1]
        area += 0.5*float((x*numpy.roll(y, -1) - numpy.roll(x, -1)*y).sum())
    return rho*g*area


def restsOnItsSprings(case, log, path):
    """Statics and the spring law at the contacts of the last frame."""
    m = re.search(r"contact: normalPenalty (\S+),.*tributary length of (\S+)\)", log)
    if not m:
        return ["no contact penalty line in log.nmmSolidFoam"]
    normalPenalty, lRef = float(m.group(1)), float(m.group(2))
    weight = grainWeight(case)
    d = nmmVtk.readContacts(path).data
    carried = numpy.zeros(2)
    largest = (0.0, 0.0, 0.0)
    failures = []
    for state, a, b, force, fn, p, l in zip(
            d["contactState"], d["blockA"], d["blockB"], d["force"],
            d["normalForce"], d["penetration"], d["length"]):
        if state == 0:
            continue
        # The force acts on blockA: on the box where it is the vertex's
        if int(b) == 0:
            carried -= force[:2]
        elif int(a) == 0:
            carried += force[:2]
        spring = normalPenalty*max(l/lRef, 0.05)*p
        largest = max(largest, (p, spring, fn))
        if abs(fn - spring) > 1e-6*weight or spring > weight:
            failures.append("%s: a contact with %.4g N/m of normal force and"
                            " %.3g m of penetration (its spring %.4g N/m, the"
                            " weight %.4g N/m)" % (path.name, fn, p, spring, weight))
    print("the grains weigh %.6g N/m; the box carries (%.4g, %.6g) N/m; the"
          " deepest contact %.3g m, %.4g N/m on its spring"
          % (weight, carried[0], carried[1], largest[0], largest[1]))
    if not (abs(carried[1] + weight) <= 1e-3*weight and abs(carried[0]) <= 1e-3*weight):
        failures.append("the box carries (%.4g, %.4g) N/m of the grains' %.4g N/m"
                        % (carried[0], carried[1], weight))
    return failures


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__)
        return 1
    binDir, project, work = Path(argv[0]), Path(argv[1]), Path(argv[2])
    case = work/"grainsInBox"
    if case.exists():
        shutil.rmtree(case)
    case.parent.mkdir(parents=True, exist_ok=True)
    shutil.copytree(project/"tutorials/contact/grainsInBox", case)
    if len(argv) == 4:
        control = case/"system/controlDict"
        text, n = re.subn(r"(?m)^(endTime\s+)[^;]*;", r"\g<1>%s;" % argv[3],
                          control.read_text())
        if n != 1:
            print("FAIL: no endTime in %s" % control)
            return 1
        control.write_text(text)
    env = dict(os.environ, NMM_PROJECT_DIR=str(project),
               PATH=str(binDir) + os.pathsep + os.environ.get("PATH", ""))
    subprocess.run(["bash", "./Allrun"], cwd=case, env=env, check=False)

    failures = []
    log = (case/"log.nmmSolidFoam").read_text() if (case/"log.nmmSolidFoam").exists() else ""
    if [l for l in log.splitlines() if l.strip()][-1:] != ["End"]:
        failures.append("log.nmmSolidFoam does not end with End")
    if not (case/"grainsInBox.png").exists():
        failures.append("Allrun did not write grainsInBox.png")
    balance = table(next((case/"postProcessing/balance").glob("*/balance.dat")))
    contacts = table(next((case/"postProcessing/contacts").glob("*/contacts.dat")))
    if not all(math.isfinite(v) for r in balance + contacts for v in r):
        failures.append("NaN or inf in the tables")

    # time kinetic strain contact work total
    work_ = balance[-1][4]
    rises = [b[5] - a[5] for a, b in zip(balance, balance[1:])]
    largestRise = max(rises + [0.0])
    print("work of gravity %.6g J, total energy at the end %.6g J, largest "
          "rise in a step %.3g J (bound %.3g J)"
          % (work_, balance[-1][5], largestRise, 1e-3*work_))
    if not largestRise <= 1e-3*work_:
        failures.append("the total energy rose by %.3g J in a step" % largestRise)
    if not balance[-1][5] < 0:
        failures.append("the total energy ends at %.3g J, not below 0" % balance[-1][5])

    failures += offTheWriteGrid(case)

    frames = nmmVtk.readContactSeries(case)
    if frames:
        failures += restsOnItsSprings(case, log, frames[-1][1])
    pulled = slidingInTension(frames)
    print("sliding contacts in tension in %d frames: %d" % (len(frames), len(pulled)))
    if not frames:
        failures.append("no contact frames in VTK/contacts.vtp.series")
    for name, fn in pulled:
        failures.append("%s: a sliding contact in tension, %.3g N/m" % (name, fn))

    for f in failures:
        print("FAIL: " + f)
    print("grainsInBox: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
