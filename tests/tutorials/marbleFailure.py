#!/usr/bin/python3
"""Runs tutorials/paper/marbleFailure with './Allrun -reduced' (only
the two 11 MPa runs) from a scratch copy and checks the behaviour
the paper reports, with numbers from summary.py:

    marbleFailure.py <binDir> <projectDir> <workDir>

  - both runs end with End;
  - with the bonds' strength (cohesion 18 MPa, tensile strength 28 MPa)
    the sample stays intact: fewer than 5% of the closed contacts lose
    their bond (a few break at grain corners, where the stress is
    concentrated), and the top moves down by the elastic shortening of
    an intact sample, sigma (1 - nu^2)/E x height = 0.118 um in plane
    strain, within 10% (the grain boundaries' springs add a little
    compliance);
  - without it (friction only) grain boundaries open: at the end at
    least twice as many contacts are open as with strength, the largest
    displacement is larger (the grains move apart), and the top moves
    down more than 1.15 times the elastic shortening.
Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (the tutorial's plot step needs numpy,
matplotlib and VTK, which Debian installs for that interpreter only).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 1
    binDir, project, work = Path(argv[0]), Path(argv[1]), Path(argv[2])
    case = work/"marbleFailure"
    if case.exists():
        shutil.rmtree(case)
    case.parent.mkdir(parents=True, exist_ok=True)
    shutil.copytree(project/"tutorials/paper/marbleFailure", case,
                    ignore=shutil.ignore_patterns("load*MPa*", "summary.md"))
    env = dict(os.environ, NMM_PROJECT_DIR=str(project),
               PATH=str(binDir) + os.pathsep + os.environ.get("PATH", ""))
    subprocess.run(["bash", "./Allrun", "-reduced"], cwd=case, env=env, check=False)

    failures = []
    for run in ("load11MPaStrength", "load11MPaNoStrength"):
        log = case/run/"log.nmmSolidFoam"
        if not log.exists() or "\nEnd" not in log.read_text():
            failures.append("%s did not end: see %s" % (run, log))
    if failures:
        print("\n".join("FAIL: " + f for f in failures))
        return 1

    out = subprocess.run([sys.executable, str(case/"summary.py"), "-json"],
                         capture_output=True, text=True, check=True).stdout
    rows = {r["run"]: r for r in json.loads(out)}
    for r in rows.values():
        print(json.dumps(r))

    def check(ok, what):
        print(("ok:   " if ok else "FAIL: ") + what)
        if not ok:
            failures.append(what)

    s, n = rows["load11MPaStrength"], rows["load11MPaNoStrength"]
    check(s["bondsBroken"] < 0.05*s["closedEnd"],
          "11 MPa with strength: %d of %d bonds break" % (s["bondsBroken"], s["closedEnd"]))
    check(n["openEnd"] >= 2*s["openEnd"],
          "11 MPa without strength: twice the open contacts (%d against %d)"
          % (n["openEnd"], s["openEnd"]))
    check(n["maxD_um"] > s["maxD_um"],
          "11 MPa without strength: the grains move further apart")
    elastic = 11e6*(1 - 0.3**2)/85e9*1e-3*1e6
    check(-n["topDy_um"] > 1.15*elastic,
          "11 MPa without strength: top shortening %.3f um, beyond elastic" % -n["topDy_um"])
    check(0.9*elastic < -s["topDy_um"] < 1.1*elastic,
          "11 MPa with strength: top shortening %.3f um against %.3f um elastic"
          % (-s["topDy_um"], elastic))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
