#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy,
# python3-matplotlib), like benchmarks/workPrecision itself.
"""Smoke test of benchmarks/workPrecision.

Usage:
    checkWorkPrecision.py <projectDir> <binDir> <outDir>

Runs <projectDir>/benchmarks/workPrecision -quick -bin <binDir> -out
<outDir> -work <outDir>/work, then checks that <outDir> holds a CSV file
for every case, each with a header and at least two rows of finite
numbers, workPrecision.png and README.md. Exit 1 otherwise.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import csv
import math
import shutil
import subprocess
import sys
from pathlib import Path

CASES = ["cantilever", "plateHole", "lame", "sneddon", "freeFall", "waveBar",
         "incline", "toppling", "bouncingBlock"]


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 1
    project, binDir, out = (Path(a).resolve() for a in argv)
    if out.exists():
        shutil.rmtree(out)
    rc = subprocess.call([sys.executable, str(project/"benchmarks"/"workPrecision"),
                          "-quick", "-bin", str(binDir), "-out", str(out),
                          "-work", str(out/"work")])
    failed = rc != 0
    if failed:
        print("workPrecision -quick exited with %d" % rc)
    for name in CASES:
        path = out/(name + ".csv")
        if not path.is_file():
            print("missing %s" % path)
            failed = True
            continue
        rows = list(csv.reader(path.open()))
        bad = [v for r in rows[1:] for v in r
               if not math.isfinite(float(v))]
        if len(rows) < 3 or bad:
            print("%s: %d rows, non-finite values %s" % (path, len(rows) - 1, bad))
            failed = True
        else:
            print("%s: %d rows of %d finite numbers" % (path.name, len(rows) - 1,
                                                       len(rows[0])))
    for extra in ("workPrecision.png", "README.md"):
        if not (out/extra).is_file() or (out/extra).stat().st_size == 0:
            print("missing %s" % (out/extra))
            failed = True
    print("FAILED" if failed else "OK")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
