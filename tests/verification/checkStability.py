#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""The stiff and extreme cases of docs/verification.md: the run must stay
finite, bounded and honest.

Usage:
    checkStability.py <case> <projectDir> <binDir> <workDir>

<case> is one of the names of CASES below. Each writes its case folders
under <workDir> with the writers of tutorials/verification/makeCases.py,
runs nmmMesh and nmmSolidFoam on them (<binDir>), and checks the logs,
the function objects' tables and the VTK frames against a stated bound.
Every case also checks that each run ends with 'End', that no number in
its log or tables is NaN or infinite, and that every step converged or was
cut and redone (no step left unresolved). Prints a table per case; exit 1
when a check fails. docs/verification/stability.md is the record.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import checkIncline  # noqa: E402
import nmmFrames as nf  # noqa: E402

mc = None           # tutorials/verification/makeCases.py, imported in main
BIN = None
PROJECT = None

G = 9.81
DDA = "{ type DDA; velocityRatio 1; }"
TRAPEZOIDAL = "{ type Newmark; beta 0.25; gamma 0.5; }"
CONTACT_FUNCTIONS = """\
    contacts    { type contactStatistics; }
    balance     { type energy; }
"""


# --------------------------------------------------------------------------
# Running a case and reading what it wrote

class run:
    """A case folder after nmmMesh and nmmSolidFoam."""

    def __init__(self, case):
        self.case = Path(case)
        self.log = (self.case/"log.nmmSolidFoam").read_text()
        self.steps = [tuple(float(v) for v in m) for m in re.findall(
            r"contacts: open (\S+), bonded (\S+), sliding (\S+); iterations (\S+), "
            r"cuts (\S+), max penetration ([^,\s]+)", self.log)]
        self.cuts = len(re.findall(r"^\s*step cut:", self.log, re.M))
        self.unsettled = len(re.findall(r"did not settle", self.log))
        self.conditioningWarning = "badly conditioned" in self.log

    def table(self, name):
        """postProcessing/<name>/0/<name>.dat as {column: array}"""
        path = self.case/"postProcessing"/name/"0"/(name + ".dat")
        lines = path.read_text().splitlines()
        header = [ln for ln in lines if ln.startswith("#")][-1][1:].split()
        rows = [[float(v) for v in ln.split()] for ln in lines
                if ln.strip() and not ln.startswith("#")]
        data = np.array(rows).reshape(-1, len(header))
        return {h: data[:, k] for k, h in enumerate(header)}

    def referenceLength(self):
        """lRef: the tributary length whose springs are the penalties"""
        return float(re.search(r"for a tributary length of ([^)\s]+)\)",
                               self.log).group(1))

    def largestSpringShare(self, c, closed, kn, load):
        """The largest closed contact's spring force over the load it
        shares: penetration x kn x max(length/lRef, 0.05) (the springs of
        docs/case-reference.md, thickness 1)"""
        weight = np.maximum(c["length"][closed]/self.referenceLength(), 0.05)
        return float((c["penetration"][closed]*kn*weight).max())/load

    def maxPenetration(self):
        return max([s[5] for s in self.steps] + [0.0])

    def lastClosed(self):
        """Closed (bonded + sliding) contacts after the last step"""
        return int(self.steps[-1][1] + self.steps[-1][2]) if self.steps else 0

    def maxIterations(self):
        return int(max([s[3] for s in self.steps] + [0]))

    def finite(self):
        """No nan or inf in the log or the tables"""
        texts = [self.log] + [p.read_text() for p in
                              (self.case/"postProcessing").glob("*/0/*.dat")]
        return not any(re.search(r"(?i)\b-?(nan|inf)\b", t) for t in texts)


def execute(case, mayFail=False):
    """nmmMesh and nmmSolidFoam on a case folder; the run (its exit code
    must be 0 and its log end with End). mayFail: the solver's exit code
    instead of the run when it is not 0."""
    case = Path(case)
    for app in ("nmmMesh", "nmmSolidFoam"):
        with open(case/("log." + app), "w") as log:
            rc = subprocess.call([str(BIN/app), "-case", str(case)],
                                 stdout=log, stderr=subprocess.STDOUT)
        if rc != 0 and mayFail and app == "nmmSolidFoam":
            return rc
        if rc != 0:
            tail = (case/("log." + app)).read_text().splitlines()[-25:]
            raise SystemExit("%s on %s: exit code %d\n%s"
                             % (app, case, rc, "\n".join(tail)))
    r = run(case)
    if [ln for ln in r.log.splitlines() if ln.strip()][-1] != "End":
        raise SystemExit("%s: log.nmmSolidFoam does not end with End" % case)
    return r


def stopReason(case):
    """The last step cut's reason and the time of a run that stopped"""
    log = (Path(case)/"log.nmmSolidFoam").read_text()
    cuts = re.findall(r"step cut: ([^;]*);", log)
    times = re.findall(r"^Time = (\S+)", log, re.M)
    return "%s, after t = %s" % (cuts[-1] if cuts else "no step cut",
                                times[-1] if times else "0")


