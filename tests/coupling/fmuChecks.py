"""What the FMU tests share: their command line, the importer
(tutorials/coupling/fmi3Master.py) and a list of checks.

    <test>.py <fmuDir> <projectDir> <binDir> <workDir>

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path


class run:
    def __init__(self, doc):
        if len(sys.argv) != 5:
            print(doc)
            raise SystemExit(1)
        self.fmus, self.project, self.bin, self.work = (Path(a).resolve() for a in sys.argv[1:])
        self.work.mkdir(parents=True, exist_ok=True)
        sys.path.insert(0, str(self.project/"tutorials"/"coupling"))
        self.failures = []

    def check(self, ok, what):
        print(("ok:   " if ok else "FAIL: ") + what)
        if not ok:
            self.failures.append(what)
        return ok

    def close(self, rel, value, exact, scale, what):
        """|value - exact| <= rel scale"""
        return self.check(abs(value - exact) <= rel*scale,
                          "%s: %.9g, expected %.9g (to %.0e of %.3g)"
                          % (what, value, exact, rel, scale))

    def end(self):
        print("%d checks failed" % len(self.failures) if self.failures else "all checks passed")
        return 1 if self.failures else 0
