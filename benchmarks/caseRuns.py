"""What the benchmark drivers that run a case share: running an
application in a case as its Allrun would (log.<application>), reading
a function object's table, and the solver log's time split.

Only the standard library is used.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import re
import subprocess
import sys


def run(driver, case, application, binDir, env=None):
    """Run binDir/application in case (env: its environment, default
    this one's), its output in log.<application>; exit 1 naming the log
    when it fails. Returns the log's text"""
    log = case / ("log." + application)
    with open(log, "w") as out:
        r = subprocess.run([str(binDir / application)], cwd=case, env=env,
                           stdout=out, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        sys.exit("%s: %s failed; see %s" % (driver, application, log))
    return log.read_text()


def setKeyword(driver, path, keyword, value):
    """Set the one entry keyword of the dictionary file path to value;
    exit 1 when there is not exactly one"""
    text = path.read_text()
    new, n = re.subn(r"(?m)^(\s*%s\s+)[^;]*;" % keyword, r"\g<1>%s;" % value, text)
    if n != 1:
        sys.exit("%s: %s: expected one '%s' entry" % (driver, path, keyword))
    path.write_text(new)


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
    "Linear algebra:" line ((0, 0) without one); a run that solved its
    contacts in contact space gives its factorisations body by body (one
    solve of every body) and its direct contact-space solves"""
    m = re.search(r"Linear algebra: (\d+) factorisations .*?, (\d+) solves"
                  r" with an updated factor(?:; (\d+) factorisations body by body,"
                  r" (\d+) direct solves in contact space)?", solverLog)
    if not m:
        return (0, 0)
    if m.group(3):
        return (int(m.group(1)) + int(m.group(3)), int(m.group(2)) + int(m.group(4)))
    return (int(m.group(1)), int(m.group(2)))


#: The parts of a step the scaling plots show, and the solver log's
#: timing entries each is made of (the rest is the step's wall time less
#: these: start-up, output, stress updates)
STEP_PARTS = (
    ("detection", ("contact detection",)),
    ("assembly", ("assembly", "mass matrix", "contact assembly", "contact pattern")),
    ("contact solve", ("factorisation", "factor update", "solution", "contact update",
                       "body factorisation", "contact operator", "contact sweeps")),
)


def timeLoop(solverLog):
    """The time loop's wall time from the solver log ("Time loop (wall
    s): ..."), None for a log of an earlier build"""
    m = re.search(r"Time loop \(wall s\): ([0-9.eE+-]+)", solverLog)
    return float(m.group(1)) if m else None


def stepLimits(solverLog):
    """What set the steps' lengths, as the solver log counts them ("Steps
    by what set their length: growth 184, ..."), "" for a log of an
    earlier build"""
    m = re.search(r"Steps by what set their length: (.*)", solverLog)
    return m.group(1).strip() if m else ""


def solverFigures(case, solverLog):
    """What a run of nmmSolidFoam in case did, from its log and its
    contactStatistics table (postProcessing/contacts): accepted steps,
    steps cut and redone, iterations and linear solves per step, the
    timing split, and the time loop's wall time"""
    f = {"split": cpuSplit(solverLog)}
    f["factorisations"], f["updates"] = linearAlgebra(solverLog)
    f["stats"] = table(next((case / "postProcessing/contacts").glob("*/contacts.dat")))
    f["steps"] = len(f["stats"])
    f["cuts"] = int(sum(r[8] for r in f["stats"]))
    f["iterations"] = sum(r[7] for r in f["stats"])/f["steps"]
    f["solves"] = (f["factorisations"] + f["updates"])/f["steps"]
    f["wall"] = timeLoop(solverLog)
    f["limits"] = stepLimits(solverLog)
    return f


def stepParts(split, wall):
    """{detection, assembly, contact solve, rest} in seconds, from the
    solver log's timing split and the time loop's wall time (the rest:
    writing, stress updates, function objects)"""
    parts = dict((name, sum(split.get(k, 0) for k in keys)) for name, keys in STEP_PARTS)
    parts["rest"] = wall - sum(parts.values())
    return parts


def scalingPlot(results, count, title, out, driver):
    """Time per accepted step against the model's size: out (a PNG) and
    out.csv. results: dicts with count (the size), unknowns, steps, cuts,
    iterations (per step), solves (linear solves per step), wall (the
    solver's wall time) and the stepParts(). The plot needs Debian's
    matplotlib, seen by /usr/bin/python3"""
    from pathlib import Path
    names = [name for name, _ in STEP_PARTS] + ["rest"]
    out = Path(out)
    with open(out.with_suffix(".csv"), "w") as csv:
        csv.write("%s,unknowns,steps,cuts,iterations per step,linear solves per step,"
                  "wall per step [s],%s\n" % (count, ",".join("%s per step [s]" % p for p in names)))
        for f in results:
            csv.write("%d,%d,%d,%d,%.3f,%.3f,%.6g,%s\n" % (
                f["count"], f["unknowns"], f["steps"], f["cuts"], f["iterations"],
                f["solves"], f["wall"]/f["steps"],
                ",".join("%.6g" % (f[p]/f["steps"]) for p in names)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, it) = plt.subplots(1, 2, figsize=(11, 4.5))
    sizes = [f["count"] for f in results]
    for p in names:
        ax.loglog(sizes, [max(f[p], 1e-9)/f["steps"] for f in results], "o-", label=p)
    ax.loglog(sizes, [f["wall"]/f["steps"] for f in results], "k^-", label="step")
    ax.set_xlabel(count)
    ax.set_ylabel("wall time per accepted step [s]")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    it.semilogx(sizes, [f["iterations"] for f in results], "o-", label="iterations (sweeps)")
    it.semilogx(sizes, [f["solves"] for f in results], "s-", label="linear solves")
    it.semilogx(sizes, [100*f["cuts"]/f["steps"] for f in results], "^-",
                label="steps cut [% of accepted]")
    it.set_xlabel(count)
    it.set_title("Per accepted step")
    it.grid(True, which="both", alpha=0.3)
    it.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print("%s: wrote %s and %s" % (driver, out, out.with_suffix(".csv")))