def fresh(work, name):
    case = Path(work)/name
    if case.exists():
        shutil.rmtree(case)
    case.mkdir(parents=True)
    return case


def common(r, name, rep):
    """The checks every run passes: finite, every step resolved"""
    rep.upper("%s: NaN or inf in log and tables" % name, 0.0 if r.finite() else 1.0, 0)
    rep.info("%s: steps cut and redone" % name, r.cuts)
    rep.info("%s: most open-close iterations in a step" % name, r.maxIterations())


def blockCase(case, blocks, patches, cellSize, E, nu, rho, solution, endTime,
              deltaT, writeInterval, D, functions=CONTACT_FUNCTIONS, g=(0, -G),
              law=None, U=None, planeStress=False, materials=None):
    """A whole case folder from makeCases.py's writers"""
    c = str(case)
    mc.dynamicControlDict(c, endTime, deltaT, writeInterval,
                          "written by tests/verification/checkStability.py",
                          functions=functions)
    mc.write(c, "system/nmmSolution", "system", "nmmSolution", solution)
    if materials is None:
        mc.mechanicalProperties(c, planeStress, "rock", E, nu, rho)
    else:
        mc.write(c, "constant/mechanicalProperties", "constant", "mechanicalProperties",
                 "planeStress     %s;\n\nthickness       1;\n\nmaterials\n{\n%s}\n"
                 % ("yes" if planeStress else "no", materials))
    if g is not None:
        mc.gravity(c, g[0], g[1])
    if law is not None:
        law(c)
    else:
        mc.contactLaw(c, 0)
    mc.meshDict(c, blocks, patches, "    type        structured;\n    cellSize    %s;\n"
                % cellSize)
    mc.D(c, D)
    if U is not None:
        mc.U(c, U)


def solution(scheme, contact="", stepControl="", analysis="dynamic",
             method="penalty"):
    return """\
analysis        %s;

%slinearSolver    { type cholmod; }

contact
{
    method                  %s;
%s}

stepControl
{
%s}
""" % (analysis, "" if scheme is None else "timeScheme      %s\n\n" % scheme,
       method, contact, stepControl)


FIXED_BASE = "    fixed       { type box; min (-10 -0.500001); max (10 -0.499999); }\n"
FIXED_D = "    fixed       { type fixedValue; value uniform (0 0 0); }\n"


# --------------------------------------------------------------------------
# 1. A block resting on a fixed base, normal penalty 1 to 1e8 times E

def restingCase(work, ratio, E, rho):
    case = fresh(work, "restingBlock_kn%g" % ratio)
    blockCase(case, """\
    base  { material rock; polygon ((-0.5 -0.5) (1.5 -0.5) (1.5 0) (-0.5 0)); }
    block { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
""", FIXED_BASE, 0.25, E, 0.25, rho,
        solution(DDA, "    normalPenalty           %g;\n" % (ratio*E),
                 "    maxDisplacementRatio    0.005;\n"),
        0.4, 0.01, 0.1, FIXED_D,
        functions=CONTACT_FUNCTIONS
        + "    motion      { type blockMotion; blocks (block); }\n")
    return case


