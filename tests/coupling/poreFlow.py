#!/usr/bin/python3
# Debian's /usr/bin/python3 on purpose: numpy and vtk are Debian's packages,
# which an interpreter that comes first on PATH may not see. This script
# needs only the standard library.
"""
poreFlow.py -- nmmPoreFlow against closed forms, with the real OpenFOAM
binaries (Debian's openfoam package, v1912).

  slot      plane Poiseuille flow between two blocks: the slot's own
            permeability k W/h (W the box's width, h the slot's) is h^2/12
            within 1%; the flow balances (|Qout - Qin| < 1e-6 Qout); the
            fluid's force on the walls (pressure and wall shear stress) is
            the pressure drop times the inlet's width within 1% (momentum
            balance of the steady flow), half on each block
  discs     Stokes flow across a square array of discs (one row of four
            unit cells, symmetry planes above and below), at solid
            fractions 0.2 and 0.4, against the drag of Sangani & Acrivos
            (1982, Int. J. Multiphase Flow 8:193, Table 1, square array:
            F/(mu U) = 51.53 and 217.89, four digits): k = l^2/(F/(mu U)),
            within 2% (the inlet and outlet planes are set at uniform
            pressure, which a periodic array has only approximately); the
            force balance as for the slot, a quarter of it on each disc
  repeatable  one pore space meshed three times (separate processes, so
            at other memory addresses): the same mesh, byte for byte
            (points, faces, owner, neighbour, boundary), and the same
            cell count. Twelve irregular grains, some 4,000 cells
  errors    broken input: an unknown keyword ("did you mean"), a missing
            physics keyword, a box that the blocks close, a time that was
            not written; and nmmSeepageFoam's nmmSeepageDict (an unknown
            keyword, a step that is not positive, blocks that match none, a
            missing keyword); each an error naming the file or time, exit 1

  convergence  not a test: the table of docs/verification/poreFlow.md,
            the error of both cases against the cells and the run time
  plot      not a test: poreFlow.png beside that table, |error| against
            run time per case, from the table (workDir: the .md file)

Usage: poreFlow.py <binDir> <projectDir> <workDir> [slot|discs|repeatable|errors|convergence]
"""
import math
import os
import random
import re
import shutil
import subprocess
import sys

# Absolute: the tools run in the cases, not where this was called
BIN, PROJECT, WORK = (os.path.abspath(a) for a in sys.argv[1:4])
WHAT = sys.argv[4] if len(sys.argv) > 4 else "all"

HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
"""

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)


def write(path, cls, location, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER % (cls, location, os.path.basename(path)) + text)


def make_case(name, blocks, flow):
    """A case of rigid-enough blocks (nothing is solved: nmmPoreFlow reads
    the geometry at time 0), and its nmmPoreFlowDict"""
    case = os.path.join(WORK, name)
    shutil.rmtree(case, ignore_errors=True)
    lines = []
    for i, poly in enumerate(blocks):
        pts = " ".join("(%.17g %.17g)" % p for p in poly)
        lines.append("    b%d { material rock; polygon (%s); }" % (i, pts))
    write(case + "/system/nmmMeshDict", "dictionary", "system",
          "blocks\n(\n%s\n);\n\npatches { }\n\ncover { type structured; cellSize %g; }\n"
          % ("\n".join(lines), flow.pop("coverCell")))
    write(case + "/system/controlDict", "dictionary", "system",
          "application nmmSolidFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
          "endTime 1;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\n")
    write(case + "/system/nmmSolution", "dictionary", "system",
          "analysis static;\nlargeDisplacement no;\n"
          "contact { method penalty; maxOpenCloseIterations 30; }\n"
          "linearSolver { type cholmod; }\n")
    write(case + "/constant/mechanicalProperties", "dictionary", "constant",
          "planeStress no;\nthickness 1;\n"
          "materials { rock { type linearElastic; E 50e9; nu 0.25; rho 2650; } }\n")
    write(case + "/constant/contactProperties", "dictionary", "constant",
          "default { law mohrCoulomb; frictionAngle 35; initialState open; }\n")
    write(case + "/0/D", "volVectorField", "0",
          "dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField { }\n")
    text = "".join("%-18s %s;\n" % (k, v) for k, v in flow.items())
    write(case + "/system/nmmPoreFlowDict", "dictionary", "system", text)
    run(["nmmMesh"], case, "nmmMesh")
    return case


def run(argv, case, log, expect=0):
    with open(os.path.join(case, "log." + log), "w") as f:
        p = subprocess.run([os.path.join(BIN, argv[0])] + argv[1:], cwd=case,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        f.write(p.stdout)
    if expect is not None and p.returncode != expect:
        print(p.stdout[-3000:])
        raise SystemExit("%s exited with %d in %s" % (argv[0], p.returncode, case))
    return p


def table(case, time="0"):
    path = os.path.join(case, "postProcessing/poreFlow", time, "poreFlow.dat")
    with open(path) as f:
        names = [l for l in f if l.startswith("# time")][0][1:].split()
    with open(path) as f:
        values = [l for l in f if not l.startswith("#")][0].split()
    return {re.sub(r"\[.*\]", "", n): float(v) for n, v in zip(names, values)}


def fluid(**extra):
    d = {"flowDirection": "x", "sides": "wall", "shrink": 0, "viscosity": 1e-3,
         "density": 1000, "pressureDrop": 1e-3, "cellsAcrossThroat": 16}
    d.update(extra)
    return d


def slot():
    L, h, t = 4e-3, 1e-3, 1e-3
    blocks = [[(0, -t), (L, -t), (L, 0), (0, 0)], [(0, h), (L, h), (L, h + t), (0, h + t)]]
    case = make_case("slot", blocks, fluid(box="{ min (0 %g); max (%g %g); }" % (-t, L, h + t),
                                           maxCellSize=1e-4, coverCell=5e-4))
    out = run(["nmmPoreFlow"], case, "nmmPoreFlow").stdout
    r = table(case)
    W = h + 2*t
    k_slot = r["permeability"]*W/h
    err = k_slot/(h*h/12) - 1
    print("slot: k W/h = %.6g m2, h^2/12 = %.6g m2, error %.3g%%, %d cells"
          % (k_slot, h*h/12, 100*err, r["cells"]))
    check(abs(err) < 0.01, "slot: permeability h^2/12 within 1%% (%.3g%%)" % (100*err))
    balance = float(re.search(r"mass balance\s+(\S+)", out).group(1))
    check(balance < 1e-6, "slot: flow in equals flow out (%.2g)" % balance)
    check_forces(case, out, "slot", [h/2, h/2])
    check(r["porosity"] == r["porosity"] and abs(r["porosity"] - h/W) < 1e-10,
          "slot: porosity h/W (%.15g)" % r["porosity"])
    check(r["Reynolds"] < 1, "slot: creeping flow (Re %.3g)" % r["Reynolds"])
    check(os.path.isfile(case + "/poreFlow/0/log.simpleFoam")
          and os.path.isfile(case + "/poreFlow/0/log.checkMesh"),
          "slot: OpenFOAM's logs in poreFlow/0")


def check_forces(case, out, name, widths):
    """Steady flow: the fluid's force on the walls along the flow is the
    pressure drop times the inlet's width (momentum balance), to 1%; each
    block carries dp times its share of the width (widths: per block; the
    slot's two walls half each, the row's discs a quarter each)"""
    balance = float(re.search(r"dp times the inlet.*\(balance (\S+)\)", out).group(1))
    check(balance < 0.01, "%s: force on the walls = dp x inlet width (%.2g)" % (name, balance))
    with open(os.path.join(case, "postProcessing/poreFlow/0/blockForces.dat")) as f:
        forces = [float(l.split()[1]) for l in f if not l.startswith("#")]
    dp = 1e-3
    worst = max(abs(F/(dp*w) - 1) for F, w in zip(forces, widths))
    check(worst < 0.02, "%s: each block's force dp x its width, to 2%% (%.2g)" % (name, worst))


def disc(cx, cy, r, n=128):
    # A regular n-gon of the disc's area
    R = r*math.sqrt(2*math.pi/(n*math.sin(2*math.pi/n)))
    return [(cx + R*math.cos(2*math.pi*i/n), cy + R*math.sin(2*math.pi*i/n)) for i in range(n)]


def discs():
    l, cells = 1e-3, 4
    for c, drag in ((0.2, 51.53), (0.4, 217.89)):
        a = l*math.sqrt(c/math.pi)
        blocks = [disc((i + 0.5)*l, 0.5*l, a) for i in range(cells)]
        case = make_case("discs%g" % c, blocks,
                         fluid(box="{ min (0 0); max (%g %g); }" % (cells*l, l), sides="symmetryPlane",
                               maxCellSize=l/15, cellsAcrossThroat=12, coverCell=l/4))
        out = run(["nmmPoreFlow"], case, "nmmPoreFlow").stdout
        check_forces(case, out, "discs c=%g" % c, [l/cells]*cells)
        r = table(case)
        k_ref = l*l/drag
        err = r["permeability"]/k_ref - 1
        print("discs c=%g: k = %.6g m2, Sangani & Acrivos %.6g m2, error %.3g%%, %d cells, porosity %.6g"
              % (c, r["permeability"], k_ref, 100*err, r["cells"], r["porosity"]))
        check(abs(r["porosity"] - (1 - c)) < 1e-9, "discs c=%g: porosity 1 - c" % c)
        check(abs(err) < 0.02, "discs c=%g: permeability within 2%% of Sangani & Acrivos (%.3g%%)"
              % (c, 100*err))


def grain(cx, cy, r, rng, n=24):
    """An irregular star-shaped grain: radii between 0.7 r and r"""
    return [(cx + r*rng.uniform(0.7, 1)*math.cos(2*math.pi*i/n),
             cy + r*rng.uniform(0.7, 1)*math.sin(2*math.pi*i/n)) for i in range(n)]


def repeatable():
    """The mesh must not depend on where the mesher's objects lie in memory:
    a coupled run restarted, or run again, must meet the same pore space"""
    rng = random.Random(20)
    l = 1e-3
    blocks = [grain((i + 0.5)*l, (j + 0.5)*l, 0.4*l, rng) for i in range(4) for j in range(3)]
    case = make_case("repeatable", blocks,
                     fluid(box="{ min (0 0); max (%g %g); }" % (4*l, 3*l), maxCellSize=l/10,
                           cellsAcrossThroat=4, coverCell=l/4))
    mesh = os.path.join(case, "poreFlow/0/constant/polyMesh")
    files = ("points", "faces", "owner", "neighbour", "boundary")
    first = None
    for i in range(3):
        out = run(["nmmPoreFlow", "-noRun"], case, "nmmPoreFlow.%d" % i).stdout
        cells = int(re.search(r"cells\s+(\d+)", out).group(1))
        content = []
        for name in files:
            with open(os.path.join(mesh, name)) as f:
                content.append(f.read())
        if first is None:
            first = (cells, content)
            print("repeatable: %d cells" % cells)
            continue
        check(cells == first[0], "repeatable: run %d has as many cells (%d, first %d)"
              % (i + 1, cells, first[0]))
        same = [n for n, a, b in zip(files, content, first[1]) if a == b]
        check(len(same) == len(files), "repeatable: run %d's mesh is the first's (the same: %s)"
              % (i + 1, " ".join(same) or "none"))


def errors():
    L, h, t = 4e-3, 1e-3, 1e-3
    blocks = [[(0, -t), (L, -t), (L, 0), (0, 0)], [(0, h), (L, h), (L, h + t), (0, h + t)]]
    base = fluid(box="{ min (0 %g); max (%g %g); }" % (-t, L, h + t), maxCellSize=2e-4,
                 coverCell=5e-4)
    case = make_case("errors", blocks, dict(base))
    dict_path = case + "/system/nmmPoreFlowDict"
    good = open(dict_path).read()

    def expect_error(text, pattern, what, argv=("nmmPoreFlow", "-noRun")):
        with open(dict_path, "w") as f:
            f.write(text)
        p = run(list(argv), case, "nmmPoreFlow.error", expect=None)
        ok = p.returncode == 1 and re.search(pattern, p.stdout, re.S) is not None
        if not ok:
            print(p.stdout[-1500:])
        check(ok, "errors: " + what)

    expect_error(good.replace("viscosity", "viscosty"), r"viscosty.*did you mean.*viscosity",
                 "an unknown keyword with a 'did you mean'")
    expect_error(re.sub(r"pressureDrop.*\n", "", good), r"nmmPoreFlowDict.*pressureDrop",
                 "a missing pressureDrop names the file and keyword")
    expect_error(good.replace("min (0 %g)" % -t, "min (0 %g)" % (-t/2)).replace(
        "max (%g %g)" % (L, h + t), "max (%g %g)" % (L, 0)), r"max|box",
                 "a box without an area")
    covered = good.replace("max (%g %g)" % (L, h + t), "max (%g %g)" % (L, -t/2))
    expect_error(covered, r"time 0: no pore space in the box", "a box the blocks cover")
    # nmmSeepageFoam's own dictionary, read before its first fluid solve
    seepage = "couplingInterval 0.01;\nimmersedBlocks (b.*);\n"
    for text, pattern, what in (
            (seepage.replace("couplingInterval", "couplingIntervl"),
             r"couplingIntervl.*did you mean.*couplingInterval.*nmmSeepageDict at line 9",
             "an unknown keyword in nmmSeepageDict, at its line, with a 'did you mean'"),
            (seepage.replace("0.01", "0"), r"out of range.*nmmSeepageDict.*keyword: couplingInterval",
             "a coupling interval that is not positive"),
            (seepage.replace("(b.*)", "(grain.*)"), r"immersedBlocks: no block matches 'grain",
             "immersedBlocks that match no block"),
            ("couplingInterval 0.01;\n", r"nmmSeepageDict.*immersedBlocks",
             "a missing immersedBlocks names the file and keyword")):
        write(case + "/system/nmmSeepageDict", "dictionary", "system", text)
        expect_error(good, pattern, what, ("nmmSeepageFoam",))
    # A third block across the slot closes it
    with open(case + "/system/nmmMeshDict") as f:
        mesh = f.read()
    with open(case + "/system/nmmMeshDict", "w") as f:
        f.write(mesh.replace("\n);", "\n    plug { material rock; polygon ((%g 0) (%g 0) (%g %g) (%g %g)); }\n);"
                             % (L/2, L/2 + t, L/2 + t, h, L/2, h), 1))
    run(["nmmMesh"], case, "nmmMesh")
    expect_error(good, r"time 0: no path through the pore space joins the inlet to the outlet",
                 "a slot a block closes")
    expect_error(good, r"-time 7.*no such time", "a time that was not written",
                 ("nmmPoreFlow", "-noRun", "-time", "7"))


def convergence():
    print("| case | maxCellSize | cellsAcrossThroat | lloydIterations | cells | error | run time [s] |")
    print("|---|---|---|---|---|---|---|")
    L, h, t = 4e-3, 1e-3, 1e-3
    blocks = [[(0, -t), (L, -t), (L, 0), (0, 0)], [(0, h), (L, h), (L, h + t), (0, h + t)]]
    for lloyd in (0, 20):
        for n in (4, 8, 16, 32):
            case = make_case("slot%d_%d" % (n, lloyd), blocks, fluid(
                box="{ min (0 %g); max (%g %g); }" % (-t, L, h + t), maxCellSize=h/n,
                cellsAcrossThroat=n, coverCell=5e-4, lloydIterations=lloyd))
            out = run(["nmmPoreFlow"], case, "nmmPoreFlow").stdout
            r = table(case)
            err = r["permeability"]*(h + 2*t)/h/(h*h/12) - 1
            secs = float(re.search(r"run time\s+(\S+)", out).group(1))
            print("| slot, k = h^2/12 | h/%d | %d | %d | %d | %+.3f%% | %.1f |"
                  % (n, n, lloyd, r["cells"], 100*err, secs))
    l = 1e-3
    for c, drag in ((0.2, 51.53), (0.4, 217.89)):
        a = l*math.sqrt(c/math.pi)
        for m, n in ((8, 6), (15, 12), (25, 16)):
            case = make_case("discs%g_%d" % (c, m), [disc((i + 0.5)*l, 0.5*l, a) for i in range(4)],
                             fluid(box="{ min (0 0); max (%g %g); }" % (4*l, l), sides="symmetryPlane",
                                   maxCellSize=l/m, cellsAcrossThroat=n, coverCell=l/4))
            out = run(["nmmPoreFlow"], case, "nmmPoreFlow").stdout
            r = table(case)
            err = r["permeability"]/(l*l/drag) - 1
            secs = float(re.search(r"run time\s+(\S+)", out).group(1))
            print("| square array c = %g, Sangani & Acrivos | l/%d | %d | 20 | %d | %+.2f%% | %.1f |"
                  % (c, m, n, r["cells"], 100*err, secs))


def plot():
    """|error| against run time, one line per case and Lloyd setting, from
    the table in the markdown file WORK; written beside it as .png"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    series = {}
    with open(WORK) as f:
        for line in f:
            cols = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cols) != 7 or not cols[5].endswith("%"):
                continue
            name = cols[0].split(",")[0] + ("" if cols[3] == "20" else ", no Lloyd steps")
            series.setdefault(name, []).append((float(cols[6]), abs(float(cols[5].rstrip("%")))))
    fig, ax = plt.subplots(figsize=(6.4, 4.5), dpi=100)
    for name, points in series.items():
        t, e = zip(*points)
        ax.loglog(t, e, "o-", label=name)
    ax.set_xlabel("run time of nmmPoreFlow [s] (mesh, checkMesh, simpleFoam)")
    ax.set_ylabel("|error of k| [%]")
    ax.set_title("nmmPoreFlow against closed forms")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.splitext(WORK)[0] + ".png")


def main():
    if WHAT == "plot":
        plot()
        return
    os.makedirs(WORK, exist_ok=True)
    if shutil.which("simpleFoam") is None and not os.path.exists("/usr/bin/simpleFoam"):
        raise SystemExit("OpenFOAM's simpleFoam is not installed (Debian package openfoam, "
                         "etc/debianPackages)")
    if WHAT == "convergence":
        convergence()
        return
    for name, test in (("slot", slot), ("discs", discs), ("repeatable", repeatable),
                       ("errors", errors)):
        if WHAT in ("all", name):
            test()
    if failures:
        raise SystemExit("%d check(s) failed" % len(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
