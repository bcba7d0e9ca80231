"""What the benchmark drivers that run a case share: running an
application in a case as its Allrun would (log.<application>), reading
a function object's table, and the solver log's time split.

Only the standard library is used.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import re
import subprocess
import sys


def run(driver, case, application, binDir):
    """Run binDir/application in case, its output in log.<application>;
    exit 1 naming the log when it fails. Returns the log's text"""
    log = case / ("log." + application)
    with open(log, "w") as out:
        r = subprocess.run([str(binDir / application)], cwd=case,
                           stdout=out, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        sys.exit("%s: %s failed; see %s" % (driver, application, log))
    return log.read_text()


def table(path):
    """The rows of a function object's .dat file, as lists of floats"""
    rows = []
    for line in path.read_text().splitlines():
        if line and not line.startswith("#"):
            rows.append([float(x) for x in line.split()])
    return rows


def cpuSplit(solverLog):
    """The solver log's "Timing (wall s):" line as {part: seconds} (the
    parts' wall-clock time; logs of earlier builds say "CPU s")"""
    return dict((k.strip(), float(v)) for k, v in re.findall(
        r"([a-z][a-z ]*?)\s+([0-9.eE+-]+)",
        re.search(r"Timing \((?:CPU|wall) s\):(.*)", solverLog).group(1)))


def linearAlgebra(solverLog):
    """Factorisations and solves with an updated factor, from the log's
    "Linear algebra:" line ((0, 0) without one)"""
    m = re.search(r"Linear algebra: (\d+) factorisations .*?, (\d+) solves"
                  r" with an updated factor", solverLog)
    return (int(m.group(1)), int(m.group(2))) if m else (0, 0)
