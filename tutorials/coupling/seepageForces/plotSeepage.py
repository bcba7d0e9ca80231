#!/usr/bin/python3
# Debian's /usr/bin/python3 on purpose: numpy and matplotlib are Debian's
# packages (python3-numpy, python3-matplotlib), which an interpreter that
# comes first on PATH may not see.
"""The seepageForces tutorial's results, from nmmSeepageFoam's
postProcessing/seepage/<startTime>/seepage.dat (one per run):

    /usr/bin/python3 plotSeepage.py <case>          the table (markdown)
    /usr/bin/python3 plotSeepage.py <case> <png>    the seepage force over
                                                    the submerged weight
                                                    and the pack's rise
                                                    against time

SPDX-License-Identifier: GPL-3.0-or-later
"""
import glob
import os
import re
import sys

COLUMNS = ("time cells iterations flowRate permeability Reynolds forceBalance "
           "Fx Fy submergedWeight immersedArea liftRatio rise packBottom packTop porosity").split()


def runs(case):
    """Per run (by start time): its rows, each a dict of COLUMNS"""
    result = []
    for path in glob.glob(os.path.join(case, "postProcessing", "seepage", "*", "seepage.dat")):
        rows = []
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                rows.append(dict(zip(COLUMNS, (float(v) for v in line.split()))))
        if rows:
            result.append((float(os.path.basename(os.path.dirname(path))), rows))
    if not result:
        raise SystemExit("no postProcessing/seepage/*/seepage.dat in %s" % case)
    return [rows for _, rows in sorted(result)]


def pressureDrop(case, run):
    """The run's pressure drop, from the log of nmmPoreFlowDict's echo in
    the OpenFOAM case of its first fluid solve"""
    t = run[0]["time"]
    for name in glob.glob(os.path.join(case, "poreFlow", "*", "constant", "poreFlowParameters")):
        if abs(float(name.split(os.sep)[-3]) - t) > 1e-12:
            continue
        with open(name) as f:
            for line in f:
                if line.startswith("inletPressure"):
                    return 1000*float(line.split()[1].rstrip(";"))
    return float("nan")


def table(case, all_runs, width):
    names = ("below", "above")
    out = ["| run | dp [Pa] | fluid solves | seepage force / submerged weight "
           "(first, last) | i/i_c at the start | rise of the grains [um] | "
           "pack porosity | worst force balance | Reynolds (max) | cells |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for k, run in enumerate(all_runs):
        first, last = run[0], run[-1]
        dp = pressureDrop(case, run)
        H = first["packTop"] - first["packBottom"]
        n = 1 - first["immersedArea"]/(width*H)
        # (rho_s - rho_w) g (1 - n) is the submerged weight per volume of pack
        ic = first["submergedWeight"]/(width*H)
        i = first["Fy"]/(width*H)
        out.append("| %s | %g | %d | %.3f, %.3f | %.3f (i = %.0f, i_c = %.0f Pa/m) | %.1f | %.3f "
                   "| %.1e | %.2g | %d-%d |" % (
                       names[k] if k < 2 else str(k), dp, len(run), first["liftRatio"],
                       last["liftRatio"], i/ic, i, ic, 1e6*last["rise"], n,
                       max(r["forceBalance"] for r in run), max(r["Reynolds"] for r in run),
                       min(r["cells"] for r in run), max(r["cells"] for r in run)))
    return "\n".join(out)


def plot(all_runs, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for run, label in zip(all_runs, ("below the critical gradient", "above it")):
        t = [r["time"] for r in run]
        a.plot(t, [r["liftRatio"] for r in run], "o-", ms=3, label=label)
        b.plot(t, [1e6*r["rise"] for r in run], "o-", ms=3, label=label)
    a.axhline(1, color="k", lw=0.8, ls="--")
    a.text(0.005, 1.03, "critical: seepage force = submerged weight", fontsize=8)
    a.set_ylabel("seepage force / submerged weight")
    b.set_ylabel("mean rise of the grains [um]")
    b.set_xlabel("time [s]")
    a.legend()
    a.grid(alpha=0.3)
    b.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main(argv):
    if len(argv) < 2:
        raise SystemExit(__doc__)
    case = argv[1]
    all_runs = runs(case)
    if len(argv) > 2:
        plot(all_runs, argv[2])
        return
    with open(os.path.join(case, "system", "nmmPoreFlowDict")) as f:
        box = re.search(r"\bbox\s*\{[^}]*?\bmin\s*\(([^)]*)\)[^}]*?\bmax\s*\(([^)]*)\)",
                        f.read())
    if not box:
        raise SystemExit("no box { min (..); max (..); } in %s/system/nmmPoreFlowDict" % case)
    width = float(box.group(2).split()[0]) - float(box.group(1).split()[0])
    print(table(case, all_runs, width))


if __name__ == "__main__":
    main(sys.argv)
