#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy, python3-vtk9).
"""Sneddon's pressurised crack through the FMU's C interface
(build/fmu/sneddonCrack.fmu, tutorials/coupling/sneddonCrack):

    fmuSneddon.py <fmuDir> <projectDir> <binDir> <workDir>

An importer sets crack.pressure p = 1e-4 (E = 1) on the 40 faces of the
crack (20 segments, two faces each), does the static step and reads the
faces' displacements back (tutorials/coupling/sneddonCrack/sneddonMaster.py).
Against Sneddon's closed form (docs: verification.md), each segment's
opening averaged as the FMU averages it:
  - the two central segments within 2 %, the verification's criterion
    for w(0);
  - the opened area within 3 % (the segments at the tips, where the
    opening goes as a square root, are the furthest off);
and against the direct run, the same case loaded by its own 0/D (crack
pressure):
  - nmmSolidFoam on it (p = 1, as the verification has it) passes the
    verification's check of w(0) within 2 % (tests/verification/
    checkSneddon.py), which it meets with the same error as the central
    segments through the FMU (0.8 %);
  - packed as an FMU too and stepped without a pressure from the importer,
    every segment's opening equals the one through the interface to 1e-9
    of the largest;
and, coupled implicitly to a compressible fluid that fills the crack
(tutorials/coupling/sneddonCrack/fluidCrackMaster.py: each iteration
restores the saved state, sets the pressure, steps and reads the volume
back; secant updates):
  - the loop converges to a residual below 1e-10 of p in at most 10
    iterations;
  - p and the crack's volume are within 3 % of the hand solution of
    C p^2 + K C p - K V0 = 0 (C Sneddon's compliance), the tolerance of
    the opened area above, on which they depend.
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fmuChecks  # noqa: E402

P = 1e-4


def directCase(t, name, p, apps):
    """The tutorial case with the pressure p in its 0/D, run through apps"""
    case = t.work/name
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(t.project/"tutorials/coupling/sneddonCrack", case,
                    ignore=shutil.ignore_patterns("constant/nmmMesh", "log.*", "VTK",
                                                  "postProcessing", "*.fmu"))
    D = (case/"0/D").read_text()
    assert "pressure    uniform 0;" in D
    (case/"0/D").write_text(D.replace("pressure    uniform 0;", "pressure    uniform %r;" % p))
    env = dict(os.environ, PATH=str(t.bin) + os.pathsep + os.environ.get("PATH", ""))
    for app in apps:
        with open(case/("log." + app), "w") as log:
            subprocess.run([str(t.bin/app), "-case", str(case)], stdout=log,
                           stderr=subprocess.STDOUT, env=env, check=True)
    return case


def main():
    t = fmuChecks.run(__doc__)
    sys.path.insert(0, str(t.project/"tutorials/coupling/sneddonCrack"))
    import sneddonMaster as sm

    rows = sm.run(t.fmus/"sneddonCrack.fmu", P)
    t.check(len(rows) == 20, "20 segments of the crack (%d)" % len(rows))
    for s, l, w in rows:
        if abs(s) < 0.01:
            exact = sm.segmentMean(P, s - l/2, s + l/2)
            t.close(0.02, w, exact, exact, "opening of the central segment at s = %.3f" % s)
    area = sum(l*w for s, l, w in rows)
    exactArea = math.pi*(1 - sm.NU**2)*P*sm.A**2*2/sm.E
    t.close(0.03, area, exactArea, exactArea, "opened area")

    # checkSneddon.py knows the verification's p = 1
    case = directCase(t, "direct", 1.0, ("nmmMesh", "nmmSolidFoam"))
    check = subprocess.run([sys.executable, str(t.project/"tests/verification/checkSneddon.py"),
                            str(case), "0"], capture_output=True, text=True)
    print(check.stdout.strip())
    t.check(check.returncode == 0, "the direct run (nmmSolidFoam) passes checkSneddon.py")

    case = directCase(t, "directFmu", P, ("nmmFmuExport",))
    direct = sm.run(case/"sneddonCrack.fmu", 0.0)
    largest = max(w for s, l, w in rows)
    diff = max(abs(a[2] - b[2]) for a, b in zip(rows, direct)) if len(direct) == len(rows) else math.inf
    t.check(diff <= 1e-9*largest, "through the interface = the direct load: largest"
            " difference %.2e of the largest opening" % (diff/largest))

    import fluidCrackMaster as fc
    p, V, iterations, r = fc.couple(t.fmus/"sneddonCrack.fmu", log=lambda line: None)
    pHand, VHand = fc.handSolution()
    t.check(iterations <= 10 and r < 1e-10, "the fluid-filled crack's implicit loop"
            " converged in %d iterations (residual %.1e of p)" % (iterations, r))
    t.close(0.03, p, pHand, pHand, "the fluid-filled crack's pressure")
    t.close(0.03, V, VHand, VHand, "the fluid-filled crack's volume")
    return t.end()


if __name__ == "__main__":
    sys.exit(main())