def restingBlock(work, rep):
    """A 1 x 1 block (rho 2000, E 1e9) on a 2 x 0.5 base fixed at its
    bottom, frictionless, DDA, 40 steps of 0.01 s from rest, touching.
    At rest the closed contacts' springs carry the weight: the sum of
    their normal forces kn delta_i is W = rho g (thickness 1), whatever
    kn, so the largest spring force F_max = delta kn w (w the contact's
    spring weight, max(length/lRef, 0.05), docs/case-reference.md) lies
    in W/n <= F_max <= W (n closed contacts): the penetration falls as
    1/kn. Pass, at normal penalties kn = 1, 1e2, 1e4, 1e6, 1e8 and 1e11
    times E: the sum of the normal forces in the last frame within 1% of
    W; F_max/W in [1/n, 1]. The log must be honest about conditioning:
    no warning where the answer is right and the largest/smallest pivot
    stays below 1e12 (kn/E <= 1e8), the warning at kn/E = 1e11 (pivot
    ratio above 1e12), and at kn/E = 1e12 either a fatal error (exit code
    1) that names the conditioning and the penalty, when the
    factorisation loses a pivot to rounding, or the warning with the
    forces still summing to W within 1%."""
    E, rho = 1e9, 2000.0
    W = rho*G
    for ratio in (1, 1e2, 1e4, 1e6, 1e8, 1e11):
        kn = ratio*E
        case = restingCase(work, ratio, E, rho)
        r = execute(case)
        name = "kn/E %g" % ratio
        common(r, name, rep)
        c = nf.contactsOfFrame(nf.readSeries(case)[-1][1])
        closed = c["contactState"] > 0
        n = int(closed.sum())
        rep.relative("%s: sum of normal forces / W" % name,
                     float(c["normalForce"][closed].sum())/W, 1.0, 0.01)
        share = r.largestSpringShare(c, closed, kn, W)
        rep.upper("%s: largest spring force / W outside [1/n, 1], n = %d"
                  % (name, n), 0.0 if 1.0/n <= share <= 1.0 else share, 0)
        rep.info("%s: largest penetration [m]" % name, float(c["penetration"].max()))
        ratioLine = re.search(r"Largest pivot ratio[^:]*: (\S+)", r.log)
        pivots = float(ratioLine.group(1)) if ratioLine else float("nan")
        rep.info("%s: largest/smallest pivot" % name, pivots)
        warnedRight = r.conditioningWarning == (pivots > 1e12) \
            and r.conditioningWarning == (ratio > 1e8)
        rep.upper("%s: conditioning warning %s" % (
            name, "missing" if ratio > 1e8 else "below pivot ratio 1e12"),
            0.0 if warnedRight else 1.0, 0)
        motion = r.table("motion")
        rep.info("%s: sideways drift [m]" % name,
                 float(motion["block:x"][-1] - motion["block:x"][0]))
    case = restingCase(work, 1e12, E, rho)
    r = execute(case, mayFail=True)
    if isinstance(r, run):
        c = nf.contactsOfFrame(nf.readSeries(case)[-1][1])
        closed = c["contactState"] > 0
        total = float(c["normalForce"][closed].sum())/W
        honest = r.conditioningWarning and abs(total - 1) <= 0.01
        rep.info("kn/E 1e12: sum of normal forces / W", total)
    else:
        log = (case/"log.nmmSolidFoam").read_text()
        honest = r == 1 and "too badly conditioned" in log and "normalPenalty" in log
    rep.upper("kn/E 1e12: neither a fatal error naming the conditioning nor "
              "a warned, right answer", 0.0 if honest else 1.0, 0)


def inclinePenalty(work, rep):
    """The incline of docs/verification.md at phi = 31 degrees on a slope
    of a = 30 (gravity tilted; the block sticks), normal penalty 1 to 1e8
    times E (shear penalty kn/2.5), DDA, 40 steps of 0.01 s from rest.
    At rest the contact forces balance the weight: sum of the normal
    forces W cos a, sum of the shear forces W sin a. Pass: both within 1%
    in the last frame, the largest spring force (restingBlock) over W cos a in
    [1/n, 1] (it falls as 1/kn), and the block's drift along the slope
    below the allowed penetration (0.4 of the search distance)."""
    E, rho = 1e9, 2000.0
    W = rho*G
    a = math.radians(30)
    allowed = 0.4*2.5*0.005*2.0
    for ratio in (1, 1e2, 1e4, 1e6, 1e8):
        kn = ratio*E
        case = fresh(work, "inclinePenalty_kn%g" % ratio)
        blockCase(case, """\
    base   { material rock; polygon ((0 -0.5) (4 -0.5) (4 0) (0 0)); }
    slider { material rock; polygon ((0.25 0) (1.25 0) (1.25 1) (0.25 1)); }
""", FIXED_BASE, 0.25, E, 0.25, rho,
            solution(DDA, "    normalPenalty           %g;\n" % kn,
                     "    maxDisplacementRatio    0.005;\n"),
            0.4, 0.01, 0.1, FIXED_D,
            functions=CONTACT_FUNCTIONS
            + "    motion      { type blockMotion; blocks (slider); }\n",
            g=(G*math.sin(a), -G*math.cos(a)), law=lambda c: mc.contactLaw(c, 31))
        r = execute(case, mayFail=True)
        name = "kn/E %g" % ratio
        if not isinstance(r, run):
            rep.upper("%s: run stopped (exit code %d): %s" % (name, r, stopReason(case)), 1, 0)
            continue
        common(r, name, rep)
        c = nf.contactsOfFrame(nf.readSeries(case)[-1][1])
        closed = c["contactState"] > 0
        n = int(closed.sum())
        rep.relative("%s: sum of normal forces / (W cos a)" % name,
                     float(c["normalForce"][closed].sum())/(W*math.cos(a)), 1.0, 0.01)
        rep.relative("%s: |sum of shear forces| / (W sin a)" % name,
                     abs(float(c["shearForce"][closed].sum()))/(W*math.sin(a)), 1.0, 0.01)
        share = r.largestSpringShare(c, closed, kn, W*math.cos(a))
        rep.upper("%s: largest spring force / (W cos a) outside [1/n, 1], n = %d"
                  % (name, n), 0.0 if 1.0/n <= share <= 1.0 else share, 0)
        motion = r.table("motion")
        rep.upper("%s: |drift along the slope| [m]" % name,
                  float(abs(motion["slider:x"][-1] - motion["slider:x"][0])), allowed)
        rep.info("%s: largest penetration [m]" % name, float(c["penetration"].max()))


# --------------------------------------------------------------------------
# 2. Time steps 1e-1 down to 1e-9 s: a frictionless slide

