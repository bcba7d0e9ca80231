#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""Check tutorials/verification/contact/stickSlip: a block of m = 1 kg/m on
a fixed base (mu = 0.8, g = 9.81) pushed by F(t) = 8 cos t to T = 10 s,
against closedForms.stickSlip.

Usage:
    checkStickSlip.py <caseDir>

Reads the rows of every step the case's function objects write:
postProcessing/contacts/0/contacts.dat (contactStatistics: the sliding
contacts) and postProcessing/motion/0/motion.dat (blockMotion: the block's
centre). A slip is a run of steps in which every closed contact slides
(the elastic block slips partially before: single contacts slide first);
its start and end are the middles of the steps in which the last contact
starts sliding and the first one sticks again. Checks: as many slips as the closed form, each start and end
within 2 deltaT of it, and the block's x displacement (its centre against
the start) on every plateau, the mean over the plateau less 2 deltaT at
either end, within 2% of the closed form.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TIME_TOLERANCE = 2          # deltaT
PLATEAU_TOLERANCE = 0.02    # relative


def table(case, name):
    """postProcessing/<name>/0/<name>.dat as {column: array}"""
    path = Path(case)/"postProcessing"/name/"0"/(name + ".dat")
    if not path.is_file():
        raise SystemExit("%s: not found (the case's function objects)" % path)
    lines = path.read_text().splitlines()
    header = [ln for ln in lines if ln.startswith("#")][-1][1:].split()
    rows = [[float(v) for v in ln.split()] for ln in lines
            if ln.strip() and not ln.startswith("#")]
    data = np.array(rows).reshape(-1, len(header))
    return {h: data[:, k] for k, h in enumerate(header)}


def slips(contacts):
    """[(start, end)] of the runs of steps in which the block slides, every
    closed contact sliding, each at the middle of its step; an unfinished
    run ends at the last row. (Single contacts slide before: the elastic
    block's springs share the shear unevenly, so partial slip spreads in
    from the edges as |F| approaches the friction.)"""
    t, dt = contacts["time"], contacts["deltaT"]
    sliding = (contacts["sliding"] > 0) & (contacts["bonded"] == 0)
    result, start = [], None
    for k in range(len(t)):
        middle = t[k] - 0.5*dt[k]
        if sliding[k] and start is None:
            start = middle
        elif not sliding[k] and start is not None:
            result.append((start, middle))
            start = None
    if start is not None:
        result.append((start, float(t[-1])))
    return result


def plateauPositions(motion, plateaus, margin):
    """The block's mean x displacement over each plateau, margin off either
    end (nan where no row is left)."""
    t = motion["time"]
    x = motion["block:x"] - motion["block:x"][0]
    result = []
    for a, b, _ in plateaus:
        inside = (t >= a + margin) & (t <= b - margin)
        result.append(float(x[inside].mean()) if inside.any() else float("nan"))
    return result


def errors(case):
    """{measure: relative error} for the work-precision study: the largest
    error of the slip times over the closed form's first slip window
    (slipTimeError) and of the plateau positions (plateauError)."""
    c = cf.stickSlip
    contacts = table(case, "contacts")
    motion = table(case, "motion")
    found, exact = slips(contacts), c.windows()
    n = min(len(found), len(exact))
    timeError = max([abs(f[i] - e[i]) for f, e in zip(found[:n], exact[:n])
                     for i in (0, 1)] or [float("nan")])
    dt = float(np.median(contacts["deltaT"]))
    x = plateauPositions(motion, c.plateaus(), 2*dt)
    plateauError = max(abs(xi/p[2] - 1) for xi, p in zip(x, c.plateaus()))
    return {"slipTimeError": timeError/(exact[0][1] - exact[0][0]),
            "plateauError": plateauError}


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    c = cf.stickSlip
    contacts = table(argv[0], "contacts")
    motion = table(argv[0], "motion")
    dt = float(np.median(contacts["deltaT"]))
    r = nf.report("stickSlip")
    found, exact = slips(contacts), c.windows()
    r.absolute("slips", float(len(found)), float(len(exact)), 0.0)
    for k, ((a, b), (ea, eb, _, _)) in enumerate(zip(found, exact)):
        r.absolute("slip %d start [s]" % (k + 1), a, ea, TIME_TOLERANCE*dt*(1 + 1e-9))
        r.absolute("slip %d end [s]" % (k + 1), b, eb, TIME_TOLERANCE*dt*(1 + 1e-9))
    for k, (x, (a, b, ex)) in enumerate(zip(plateauPositions(motion, c.plateaus(), 2*dt),
                                            c.plateaus())):
        r.relative("plateau %d (%.4g .. %.4g s): x [m]" % (k + 1, a, b), x, ex,
                   PLATEAU_TOLERANCE)
    t = motion["time"]
    x = motion["block:x"] - motion["block:x"][0]
    stuck = np.array([not any(a <= ti <= b for a, b, _, _ in exact) for ti in t])
    if stuck.any():
        # Within a plateau the position should not creep
        spread = max(float(np.ptp(x[(t >= a + 2*dt) & (t <= b - 2*dt)]))
                     for a, b, _ in c.plateaus() if b - a > 4*dt)
        r.info("largest spread of x within a plateau [m]", spread)
    r.info("deltaT [s]", dt)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
