#!/usr/bin/python3
"""Runs tutorials/coupling/fractureFlow (the solid and a cubic-law flow
along its fracture, coupled by fractureFlowDriver through the coupling
interface) in a scratch copy and checks it against the hand solution:

    fractureFlow.py <binDir> <projectDir> <workDir>

The inlet pressure (3 MPa at the last step) stays below the normal stress
(5 MPa), so the fracture stays closed at its residual aperture a_r and the
flow is that of parallel plates a_r apart:
  - the flux at each step is q = a_r^3 (p_in - p_out)/(12 mu L), to 1e-9;
  - the last step's pressure falls linearly from p_in to p_out along x,
    to 1e-9 p_in;
  - every aperture is a_r;
  - each step's fixed-point iteration converges in at most 3 iterations
    (the apertures do not change, so the second one confirms the first).
Exit 1 when a check fails.
SPDX-License-Identifier: GPL-3.0-or-later
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 1
    binDir, project, work = (Path(a) for a in argv)
    case = work/"fractureFlow"
    if case.exists():
        shutil.rmtree(case)
    case.parent.mkdir(parents=True, exist_ok=True)
    shutil.copytree(project/"tutorials/coupling/fractureFlow", case,
                    ignore=shutil.ignore_patterns("postProcessing", "log.*", "constant/nmmMesh"))
    env = dict(os.environ, NMM_PROJECT_DIR=str(project),
               PATH=str(binDir) + os.pathsep + os.environ.get("PATH", ""))
    subprocess.run(["bash", "./Allrun"], cwd=case, env=env, check=False)

    failures = []

    def check(ok, what):
        print(("ok:   " if ok else "FAIL: ") + what)
        if not ok:
            failures.append(what)
        return ok

    log = (case/"log.fractureFlowDriver").read_text() if (case/"log.fractureFlowDriver").exists() else ""
    if not check("\nEnd" in log, "fractureFlowDriver ended"):
        print(log[-2000:])
        return 1
    pIn, pOut, mu, ar, L, steps = 3e6, 0.0, 1e-3, 1e-5, 0.04, 4
    rows = re.findall(r"Step (\d+): inlet pressure (\S+) Pa, (\d+) iterations, flux (\S+) m2/s,"
                      r" largest aperture (\S+) m", log)
    check(len(rows) == steps, "%d coupled steps" % len(rows))
    for step, p, iterations, q, amax in rows:
        expected = ar**3*(float(p) - pOut)/(12*mu*L)
        check(abs(float(q) - expected) <= 1e-9*expected,
              "step %s: flux %s against a_r^3 dp/(12 mu L) = %.6g" % (step, q, expected))
        check(int(iterations) <= 3, "step %s: %s iterations" % (step, iterations))
        check(float(amax) == ar, "step %s: largest aperture %s" % (step, amax))

    profile = [[float(v) for v in line.split()]
               for line in (case/"postProcessing/fractureFlow/profile.dat").read_text().splitlines()
               if line.strip() and not line.startswith("#")]
    worst = max(abs(p - (pIn + (pOut - pIn)*min(max(x, 0.0), L)/L)) for x, p, _ in profile)
    check(worst <= 1e-9*pIn, "pressure linear along x: largest departure %.3g Pa" % worst)
    check(all(a == ar for _, _, a in profile), "every aperture is a_r")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