def timeStep(work, rep):
    """The incline of docs/verification.md at phi = 0 (a = 30 degrees,
    gravity tilted): 1 x 1 block on a fixed base, frictionless, DDA, which
    is exact for a constant acceleration: d(t) = g sin(a) t^2/2 and
    u(t) = g sin(a) t along the slope. Ten steps of each dt from 1e-1 to
    1e-9 s. The slider's displacement (mean D_x of its elements, binary
    VTK, so resolved relative to itself) and velocity must be within 1%
    of the closed form at every dt: the error levels off and never
    grows as dt falls."""
    a = math.radians(30)
    acc = G*math.sin(a)
    for k in range(1, 10):
        dt = 10.0**-k
        case = fresh(work, "timeStep_dt1e-%d" % k)
        blockCase(case, """\
    base   { material rock; polygon ((0 -0.5) (4 -0.5) (4 0) (0 0)); }
    slider { material rock; polygon ((0.25 0) (1.25 0) (1.25 1) (0.25 1)); }
""", FIXED_BASE, 0.25, 1e9, 0.25, 2000,
            solution(DDA, stepControl="    maxDisplacementRatio    0.005;\n"
                     "    minDeltaT               1e-12;\n"),
            10*dt, dt, 10*dt, FIXED_D,
            functions=CONTACT_FUNCTIONS
            + "    motion      { type blockMotion; blocks (slider); }\n",
            g=(G*math.sin(a), -G*math.cos(a)))
        r = execute(case)
        name = "dt 1e-%d" % k
        common(r, name, rep)
        t, path = nf.readSeries(case)[-1]
        mean, _ = checkIncline.blockDisplacement(nf.readFrame(path), 1)
        rep.relative("%s: d(10 dt) [m]" % name, float(mean[0]), 0.5*acc*t*t, 0.01)
        ux = float(r.table("motion")["slider:Ux"][-1])
        rep.relative("%s: u(10 dt) [m/s]" % name, ux, acc*t, 0.01)


# --------------------------------------------------------------------------
# 3. A fast block: travel per step 10 times its thickness

def fastBlock(work, rep):
    """A 0.1 x 1 plate flying at v = 20 m/s (0/U: the plate only; the
    cover nodes of the plate lie within one cell of it, those of the wall
    beyond x = 0.45) towards a fixed 0.5 x 2 wall 0.3 m away; no gravity,
    frictionless, DDA, E = 1e10 (impact strain v/c = 0.9%), deltaT 0.05 s:
    1 m, ten thicknesses, per step. The step control must shorten the
    steps (maxDisplacementRatio) so that the contact is found. Pass: no
    point of the plate ever passes the wall's face by more than the
    allowed penetration (0.4 of the search distance), nor does any
    contact; the plate ends moving away from the wall or at rest; its
    kinetic energy never exceeds the initial 1/2 m v^2 (no energy gain)."""
    rho, v = 2000.0, 20.0
    case = fresh(work, "fastBlock")
    blockCase(case, """\
    wall  { material rock; polygon ((0.5 -1) (1 -1) (1 1) (0.5 1)); }
    plate { material rock; polygon ((0.1 -0.5) (0.2 -0.5) (0.2 0.5) (0.1 0.5)); }
""", "    fixed       { type box; min (0.999999 -2); max (1.000001 2); }\n",
        0.05, 1e10, 0.25, rho,
        solution(DDA, stepControl="    maxDisplacementRatio    0.005;\n"),
        0.1, 0.05, 2e-4, FIXED_D,
        functions=CONTACT_FUNCTIONS
        + "    motion      { type blockMotion; blocks (plate); }\n",
        g=None, U='expression "x < 0.35 ? vector(%g, 0, 0) : vector(0, 0, 0)"' % v)
    r = execute(case)
    common(r, "fast plate", rep)
    halfSize = 0.5*2.0
    allowed = 0.4*2.5*0.005*halfSize
    front = []
    for _, path in nf.readSeries(case):
        f = nf.readFrame(path)
        cells = np.flatnonzero(f.cellData["blockId"].astype(int) == 1)
        pts = np.unique(np.concatenate([f.cells[k] for k in cells]))
        front.append(float(f.x[pts, 0].max()))
    # The wall's face gives way elastically under the impact: the plate's
    # points past its undeformed position are not a penetration
    rep.info("largest x of the plate past the undeformed wall face [m]", max(front) - 0.5)
    rep.upper("plate's front past the wall face at the end [m]", front[-1] - 0.5, 0)
    rep.upper("largest contact penetration [m]", r.maxPenetration(), allowed)
    m = r.table("motion")
    rep.upper("final velocity towards the wall [m/s]", float(m["plate:Ux"][-1]), 1e-6*v)
    e = r.table("balance")
    ke0 = 0.5*rho*0.1*v*v
    rep.upper("largest kinetic energy / initial", float(e["kinetic"].max()/ke0), 1.0 + 1e-6)
    rep.info("final kinetic energy / initial", float(e["kinetic"][-1]/ke0))


