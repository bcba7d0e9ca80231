#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""Pressurise the crack of sneddonCrack.fmu through its FMI 3.0 interface
and compare the opening with Sneddon's closed form.

Usage:
    sneddonMaster.py <sneddonCrack.fmu> [pressure, default 1e-4]

The importer sets crack.pressure on every face of the crack, does the one
static step from t = 0 to 1, and reads crack.displacement back. A face's
opening is how far it moved away from the crack, -D.n (n its outward
normal); the opening of a segment is the sum over its two faces. The
pressure is small against E so that the faces, which the FMU gives where
they are now, stay where the linear closed form has them. Sneddon,
plane strain: w(s) = 4 p (1 - nu^2)/E sqrt(a^2 - s^2), here averaged over
each segment as the FMU's displacement is (E = 1, nu = 0.15, a = 0.1 from
the case). Writes postProcessing/sneddon/opening.dat and opening.png (the
segments' openings over the closed form; needs python3-matplotlib) and
prints the profile, the error of the two central segments (the verification's w(0)
criterion is 2 %) and of the crack's opened area.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import sys
from pathlib import Path

import numpy as np

# The importer sits beside the tutorials (or in the project's copy)
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
if os.environ.get("NMM_PROJECT_DIR"):
    sys.path.append(os.path.join(os.environ["NMM_PROJECT_DIR"], "tutorials", "coupling"))
import fmi3Master  # noqa: E402

E, NU, A = 1.0, 0.15, 0.1


def segmentMean(p, s1, s2):
    """Sneddon's opening averaged over [s1, s2]"""
    def F(s):
        s = max(-A, min(A, s))
        return 0.5*(s*math.sqrt(A*A - s*s) + A*A*math.asin(s/A))
    return 4*p*(1 - NU**2)/E*(F(s2) - F(s1))/(s2 - s1)


def openings(solid):
    """Per segment of the crack: (s, length, opening), in increasing s"""
    mid = solid.get("crack.midpoint")
    n = solid.get("crack.normal")
    D = solid.get("crack.displacement")
    L = solid.get("crack.length")
    away = -np.einsum("ij,ij->i", D, n)
    # The two faces of a segment started at the same place (to well within
    # a hundredth of its length)
    start = mid - D
    segments = {}
    for i in range(len(L)):
        key = round(start[i, 0]/L[i]*100)
        s, l, w = segments.get(key, (start[i, 0], L[i], 0.0))
        segments[key] = (s, l, w + away[i])
    return sorted(segments.values())


def run(path, p):
    fmu = fmi3Master.fmu(path)
    try:
        solid = fmu.initialized("sneddon")
        solid.set("crack.pressure", p)
        status, t = solid.doStep(0.0, 1.0)
        if status != fmi3Master.OK:
            raise SystemExit("the step was not completed: " + solid.lastMessage())
        result = openings(solid)
        solid.terminate()
        solid.free()
        return result
    finally:
        fmu.remove()


def plot(rows, p, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s = np.linspace(-A, A, 401)
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(s/A, 4*p*(1 - NU**2)/E*np.sqrt(A*A - s*s), "k-", lw=1, label="Sneddon")
    for si, l, w in rows:
        ax.plot([(si - l/2)/A, (si + l/2)/A], [w, w], "C0-", lw=2,
                label="through the FMU (per segment)" if si == rows[0][0] else None)
    ax.set_xlabel("s/a")
    ax.set_ylabel("opening [m]")
    ax.set_title("crack opening, p = %g, E = %g, nu = %g" % (p, E, NU))
    ax.legend(loc="lower center")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    path = sys.argv[1]
    p = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-4
    rows = run(path, p)
    out = Path("postProcessing/sneddon")
    out.mkdir(parents=True, exist_ok=True)
    print("%10s %14s %14s %9s" % ("s", "opening", "Sneddon", "error"))
    with open(out / "opening.dat", "w") as f:
        f.write("# s opening Sneddon (means over each segment of the crack)\n")
        for s, l, w in rows:
            exact = segmentMean(p, s - l/2, s + l/2)
            f.write("%.6g %.9g %.9g\n" % (s, w, exact))
            print("%10.4f %14.6e %14.6e %8.2f%%" % (s, w, exact, 100*(w/exact - 1)))
    central = [(w, segmentMean(p, s - l/2, s + l/2)) for s, l, w in rows if abs(s) < 0.01]
    centre = max(abs(w/e - 1) for w, e in central)
    area = sum(l*w for s, l, w in rows)
    exactArea = math.pi*(1 - NU**2)*p*A*A*2/E
    plot(rows, p, out/"opening.png")
    print("central segments: error %.2f %% (within 2 %% as the verification asks)"
          % (100*centre))
    print("opened area: %.6e, Sneddon %.6e, error %.2f %%"
          % (area, exactArea, 100*(area/exactArea - 1)))


if __name__ == "__main__":
    main()
