#!/usr/bin/python3
# Debian's /usr/bin/python3 on purpose: numpy and matplotlib are Debian's
# packages (python3-numpy, python3-matplotlib), which an interpreter that
# comes first on PATH may not see.
"""The permeability of the compacting sand at each stage nmmPoreFlow ran,
from <case>/postProcessing/poreFlow/<time>/poreFlow.dat, with the
Kozeny-Carman line k = C n^3/(1 - n)^2 fitted through it (C by least
squares on log k).

    /usr/bin/python3 plotPermeability.py <case> [<png>]

Prints the table (markdown) and the fit; with <png>, plots k against the
porosity n (log scale) with the fitted line.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import glob
import math
import os
import sys


def stages(case):
    rows = []
    for path in glob.glob(os.path.join(case, "postProcessing/poreFlow/*/poreFlow.dat")):
        with open(path) as f:
            lines = f.read().splitlines()
        names = [l for l in lines if l.startswith("# time")][0][1:].split()
        values = [l for l in lines if l and not l.startswith("#")][0].split()
        row = {n.split("[")[0]: float(v) for n, v in zip(names, values)}
        row["name"] = values[0]
        rows.append(row)
    return sorted(rows, key=lambda r: r["time"])


def kozeny(n):
    return n**3/(1 - n)**2


def fit(rows):
    logs = [math.log(r["permeability"]/kozeny(r["porosity"])) for r in rows]
    return math.exp(sum(logs)/len(logs))


def main():
    case = sys.argv[1]
    rows = stages(case)
    if len(rows) < 2:
        raise SystemExit("fewer than two stages in %s/postProcessing/poreFlow" % case)
    C = fit(rows)
    print("| time [s] | porosity | flow porosity | permeability [m2] | Kozeny-Carman fit [m2] "
          "| Reynolds | cells | narrowest throat [um] |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %.4f | %.4f | %.3e | %.3e | %.2g | %d | %.2f |"
              % (r["name"], r["porosity"], r["flowPorosity"], r["permeability"],
                 C*kozeny(r["porosity"]), r["Reynolds"], r["cells"], 1e6*r["throat"]))
    worst = max(abs(r["permeability"]/(C*kozeny(r["porosity"])) - 1) for r in rows)
    print("\nKozeny-Carman: k = C n^3/(1 - n)^2 with C = %.3e m2; largest deviation %.0f%%"
          % (C, 100*worst))
    if len(sys.argv) < 3:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = [r["porosity"] for r in rows]
    k = [r["permeability"] for r in rows]
    lo, hi = min(n) - 0.02, max(n) + 0.02
    line = [lo + (hi - lo)*i/100 for i in range(101)]
    fig, ax = plt.subplots(figsize=(6, 4.5), dpi=100)
    ax.semilogy(line, [C*kozeny(x) for x in line], "-", color="0.5",
                label="Kozeny-Carman, C = %.2e m$^2$" % C)
    ax.semilogy(n, k, "o", color="tab:blue", label="OpenFOAM (simpleFoam) on the pore space")
    for r in rows:
        ax.annotate("t = %s s" % r["name"], (r["porosity"], r["permeability"]),
                    textcoords="offset points", xytext=(6, -10), fontsize=8)
    ax.set_xlabel("porosity n (grains as they are, in the box around them)")
    ax.set_ylabel("permeability k [m$^2$]")
    ax.set_title("Permeability of the compacting sand")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