# --------------------------------------------------------------------------
# 4. Corners meeting exactly and at +-1e-9 offsets

def corners(work, rep):
    """A 1 x 1 block whose lower left corner meets the upper right corner
    of a fixed 1 x 0.5 base: dropped from 1e-3 m with the corners above
    each other, shifted sideways by s = -1e-9, 0, +1e-9 m; and placed on
    it with a vertical gap of -1e-9 (overlap), 0, +1e-9 m. The block's
    centre is beyond the base: it tips over the corner and falls.
    Frictionless, DDA, 200 steps of 1e-3 s. Pass: every step settles
    within the open-close limit (no 'did not settle' cut: no flip-flop
    without end), and the energy never grows: total (kinetic + strain +
    contact - work of gravity) stays below its start plus 1e-6 m g
    (the energy of a micrometre of fall)."""
    rho = 2000.0
    m = rho*1.0
    for s, gap in ((-1e-9, 1e-3), (0.0, 1e-3), (1e-9, 1e-3),
                   (0.0, -1e-9), (0.0, 0.0), (0.0, 1e-9)):
        x0, y0 = 1.0 + s, gap
        name = "%s s = %+g, gap %+g" % ("drop" if gap > 1e-6 else "touch", s, gap)
        case = fresh(work, "corners_s%+g_gap%+g" % (s, gap))
        blockCase(case, """\
    base  { material rock; polygon ((0 -0.5) (1 -0.5) (1 0) (0 0)); }
    block { material rock; polygon (%s %s %s %s); }
""" % (mc.pt((x0, y0)), mc.pt((x0 + 1, y0)), mc.pt((x0 + 1, y0 + 1)),
            mc.pt((x0, y0 + 1))),
            FIXED_BASE, 0.25, 1e9, 0.25, rho,
            solution(DDA, stepControl="    maxDisplacementRatio    0.005;\n"),
            0.2, 1e-3, 0.01, FIXED_D)
        r = execute(case)
        common(r, name, rep)
        rep.upper("%s: steps whose open-close iteration did not settle" % name,
                  float(r.unsettled), 0)
        e = r.table("balance")
        rep.upper("%s: largest energy gain [J]" % name,
                  float((e["total"] - e["total"][0]).max()), 1e-6*m*G)
        rep.info("%s: energy lost by the end [J]" % name,
                 float(e["total"][0] - e["total"][-1]))
        rep.info("%s: max penetration [m]" % name, r.maxPenetration())
        rep.info("%s: steps with a closed contact" % name,
                 sum(1 for st in r.steps if st[1] + st[2] > 0))


# --------------------------------------------------------------------------
# 5. Stiffness contrast 1 to 1e6 between bonded blocks

def stiffnessContrast(work, rep):
    """Two 1 x 1 blocks bonded one on the other, the lower fixed at its
    bottom, the upper under a pressure p = 1e3 Pa on its top; nu = 0,
    plane stress, so the stress is uniaxial, sigma_yy = -p in both blocks
    whatever their moduli, and the top moves by p (1/E_lower + 1/E_upper)
    plus the bond springs' compression (between 0 and p/kn, kn = 50 times
    the larger E). Static analysis, one step. The softer modulus is 1e6
    (strain 1e-3), the other 1, 1e3 or 1e6 times it, above or below.
    Pass: each block's mean sigma_yy within 1% of -p; the top
    displacement in [0.99, 1.01] times the closed form, plus p/kn."""
    p, soft = 1e3, 1e6
    for ratio, stiffBelow in ((1, True), (1e3, True), (1e6, True), (1e3, False),
                              (1e6, False)):
        Elower, Eupper = (ratio*soft, soft) if stiffBelow else (soft, ratio*soft)
        name = "E_lower/E_upper %g" % (Elower/Eupper)
        case = fresh(work, "stiffnessContrast_%g" % (Elower/Eupper))
        blockCase(case, """\
    lower { material lower; polygon ((0 0) (1 0) (1 1) (0 1)); }
    upper { material upper; polygon ((0 1) (1 1) (1 2) (0 2)); }
""", """\
    fixed       { type box; min (-1 -1e-6); max (2 1e-6); }
    top         { type box; min (-1 1.999999); max (2 2.000001); }
""", 0.25, None, None, None,
            solution(None, analysis="static"), 1, 1, 1, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
    top
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %g;
    }
