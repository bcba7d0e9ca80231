"""What the geometry utilities' tests share: a case folder with one
dictionary, running an application on it, reading the block list it
wrote, a polygon's area, and the checks' verdicts.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import re
import shutil
import subprocess

failures = []


def check(ok, what):
    """Prints the verdict and remembers a failure."""
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)
    return ok


def report():
    """Prints the outcome; the exit code: 1 when a check failed."""
    print("\n%s" % ("FAILED: %d checks" % len(failures) if failures else "All checks passed"))
    return 1 if failures else 0


def makeCase(work, name, entries, dictName):
    """A fresh case work/name whose system/<dictName> holds the entries
    (a value starting with '{' is a sub-dictionary)."""
    case = work/name
    if case.exists():
        shutil.rmtree(case)
    (case/"system").mkdir(parents=True)
    text = "".join("%s %s%s\n" % (k, v, "" if v.startswith("{") else ";")
                   for k, v in entries.items())
    (case/"system"/dictName).write_text(text)
    return case


def run(binDir, app, case, timeout=60):
    return subprocess.run([str(binDir/app), "-case", str(case)],
                          capture_output=True, text=True, timeout=timeout)


def blockList(path):
    """[(name, material, [(xText, yText), ...])] of a written block list:
    the coordinates as written, so that shared vertices compare exactly."""
    blocks = []
    item = re.compile(r"^(\S+) \{ material (\S+); polygon \((.*)\); \}$")
    for line in path.read_text().splitlines():
        if not line or line.startswith("//"):
            continue
        m = item.match(line)
        if not m:
            raise ValueError("unexpected line: " + line)
        pts = re.findall(r"\(([^()\s]+) ([^()\s]+)\)", m.group(3))
        blocks.append((m.group(1), m.group(2), pts))
    return blocks


def polygonArea(points):
    """Signed area (counter-clockwise positive) of (x, y) pairs."""
    xy = [(float(x), float(y)) for x, y in points]
    return 0.5*math.fsum(p[0]*q[1] - q[0]*p[1] for p, q in zip(xy, xy[1:] + xy[:1]))


def checkRejected(binDir, app, broken, makeCase, work):
    """Each of broken, (name, entries, words), written by
    makeCase(work, name, entries), makes app exit 1 with a message holding
    every one of the words."""
    for name, entries, words in broken:
        r = run(binDir, app, makeCase(work, name, entries))
        missing = [w for w in words if w not in r.stderr]
        check(r.returncode == 1 and not missing,
              "%s: exit %d, message names %s" % (name, r.returncode, ", ".join(words)))
        if missing:
            print(r.stderr)
