#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/{hertz,discOnDisc} against Hertz.

Usage:
    checkHertz.py <caseDir> hertz|discOnDisc

Half models (x >= 0) of a cylinder pressed by P per unit thickness on a
stiff flat, or on an identical cylinder: closedForms.hertz/discOnDisc give
a = sqrt(4 P R/(pi E*)) and p0 = 2P/(pi a) (a = 0.1076, p0 = 0.0591 for
both). On the last contact frame (VTK/contacts_<i>.vtp):
  - the contact pressure of each contact point is its normalForce over its
    tributary length x thickness, the tributary length being half the
    distance between its neighbouring contact points (open ones included;
    x = 0 is the symmetry line: half the distance to the first neighbour).
    Points closer than 1e-9 R are one point (their forces add). Only
    contacts whose normal is within 25 deg of y count (the symmetry line
    also holds contacts between the rollered edges, normals along x). The
    contact forces are the contact model's own output; the elements'
    stresses near the surface would need an extrapolation to it;
  - p0: the point pressures scatter (the contacts of the two bodies'
    vertices interleave, a few nearly coincide), so p0 comes from the
    force carried up to x, F(x) = sum of the point forces up to x, fitted
    by the integral of p0 sqrt(1 - s^2/a^2) over [0, x] (p0 and a free,
    over x < 1.5 a); within 5%. The fit of p^2 = p0^2 (1 - x^2/a^2) to the
    point pressures (x < 0.9 a) is printed;
  - a: the largest x of a closed contact carrying a positive normal force,
    within one edge length of the closed form; the edge length is the
    longest edge of the upper body's surface on [0, 1.5 a]. The contact
    zone ends on an edge of each body, and a straight edge between a closed
    vertex and an open one is open along its length: the other body's
    vertices between them (the contacts interleave) do not resolve the end
    more finely. The fit of F(x) gives a too, within 5% like p0;
  - equilibrium: the vertical contact forces add up to P/2 within 1%.
Hertz's theory is geometrically linear: x is a position in the reference
configuration. The contact output is in the current one, and pressing
slides the cylinder's surface towards the symmetry line by up to
(1 - 2 nu)(1 + nu) P/(2 E) (0.0026, 2.4% of a, for a half-plane), so each
contact point is mapped back to the upper body's reference x through the
displacement of that body's surface (its boundary points on the circle,
from the element frame of the same write time).
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL_P0 = 0.05
TOL_EQUILIBRIUM = 0.01


def contactPressure(c, R, thickness):
    """Sorted x, pressure, normal force, closed flag of the contact points."""
    # Only contacts across the contact surface (normal within 25 deg of y):
    # the symmetry line x = 0 also holds contacts between the two blocks'
    # rollered edges, with normals along x, which carry no vertical load
    onSurface = np.abs(c.data["normal"][:, 1]) > 0.9
    x = np.abs(c.x[onSurface, 0])
    fn = c.data["normalForce"][onSurface].copy()
    closed = c.data["contactState"][onSurface] != 0
    fn[~closed] = 0
    o = np.argsort(x)
    x, fn, closed = x[o], fn[o], closed[o]
    # merge coincident points
    xs, fs, cs = [], [], []
    for xi, fi, ci in zip(x, fn, closed):
        if xs and xi - xs[-1] <= 1e-9*R:
            fs[-1] += fi
            cs[-1] = cs[-1] or ci
        else:
            xs.append(xi)
            fs.append(fi)
            cs.append(ci)
    x, fn, closed = np.array(xs), np.array(fs), np.array(cs)
    if len(x) < 3:
        raise SystemExit("%s: %d contact points" % (c.path, len(x)))
    trib = np.empty(len(x))
    trib[1:-1] = 0.5*(x[2:] - x[:-2])
    trib[-1] = 0.5*(x[-1] - x[-2])
    trib[0] = 0.5*(x[1] - x[0]) + (x[0] if x[0] > 1e-9*R else 0.0)
    return x, fn/(trib*thickness), fn, closed


def thicknessInverse(sol):
    return 1/sol.thickness


def upperSurface(vtu, sol):
    """Current and reference x of the upper body's surface points (those
    on the circle of radius R1 about (0, R1), below its centre), sorted."""
    f = nf.readFrame(vtu)
    Ru = getattr(sol, "R1", sol.R)
    onCircle = (np.abs(np.hypot(f.X[:, 0], f.X[:, 1] - Ru) - Ru) < 1e-9*Ru) \
        & (f.X[:, 1] < 0.5*Ru) & (f.X[:, 0] >= 0)
    if onCircle.sum() < 2:
        raise SystemExit("%s: %d points on the upper body's surface"
                         % (vtu, onCircle.sum()))
    x, X = f.x[onCircle, 0], f.X[onCircle, 0]
    o = np.argsort(x)
    return x[o], X[o]