""" % p, g=None, planeStress=True,
            functions=CONTACT_FUNCTIONS
            + "    top         { type patchDisplacement; patch top; }\n",
            law=lambda c: mc.contactLaw(c, 30, cohesion=1e7, tensileStrength=1e7,
                                        initialState="bonded"),
            materials="    lower { type linearElastic; E %g; nu 0; rho 1; }\n"
                      "    upper { type linearElastic; E %g; nu 0; rho 1; }\n"
                      % (Elower, Eupper))
        r = execute(case)
        common(r, name, rep)
        f = nf.readFrame(nf.readSeries(case)[-1][1])
        ids = f.cellData["blockId"].astype(int)
        syy = nf.cellStress(f)[1]
        for b, label in ((0, "lower"), (1, "upper")):
            sel = ids == b
            mean = float((syy[sel]*f.cellArea[sel]).sum()/f.cellArea[sel].sum())
            rep.relative("%s: mean sigma_yy of the %s block [Pa]" % (name, label),
                         mean, -p, 0.01)
        kn = 50*max(Elower, Eupper)
        uy = -float(r.table("top")["Dy"][-1])
        elastic = p*(1/Elower + 1/Eupper)
        lo, hi = 0.99*elastic, 1.01*elastic + p/kn
        rep.upper("%s: top displacement outside [%.5g, %.5g] [m]" % (name, lo, hi),
                  0.0 if lo <= uy <= hi else abs(uy - elastic), 0)
        rep.info("%s: top displacement [m]" % name, uy, elastic)


# --------------------------------------------------------------------------
# 6. A spinning free block

def spinningBlock(work, rep):
    """A free 1 x 1 block spinning at w = 2 pi rad/s about its centre
    (0/U: vector(-w y, w x, 0) about the centre), no gravity, no contact,
    trapezoidal rule, 100 steps of 0.01 s: one revolution. rho = 1,
    E = 1e11: the centrifugal dilatation rho w^2 R^2/E is 2e-10, below
    the bound. Pass: |area change| < 1e-8 of the area at every frame of
    the revolution, the rotation within 1% of 2 pi (angular momentum is
    conserved). The kinetic energy's drift is reported."""
    w = 2*math.pi
    case = fresh(work, "spinningBlock")
    blockCase(case, """\
    block { material rock; polygon ((-0.5 -0.5) (0.5 -0.5) (0.5 0.5) (-0.5 0.5)); }
""", "", 0.25, 1e11, 0.25, 1,
        """\
analysis        dynamic;

timeScheme      %s

linearSolver    { type cholmod; }
""" % TRAPEZOIDAL, 1.0, 0.01, 0.1, "    // No patch: free\n",
        functions="""\
    motion      { type blockMotion; blocks (block); }
    balance     { type energy; }
""", g=None, U='expression "vector(%r*-y, %r*x, 0)"' % (w, w))
    r = execute(case)
    rep.upper("NaN or inf in log and tables", 0.0 if r.finite() else 1.0, 0)
    series = nf.readSeries(case)
    areas = []
    for _, path in series:
        f = nf.readFrame(path)
        areas.append(float(nf.polygonCentroids(f.x, f.cells)[1].sum()))
    areas = np.array(areas)
    rep.upper("largest |area change|/area over the revolution",
              float(abs(areas - areas[0]).max()/areas[0]), 1e-8)
    m = r.table("motion")
    turned = float(np.unwrap(m["block:rotation"])[-1] - m["block:rotation"][0])
    rep.relative("rotation after 1 s [rad]", turned, 2*math.pi, 0.01)
    e = r.table("balance")
    rep.info("kinetic energy after 1 s [J]", float(e["kinetic"][-1]),
             float(e["kinetic"][0]))


# --------------------------------------------------------------------------
# 7. A bonded packing loaded far past its strength

def grainPacking(n, h, jitter, seed):
    """n x n polygon grains of size h tiling [0, n h]^2: the interior
    vertices of the square lattice moved at random by up to jitter h, so
    that neighbours share their edges exactly (cemented grains)"""
    rng = np.random.default_rng(seed)
    P = np.array([[(i*h, j*h) for j in range(n + 1)] for i in range(n + 1)], dtype=float)
    P[1:n, 1:n] += rng.uniform(-jitter*h, jitter*h, size=(n - 1, n - 1, 2))
    grains = []
    for i in range(n):
        for j in range(n):
            grains.append([P[i, j], P[i + 1, j], P[i + 1, j + 1], P[i, j + 1]])
    return grains


def marble(work, rep):
    """25 marble grains (5 x 5 jittered polygons of 0.2 m, E = 50 GPa,
    rho = 2700) bonded (c = 20 MPa, tensile strength 10 MPa, phi = 35
    degrees: the packing's uniaxial strength is about 2 c tan(45 + phi/2)
    = 77 MPa), fixed at the bottom and loaded on the top by a pressure
    ramped to 1.1 GPa (about 14 times that) in 0.2 ms, held to 1 ms.
    DDA. Pass: the run ends (every step converged or was cut and redone,
    none left unresolved); nothing NaN; the bonds fail (more than half of
    the initially bonded contacts broken); the energy is bounded by the
    work of the load: kinetic + strain + contact <= work (total <= 0) to
    1% of the work."""
    n, h = 5, 0.2
    grains = grainPacking(n, h, 0.2, 20261122)
    blocks = "".join("    g%d { material marble; polygon (%s); }\n"
                     % (k, " ".join(mc.pt(p) for p in g)) for k, g in enumerate(grains))
    case = fresh(work, "marble")
    L = n*h
    blockCase(case, blocks, """\
    fixed       { type box; min (-1 -1e-6); max (2 1e-6); }
    top         { type box; min (-1 %s); max (2 %s); }
""" % (mc.fmt(L - 1e-6), mc.fmt(L + 1e-6)), 0.1, None, None, None,
        solution(DDA, stepControl="    maxDisplacementRatio    0.005;\n"),
        1e-3, 1e-5, 1e-4, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
    top
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    expression "1.1e9*min(t/2e-4, 1)";
    }
