"""What the tests of the paper tutorials share: run a tutorial's reduced
version in a scratch copy, check that its runs ended, read summary.py's
table, and keep the checks' verdicts.

    case = paperTutorial.runReduced(argv, "claySettling", ["settling*"], __doc__)

SPDX-License-Identifier: GPL-3.0-or-later
"""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path


def runReduced(argv, name, runFolders, usage, allrunArgs=("-reduced",), group="paper"):
    """Copies tutorials/<group>/<name> to <workDir>/<name> without the run
    folders (glob patterns) an earlier Allrun left, and runs
    './Allrun -reduced' (or './Allrun <allrunArgs>') there with <binDir>
    on the PATH. argv is <binDir> <projectDir> <workDir>; returns the
    copy, or None (after printing usage) when argv is not that."""
    if len(argv) != 3:
        print(usage)
        return None
    binDir, project, work = (Path(a) for a in argv)
    case = work/name
    if case.exists():
        shutil.rmtree(case)
    case.parent.mkdir(parents=True, exist_ok=True)
    shutil.copytree(project/"tutorials"/group/name, case,
                    ignore=shutil.ignore_patterns(*runFolders, "summary.md"))
    env = dict(os.environ, NMM_PROJECT_DIR=str(project),
               PATH=str(binDir) + os.pathsep + os.environ.get("PATH", ""))
    subprocess.run(["bash", "./Allrun", *allrunArgs], cwd=case, env=env, check=False)
    return case


class checks:
    """Prints each check's verdict and remembers the failures."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        print(("ok:   " if ok else "FAIL: ") + what)
        if not ok:
            self.failures.append(what)
        return ok

    def ended(self, case, runs):
        """Each run's solver log ends with End; False if one does not."""
        for run in runs:
            log = case/run/"log.nmmSolidFoam"
            self(log.exists() and "\nEnd" in log.read_text(),
                 "%s ended (%s)" % (run, log))
        return not self.failures

    def exitCode(self):
        return 1 if self.failures else 0


def summary(case):
    """summary.py -json of the copy: its rows by run name. The copy finds
    bin/tools (nmmVtk.py) through NMM_PROJECT_DIR, this project's."""
    env = dict(os.environ, NMM_PROJECT_DIR=str(Path(__file__).resolve().parents[2]))
    out = subprocess.run([sys.executable, str(case/"summary.py"), "-json"],
                         capture_output=True, text=True, check=True, env=env).stdout
    rows = {r["run"]: r for r in json.loads(out)}
    for r in rows.values():
        print(json.dumps(r))
    return rows