def lastFrame(caseDir):
    """The last element frame and the contact frame of the same write."""
    vtu = nf.readSeries(caseDir)[-1][1]
    return vtu, nf.contactsFile(vtu)


def measure(caseDir, sol):
    vtu, path = lastFrame(caseDir)
    if not path.is_file():
        raise SystemExit("%s: no contact frame %s" % (vtu, path))
    c = nf.readContacts(path)
    if len(c.x) == 0:
        raise SystemExit("%s: no contacts" % path)
    xNow, xRef = upperSurface(vtu, sol)
    c.x[:, 0] = np.interp(np.abs(c.x[:, 0]), xNow, xRef)
    x, p, fn, closed = contactPressure(c, sol.R, sol.thickness)
    a = sol.halfWidth()
    m = closed & (x < 0.9*a) & (fn > 0)
    if m.sum() < 3:
        raise SystemExit("%s: %d closed contact points within 0.9 a" % (path, m.sum()))
    A, B = np.polyfit(x[m]**2, p[m]**2, 1)[::-1]
    p0Points = float(np.sqrt(max(A, 0.0)))
    # The force carried up to x, F(x) = sum of the point forces at x_i <= x,
    # taken half-way to the next point, against the integral of
    # p0 sqrt(1 - s^2/a^2): (p0 a/2)(z sqrt(1 - z^2) + asin z), z = min(x/a, 1);
    # linear in p0 for a given a: a scanned, p0 by least squares
    F = np.cumsum(fn)*thicknessInverse(sol)
    xm = np.append(0.5*(x[1:] + x[:-1]), x[-1])
    use = xm <= 1.5*a

    def fit(aTry):
        z = np.minimum(xm[use]/aTry, 1.0)
        g = 0.5*aTry*(z*np.sqrt(1 - z*z) + np.arcsin(z))
        pTry = float(g @ F[use]/(g @ g))
        return float(((pTry*g - F[use])**2).sum()), aTry, pTry
    # a coarse scan, then a fine one around its best (steps of 1e-6 a)
    best = min(fit(aTry) for aTry in np.linspace(0.5*a, 1.5*a, 2001))
    best = min(fit(aTry) for aTry in best[1] + np.linspace(-5e-4, 5e-4, 1001)*a)
    _, aFit, p0 = best
    carrying = closed & (fn > 0)
    aMeasured = float(x[carrying].max())
    near = xRef <= 1.5*a
    edge = float(np.diff(xRef[near]).max()) if near.sum() > 1 else float("nan")
    ny = np.abs(c.data["normal"][:, 1]) if "normal" in c.data else 1.0
    fnAll = np.where(c.data["contactState"] != 0, c.data["normalForce"], 0.0)
    total = float((fnAll*ny).sum())
    return {"p0": p0, "a": aMeasured, "edge": edge, "total": total,
            "aFit": aFit, "p0Points": p0Points,
            "nClosed": int(carrying.sum()), "pFirst": float(p[0])}


def errors(caseDir, which="hertz"):
    sol = getattr(cf, which)
    r = measure(caseDir, sol)
    return {"h": r["edge"], "p0Error": abs(r["p0"] - sol.peakPressure())/sol.peakPressure(),
            "aError": abs(r["a"] - sol.halfWidth())/sol.halfWidth(),
            "aFitError": abs(r["aFit"] - sol.halfWidth())/sol.halfWidth()}


def main(argv):
    if len(argv) != 2 or argv[1] not in ("hertz", "discOnDisc"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "-help", "--help") else 1
    sol = getattr(cf, argv[1])
    r = measure(argv[0], sol)
    rep = nf.report("%s: a = %.4g, p0 = %.4g (edge length %.3g)"
                    % (argv[1], sol.halfWidth(), sol.peakPressure(), r["edge"]))
    rep.info("closed contact points carrying load", float(r["nClosed"]))
    rep.relative("p0 (fit of the carried force F(x))", r["p0"], sol.peakPressure(), TOL_P0)
    rep.info("p0 (fit of p^2 over x < 0.9 a, point pressures)", r["p0Points"],
             sol.peakPressure())
    rep.absolute("a (outermost loaded contact)", r["a"], sol.halfWidth(), r["edge"])
    rep.relative("a (fit of the carried force F(x))", r["aFit"], sol.halfWidth(), TOL_P0)
    rep.info("p at the symmetry line", r["pFirst"], sol.peakPressure())
    rep.relative("sum of vertical contact forces = P/2", r["total"], sol.P/2,
                 TOL_EQUILIBRIUM)
    return rep.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