""", g=None,
        law=lambda c: mc.contactLaw(c, 35, cohesion=2e7, tensileStrength=1e7,
                                    initialState="bonded"),
        materials="    marble { type linearElastic; E 5e10; nu 0.25; rho 2700; }\n")
    r = execute(case)
    common(r, "marble", rep)
    stats = r.table("contacts")
    bonded0 = float(stats["bonded"][0] + stats["bondsBroken"][0])
    broken = float(stats["bondsBroken"].sum())
    rep.upper("bonds left intact / bonds at the start",
              float(stats["bonded"][-1])/bonded0, 0.5)
    rep.info("bonds broken", broken)
    e = r.table("balance")
    work_ = float(e["work"].max())
    rep.upper("largest (kinetic + strain + contact - work) / work",
              float(e["total"].max())/work_, 0.01)
    rep.info("kinetic energy at the end / work", float(e["kinetic"][-1])/work_)
    rep.info("steps", len(r.steps))
    rep.info("steps cut and redone", r.cuts)
    rep.info("largest penetration [m]", r.maxPenetration())


# --------------------------------------------------------------------------
# Hertz's cylinder on a flat over the normal penalty

# contactModel's minWeight: the spring of a contact of tiny tributary
# length is this fraction of the penalty
MIN_SPRING_WEIGHT = 0.05


def hertzPenalty(work, rep):
    """tutorials/verification/contact/hertz (a cylinder of E = 1 on a flat
    of E = 1e4, static, frictionless, P/2 = 0.005 on the half model) with
    the normal penalty 1 to 1e8 times the cylinder's E. Pass: the single
    step settles, no closed contact pulls, the vertical contact forces
    carry P/2 within 1%, and the largest penetration falls as 1/kn where
    every spring is stiff against the elements: from one penalty to the
    next (x 100) it falls by a factor in [50, 200] once the weakest spring
    (a vertex with 5% of the median tributary length gets the smallest
    weight, 0.05: contactModel's minWeight) is 100 times E, kn/E >= 2000.
    Softer springs share the load by the geometry of the approach, not by
    the elements' stiffness: their force grows with kn, and the
    penetration falls more slowly (a cylinder on a Winkler layer: as
    kn^(-2/3), 21.5 a step); there it must only fall."""
    last = None
    for ratio in (1, 1e2, 1e4, 1e6, 1e8):
        case = Path(work)/("hertzPenalty_kn%g" % ratio)
        if case.exists():
            shutil.rmtree(case)
        shutil.copytree(Path(PROJECT)/"tutorials"/"verification"/"contact"/"hertz", case)
        sol = case/"system"/"nmmSolution"
        text, n = re.subn(r"normalPenalty\s+auto;", "normalPenalty %g;" % ratio,
                          sol.read_text())
        if n != 1:
            raise SystemExit("%s: no 'normalPenalty auto;' to replace" % sol)
        sol.write_text(text)
        r = execute(case, mayFail=True)
        name = "kn/E %g" % ratio
        if not isinstance(r, run):
            rep.upper("%s: run stopped (exit code %d): %s" % (name, r, stopReason(case)), 1, 0)
            last = None
            continue
        common(r, name, rep)
        rep.upper("%s: steps cut and redone" % name, float(r.cuts), 0)
        c = nf.contactsOfFrame(nf.readSeries(case)[-1][1])
        closed = c["contactState"] > 0
        fn = c["normalForce"][closed]
        rep.upper("%s: most tension in a closed contact [N]" % name,
                  float(max(-fn.min(), 0.0)) if fn.size else 0.0, 0)
        vertical = float((fn*np.abs(c["normal"][closed][:, 1])).sum())
        rep.relative("%s: vertical contact force / (P/2)" % name, vertical/0.005, 1.0, 0.01)
        pen = float(c["penetration"].max())
        rep.info("%s: largest penetration [m]" % name, pen)
        if last is not None and pen > 0:
            fall = last/pen
            rep.info("%s: penetration fall from kn/100" % name, fall)
            if ratio/100*MIN_SPRING_WEIGHT >= 100:
                rep.upper("%s: penetration fall from kn/100 outside [50, 200]" % name,
                          0.0 if 50 <= fall <= 200 else fall, 0)
            else:
                rep.upper("%s: penetration fall from kn/100 (soft springs) not above 1"
                          % name, 0.0 if fall > 1 else fall, 0)
        last = pen


def restingAL(work, method, ratio, extra):
    """restingBlock's case with the given contact method; its run"""
    E, rho = 1e9, 2000.0
    case = fresh(work, "restingAL_%s_kn%g" % (method, ratio))
    blockCase(case, """\
    base  { material rock; polygon ((-0.5 -0.5) (1.5 -0.5) (1.5 0) (-0.5 0)); }
    block { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
""", FIXED_BASE, 0.25, E, 0.25, rho,
        solution(DDA, "    normalPenalty           %g;\n%s" % (ratio*E, extra),
                 "    maxDisplacementRatio    0.005;\n", method=method),
        0.4, 0.01, 0.1, FIXED_D)
    return case, execute(case)


def hertzAL(work, method, ratio, extra):
    """hertzPenalty's case with the given contact method; its run"""
    case = Path(work)/("hertzAL_%s_kn%g" % (method, ratio))
    if case.exists():
        shutil.rmtree(case)
    shutil.copytree(Path(PROJECT)/"tutorials"/"verification"/"contact"/"hertz", case)
    sol = case/"system"/"nmmSolution"
    text, n = re.subn(r"normalPenalty\s+auto;", "normalPenalty %g;\n%s" % (ratio, extra),
                      sol.read_text())
    text, m = re.subn(r"method\s+penalty;", "method %s;" % method, text)
    if n != 1 or m != 1:
        raise SystemExit("%s: no 'normalPenalty auto;' or 'method penalty;'" % sol)
    sol.write_text(text)
    return case, execute(case)


def augmentedLagrangian(work, rep):
    """Penetration against the penalty for both contact methods: the
    resting block (restingBlock's case, weight W) at kn/E = 1, 1e2, 1e4,
    and Hertz (hertzPenalty's, load P/2) at kn/E = 1e4, 1e6. The penalty
    method's penetration falls with kn (by at least 10 per factor 100);
    the augmented Lagrangian's stays within its penetrationTolerance,
    1e-9 m, whatever kn, and the contact forces carry the load within 1%.
    (Uzawa's rounds shrink the penetration by about 1/(1 + kN c): with
    Hertz's softest springs, kn/E <= 1e2, twenty rounds do not reach 1e-9
    m; the step is then cut with that reason.)"""
    tol = 1e-9
    extraAL = "    penetrationTolerance    %g;\n" % tol
    W = 2000.0*G
    cases = [("block", r) for r in (1, 1e2, 1e4)] + [("hertz", r) for r in (1e4, 1e6)]
    previous = {}
    for which, ratio in cases:
        for method in ("penalty", "augmentedLagrangian"):
            name = "%s %s kn/E %g" % (which, method, ratio)
            extra = extraAL if method != "penalty" else ""
            make = restingAL if which == "block" else hertzAL
            case, r = make(work, method, ratio, extra)
            common(r, name, rep)
            c = nf.contactsOfFrame(nf.readSeries(case)[-1][1])
            closed = c["contactState"] > 0
            fn = c["normalForce"][closed]
            if which == "block":
                rep.relative("%s: sum of normal forces / W" % name, float(fn.sum())/W, 1.0, 0.01)
            else:
                vertical = float((fn*np.abs(c["normal"][closed][:, 1])).sum())
                rep.relative("%s: vertical contact force / (P/2)" % name,
                             vertical/0.005, 1.0, 0.01)
            pen = float(max(c["penetration"][closed].max(), 0.0)) if closed.any() else 0.0
            if method == "penalty":
                rep.info("%s: largest penetration [m]" % name, pen)
                if (which, "penalty") in previous:
                    fall = previous[(which, "penalty")]/max(pen, 1e-300)
                    rep.info("%s: penetration fall from kn/100" % name, fall)
                    rep.upper("%s: penetration fall from kn/100 below 10" % name,
                              0.0 if fall >= 10 else 1.0, 0)
                previous[(which, "penalty")] = pen
            else:
                rep.upper("%s: largest penetration [m]" % name, pen, tol)


CASES = {
    "augmentedLagrangian": augmentedLagrangian,
    "restingBlock": restingBlock,
    "inclinePenalty": inclinePenalty,
    "timeStep": timeStep,
    "fastBlock": fastBlock,
    "corners": corners,
    "stiffnessContrast": stiffnessContrast,
    "spinningBlock": spinningBlock,
    "marble": marble,
    "hertzPenalty": hertzPenalty,
}


def main(argv):
    global mc, BIN, PROJECT
    if len(argv) != 4 or argv[0] not in CASES:
        print(__doc__)
        print("Cases: " + " ".join(CASES))
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    name, project, binDir, work = argv
    sys.path.insert(0, str(Path(project)/"tutorials"/"verification"))
    import makeCases
    mc = makeCases
    BIN = Path(binDir).resolve()
    PROJECT = Path(project).resolve()
    work = Path(work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    rep = nf.report("stability " + name)
    start = time.time()
    CASES[name](work, rep)
    rep.info("run time [s]", time.time() - start)
    return rep.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
