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
  - contacts (postProcessing/contacts): the largest penetration of a
    closed contact in the last step is below 1e-6 m, about 1e-6 of the
    box's width (the pile rests on its springs);
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

    # time deltaT open bonded sliding bondsBroken maxPenetration ...
    penetration = contacts[-1][6]
    print("largest penetration in the last step %.3g m (bound 1e-6 m)" % penetration)
    if not penetration < 1e-6:
        failures.append("largest penetration %.3g m in the last step" % penetration)

    frames = nmmVtk.readContactSeries(case)
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
