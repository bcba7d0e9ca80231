#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Write nmmSolidFoam-like output holding the exact solution of a
verification case, to prove that its checker passes on exact data and
fails on wrong data.

Usage:
    makeSynthetic.py <case> <outDir> [--tamper] [--level k]

case: cantilever | plateHole | lame | sneddon | freeFall | waveBar |
      incline (phi 20) | inclineStatic (phi 31) | toppleStable |
      toppleSliding | toppleToppling | toppleSlip | bouncingBlock |
      bouncingBlockDDA | pushedBlock | stickSlip
Writes <outDir>/VTK/<name>_<index>.vtu and <outDir>/VTK/<name>.vtu.series
(name = the folder name of outDir) in the solver's layout: polygons in the
deformed position, point and cell data D, U (3 components), sigma (6: xx yy
zz xy yz xz), blockId, materialId. Fields are the closed forms of
closedForms.py at the points (point data) and at the element centroids
(cell data) of a simple structured triangle mesh of the body.

--tamper writes a wrong solution the checker must reject:
    cantilever  displacements x 1.05         plateHole  stresses x 0.95
    lame        displacements, stresses x 1.03
    sneddon     crack opening x 0.97          freeFall   one point off by 1e-8
    waveBar     c x 0.95
    incline     slider displacement x 1.02
    inclineStatic  slider creeping 0.02 m in 1 s
    toppleStable   the block turning by 0.005 rad (within the allowed
                   penetration)
    toppleSliding  the sliding block turning by 0.005 rad
    toppleToppling rotation x 1.05
    toppleSlip     the pivot slipping by a tenth of the top corner's
                   displacement
    bouncingBlock  restitution 0.97 instead of 1
    bouncingBlockDDA  restitution 1.02 (an energy gain) instead of 0.8
    pushedBlock    the bond breaks at F = 0.60 instead of 0.6774
    stickSlip      (postProcessing/ rows only, no VTK) the second slip
                   ends 3 deltaT late, carrying the block 2.5% further
--level k (cantilever only) writes refinement level k, for the rates.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import json
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import closedForms as cf  # noqa: E402


def gridMesh(xs, ys, mapping=None):
    """Points and triangles of the tensor grid xs x ys, mapped by
    mapping(u, v) -> (x, y) when given."""
    U, V = np.meshgrid(xs, ys, indexing="ij")
    u, v = U.ravel(), V.ravel()
    if mapping is not None:
        x, y = mapping(u, v)
    else:
        x, y = u, v
    ny = len(ys)
    tris = []
    for i in range(len(xs) - 1):
        for j in range(ny - 1):
            p0 = i*ny + j
            p1 = (i + 1)*ny + j
            p2 = (i + 1)*ny + j + 1
            p3 = i*ny + j + 1
            tris.append([p0, p1, p2])
            tris.append([p0, p2, p3])
    return np.column_stack([x, y]), tris


def centroids(X, cells):
    return np.array([X[c].mean(axis=0) for c in cells])


def sigma6(sxx, syy, sxy, nu, planeStress):
    szz = 0*sxx if planeStress else nu*(sxx + syy)
    z = 0*sxx
    return np.column_stack([sxx, syy, szz, sxy, z, z])


def writeFrame(path, X, cells, D, U, Sp, Dc, Uc, Sc, blockId=None):
    from vtkmodules.vtkCommonCore import vtkPoints, vtkIdList
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid, VTK_POLYGON
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk

    grid = vtkUnstructuredGrid()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    x = X + D
    pts.SetData(numpy_to_vtk(np.column_stack([x, np.zeros(len(x))]), deep=1))
    grid.SetPoints(pts)
    for c in cells:
        ids = vtkIdList()
        for i in c:
            ids.InsertNextId(int(i))
        grid.InsertNextCell(VTK_POLYGON, ids)

    def add(data, name, arr):
        a = numpy_to_vtk(np.ascontiguousarray(arr), deep=1)
        a.SetName(name)
        data.AddArray(a)

    def vec3(v):
        return np.column_stack([v, np.zeros(len(v))])
    pd = grid.GetPointData()
    add(pd, "D", vec3(D))
    add(pd, "U", vec3(U))
    add(pd, "sigma", Sp)
    cd = grid.GetCellData()
    add(cd, "D", vec3(Dc))
    add(cd, "U", vec3(Uc))
    add(cd, "sigma", Sc)
    add(cd, "blockId", np.zeros(len(cells), dtype=np.int32) if blockId is None
        else np.asarray(blockId, dtype=np.int32))
    add(cd, "materialId", np.zeros(len(cells), dtype=np.int32))
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(str(path))
    w.SetInputData(grid)
    if w.Write() != 1:
        raise SystemExit("could not write %s" % path)


class writer:
    def __init__(self, outDir):
        self.dir = Path(outDir).resolve()
        self.name = self.dir.name
        (self.dir/"VTK").mkdir(parents=True, exist_ok=True)
        self.files = []

    def frame(self, index, time, X, cells, D, U, Sp, Dc, Uc, Sc, blockId=None):
        fname = "%s_%d.vtu" % (self.name, index)
        writeFrame(self.dir/"VTK"/fname, X, cells, D, U, Sp, Dc, Uc, Sc, blockId)
        self.files.append({"name": fname, "time": time})

    def close(self):
        (self.dir/"VTK"/(self.name + ".vtu.series")).write_text(json.dumps(
            {"file-series-version": "1.0", "files": self.files}, indent=2))


def staticCase(out, X, cells, sol, dScale=1.0, sScale=1.0):
    C = centroids(X, cells)
    D = np.column_stack(sol.displacement(X[:, 0], X[:, 1]))*dScale
    Dc = np.column_stack(sol.displacement(C[:, 0], C[:, 1]))*dScale
    Sp = sigma6(*sol.stress(X[:, 0], X[:, 1]), sol.nu, sol.planeStress)*sScale
    Sc = sigma6(*sol.stress(C[:, 0], C[:, 1]), sol.nu, sol.planeStress)*sScale
    w = writer(out)
    w.frame(1, 1.0, X, cells, D, 0*D, Sp, Dc, 0*Dc, Sc)
    w.close()


def cantilever(out, tamper, level=None):
    """level k (--level k): 12 x 2^k elements across the depth, and a
    tampering of relative size 5e-3 x 2^-k that spoils the L2 rate (1
    instead of 2) but not the tip deflection."""
    b = cf.cantilever
    n = 12*2**(level or 0)
    X, cells = gridMesh(np.linspace(0, b.L, 4*n + 1), np.linspace(-b.D/2, b.D/2, n + 1))
    if level is None:
        scale = 1.05 if tamper else 1.0
    else:
        scale = 1 + (5e-3*2.0**-level if tamper else 0.0)
    staticCase(out, X, cells, b, dScale=scale)


def plateHole(out, tamper):
    """The tutorial's structured triangles (h = 0.05) with the hole cut out
    crudely: triangles whose centroid is in the hole dropped, vertices in
    the hole moved onto it radially (small, distorted elements next to
    the hole, as the cover cut by the boundary gives)."""
    k = cf.kirsch
    n = 100
    X, cells = gridMesh(np.linspace(0, k.side, n + 1), np.linspace(0, k.side, n + 1))
    C = centroids(X, cells)
    cells = [c for c, cc in zip(cells, C) if np.hypot(*cc) > k.a]
    r = np.hypot(X[:, 0], X[:, 1])
    inside = (r < k.a) & (r > 0)
    X[inside] *= (k.a/r[inside])[:, None]
    used = np.unique(np.concatenate(cells))
    renumber = -np.ones(len(X), dtype=int)
    renumber[used] = np.arange(len(used))
    X = X[used]
    cells = [list(renumber[c]) for c in cells]
    s = 0.95 if tamper else 1.0
    staticCase(out, X, cells, k, dScale=s, sScale=s)


def lame(out, tamper):
    c = cf.lame

    def mapping(r, t):
        return r*np.cos(t), r*np.sin(t)
    X, cells = gridMesh(np.linspace(c.a, c.b, 21), np.linspace(0, np.pi/2, 61), mapping)
    s = 1.03 if tamper else 1.0
    staticCase(out, X, cells, c, dScale=s, sScale=s)


def sneddon(out, tamper, angleDeg=30.0):
    c = cf.sneddon
    h = 0.05
    n = int(round(c.side/h))
    xs = np.linspace(-c.side/2, c.side/2, n + 1)
    Xl, cells = gridMesh(xs, xs)
    # duplicate the points strictly inside the crack (local y = 0): the
    # elements below it use the copies
    ny = n + 1
    jc = n//2
    inside = [i*ny + jc for i in range(n + 1) if abs(xs[i]) < c.a*(1 - 1e-9)]
    copy = {p: len(Xl) + k for k, p in enumerate(inside)}
    Xl = np.vstack([Xl, Xl[inside]])
    newCells = []
    for tri in cells:
        below = Xl[tri][:, 1].mean() < 0
        newCells.append([copy[p] if below and p in copy else p for p in tri])
    a = math.radians(angleDeg)
    Rm = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    X = Xl @ Rm.T
    nrm = Rm @ np.array([0.0, 1.0])
    scale = 0.97 if tamper else 1.0
    half = np.zeros(len(X))
    for p in inside:
        w = scale*float(c.opening(Xl[p, 0]))
        half[p] = 0.5*w
        half[copy[p]] = -0.5*w
    D = np.outer(half, nrm)
    C = centroids(X, newCells)
    z6 = np.zeros((len(X), 6))
    w = writer(out)
    w.frame(1, 1.0, X, newCells, D, 0*D, z6, np.zeros((len(C), 2)),
            np.zeros((len(C), 2)), np.zeros((len(C), 6)))
    w.close()


def freeFall(out, tamper):
    c = cf.freeFall
    X, cells = gridMesh(np.linspace(0, 1, 5), np.linspace(0, 1, 5))
    w = writer(out)
    z6 = np.zeros((len(X), 6))
    zc6 = np.zeros((len(cells), 6))
    for i in range(c.nSteps + 1):
        t = i*c.deltaT
        D = np.column_stack([0*X[:, 0], 0*X[:, 0] + c.displacementY(t)])
        U = np.column_stack([0*X[:, 0], 0*X[:, 0] + c.velocityY(t)])
        if tamper and i == 7:
            D[3, 1] *= 1 + 1e-8
        w.frame(i, t, X, cells, D, U, z6, np.tile(D[0], (len(cells), 1)),
                np.tile(U[0], (len(cells), 1)), zc6)
    w.close()


def waveBar(out, tamper):
    c = cf.waveBar
    X, cells = gridMesh(np.linspace(0, c.L, 101), np.linspace(0, c.H, 6))
    speed = c.c()*(0.95 if tamper else 1.0)
    C = centroids(X, cells)
    w = writer(out)
    nSteps = int(round(c.endTime/c.deltaT))
    for i in range(nSteps + 1):
        t = i*c.deltaT

        def fields(x):
            # reflection from the fixed end x = L ignored (after the window)
            d = c.p0/c.E*np.maximum(speed*t - x, 0.0)
            u = np.where(speed*t > x, c.p0*speed/c.E, 0.0)
            s = np.where(speed*t > x, -c.p0, 0.0)
            return (np.column_stack([d, 0*d]), np.column_stack([u, 0*u]),
                    sigma6(s, 0*s, 0*s, 0.0, True))
        D, U, S = fields(X[:, 0])
        Dc, Uc, Sc = fields(C[:, 0])
        w.frame(i, t, X, cells, D, U, S, Dc, Uc, Sc)
    w.close()


def twoBlocks(lower, upper, n=4):
    """Points and triangles of two rectangles ((x0, y0), (x1, y1)), the
    points of each block its own, and the blockId of each triangle."""
    X = []
    cells = []
    ids = []
    for b, ((x0, y0), (x1, y1)) in enumerate((lower, upper)):
        Xb, cb = gridMesh(np.linspace(x0, x1, n + 1), np.linspace(y0, y1, n + 1))
        off = sum(len(x) for x in X)
        X.append(Xb)
        cells += [[p + off for p in c] for c in cb]
        ids += [b]*len(cb)
    return np.vstack(X), cells, np.array(ids)


def rigidMotion(out, X, cells, ids, times, upperD, upperU=None):
    """Frames where block 0 stays put and block 1 moves rigidly by
    upperD(t) (a 2-vector), with velocity upperU(t)."""
    w = writer(out)
    z6 = np.zeros((len(X), 6))
    zc6 = np.zeros((len(cells), 6))
    pointBlock = np.zeros(len(X), dtype=int)
    for c, b in zip(cells, ids):
        pointBlock[c] = b
    for i, t in enumerate(times):
        d = np.asarray(upperD(t), dtype=float)
        u = np.asarray(upperU(t) if upperU else (0.0, 0.0), dtype=float)
        D = np.where(pointBlock[:, None] == 1, d, 0.0)*np.ones((len(X), 2))
        U = np.where(pointBlock[:, None] == 1, u, 0.0)*np.ones((len(X), 2))
        Dc = np.where(ids[:, None] == 1, d, 0.0)*np.ones((len(cells), 2))
        Uc = np.where(ids[:, None] == 1, u, 0.0)*np.ones((len(cells), 2))
        w.frame(i, t, X, cells, D, U, z6, Dc, Uc, zc6, blockId=ids)
    w.close()


def incline(out, tamper, phi=20.0):
    """The tutorial's blocks (base 4 x 0.5, slider 1 x 1); the slider moves
    by the closed form d(t) (x 1.02 when tampered)."""
    c = cf.incline
    X, cells, ids = twoBlocks(((0, -0.5), (4, 0)), ((0.25, 0), (1.25, 1)))
    s = 1.02 if tamper else 1.0
    times = [0.1*i + 1e-3*(i == 10) for i in range(11)]
    rigidMotion(out, X, cells, ids, times,
                lambda t: (s*c.displacement(phi, t), 0.0))


def inclineStatic(out, tamper):
    """phi = 31: the slider sticks; tampered, it creeps by 0.02 m (twice
    the allowed penetration) by t = 1."""
    c = cf.incline
    X, cells, ids = twoBlocks(((0, -0.5), (4, 0)), ((0.25, 0), (1.25, 1)))
    times = [0.1*i for i in range(11)]
    rigidMotion(out, X, cells, ids, times,
                lambda t: ((0.02*t if tamper else 1e-4*t), -1e-6))


def toppleFrames(out, regime, theta, shift):
    """The topple tutorial's blocks (base 4 x 0.5, block b x h at x0);
    the block turns clockwise by theta(t) about its downhill bottom corner
    and moves by shift(t) (2-vectors), the base stays put."""
    c = cf.topple
    b, h, _ = c.regimes[regime]
    X, cells, ids = twoBlocks(((0, -0.5), (4, 0)), ((c.x0, 0), (c.x0 + b, h)))
    C = centroids(X, cells)
    pointBlock = np.zeros(len(X), dtype=int)
    for cell, k in zip(cells, ids):
        pointBlock[cell] = k
    pivot = np.array([c.x0 + b, 0.0])

    def motion(P, t):
        q = -theta(t)
        R = np.array([[math.cos(q), -math.sin(q)], [math.sin(q), math.cos(q)]])
        return (P - pivot) @ R.T + pivot - P + np.asarray(shift(t), dtype=float)
    times = ([0.01*i for i in range(16)] if regime == "toppling"
             else [0.1*i for i in range(11)])
    w = writer(out)
    for i, t in enumerate(times):
        D = np.where(pointBlock[:, None] == 1, motion(X, t), 0.0)
        Dc = np.where(ids[:, None] == 1, motion(C, t), 0.0)
        w.frame(i, t, X, cells, D, 0*D, np.zeros((len(X), 6)), Dc, 0*Dc,
                np.zeros((len(cells), 6)), blockId=ids)
    w.close()


def toppleStable(out, tamper):
    """Stable: a creep of 1e-4 m in 1 s; tampered, the block also turns by
    0.005 rad about its downhill corner (its points stay within the
    allowed penetration: only the rotation check can see it)."""
    toppleFrames(out, "stable", lambda t: 0.005*t if tamper else 0.0,
                 lambda t: (1e-4*t, -1e-6))


def toppleSliding(out, tamper):
    """Sliding: d(t) exactly; tampered, it also turns by 0.005 rad."""
    c = cf.topple
    toppleFrames(out, "sliding", lambda t: 0.005*t if tamper else 0.0,
                 lambda t: (c.displacement("sliding", t), 0.0))


def toppleToppling(out, tamper):
    """Toppling: theta(t) about the pivot (x 1.05 when tampered)."""
    c = cf.topple
    s = 1.05 if tamper else 1.0
    toppleFrames(out, "toppling", lambda t: s*c.rotation("toppling", t),
                 lambda t: (0.0, 0.0))


def toppleSlip(out, tamper):
    """Toppling: theta(t) about the pivot; tampered, the pivot also slips
    downhill by a tenth of the top corner's x displacement."""
    c = cf.topple
    h = c.regimes["toppling"][1]
    toppleFrames(out, "toppling", lambda t: c.rotation("toppling", t),
                 lambda t: ((0.1*h*math.sin(c.rotation("toppling", t)) if tamper else 0.0),
                            0.0))


def bouncingBlockDY(t, e, omega=150.0):
    """Height change of a block dropped from h0 that hits a linear spring
    (omega) and leaves it with e times its impact speed: free flight, then
    half a sine under the base, then flight again."""
    c = cf.bouncingBlock
    t0 = 0.0            # start of the current flight
    y0 = 0.0            # D_y at its start
    v0 = 0.0            # velocity at its start
    while True:
        # flight: y = y0 + v0 s - g s^2/2 until y = -h0 (falling)
        disc = v0*v0 + 2*c.g*(y0 + c.h0)
        s1 = (v0 + np.sqrt(disc))/c.g
        if t <= t0 + s1:
            s = t - t0
            return y0 + v0*s - 0.5*c.g*s*s
        v = np.sqrt(disc)
        tc = t0 + s1
        if t <= tc + np.pi/omega:
            return -c.h0 - v/omega*np.sin(omega*(t - tc))
        t0, y0, v0 = tc + np.pi/omega, -c.h0, e*v


def bouncingBlock(out, tamper, e=1.0):
    """The tutorial's blocks (base 2 x 0.5, block 1 x 1 at h0 = 1 above it):
    an elastic bounce (restitution 1), or 0.97 when tampered."""
    X, cells, ids = twoBlocks(((-0.5, -0.5), (1.5, 0)), ((0, 1), (1, 2)))
    ee = 0.97 if tamper else e
    times = [0.005*i for i in range(381)]
    rigidMotion(out, X, cells, ids, times, lambda t: (0.0, bouncingBlockDY(t, ee)))


def bouncingBlockDDA(out, tamper):
    """Damped bounces (restitution 0.8), or a rebound above the drop height
    (1.02) when tampered."""
    X, cells, ids = twoBlocks(((-0.5, -0.5), (1.5, 0)), ((0, 1), (1, 2)))
    times = [0.005*i for i in range(381)]
    e = 1.02 if tamper else 0.8
    rigidMotion(out, X, cells, ids, times, lambda t: (0.0, bouncingBlockDY(t, e)))


def writeContacts(path, points, state):
    """A contacts_<i>.vtp as the solver writes it (points, contactState)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    poly = vtkPolyData()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    pts.SetData(numpy_to_vtk(np.column_stack([points, np.zeros(len(points))]), deep=1))
    poly.SetPoints(pts)
    a = numpy_to_vtk(np.asarray(state, dtype=np.int32), deep=1)
    a.SetName("contactState")
    poly.GetPointData().AddArray(a)
    w = vtkXMLPolyDataWriter()
    w.SetFileName(str(path))
    w.SetInputData(poly)
    if w.Write() != 1:
        raise SystemExit("could not write %s" % path)


def pushedBlock(out, tamper):
    """Five contacts on the interface, bonded until the closed-form onset
    (F = 0.6774, rounded up to the next step), sliding after it, the block
    moving by the closed form; tampered, the bond breaks at F = 0.60."""
    c = cf.pushedBlock
    X, cells, ids = twoBlocks(((-0.5, -0.5), (2.5, 0)), ((0, 0), (1, 1)))
    t0 = 0.60 if tamper else c.onsetTime()
    times = [c.deltaT*i for i in range(101)]
    rigidMotion(out, X, cells, ids, times,
                lambda t: (c.displacement(t, t0), 0.0))
    cp = np.column_stack([np.linspace(0, 1, 5), np.zeros(5)])
    for i, t in enumerate(times):
        state = 2 if t >= t0 else 1
        writeContacts(Path(out)/"VTK"/("contacts_%d.vtp" % i), cp, [state]*5)


def stickSlip(out, tamper):
    """The rows of the case's function objects (motion, contacts) for
    every step of the closed form: a contact of five sliding in the steps
    of the slips, the block's centre at x0 + x(t); tampered, the second
    slip lasts 3 deltaT longer and its plateaus are 2.5% further."""
    c = cf.stickSlip
    dt = c.deltaT
    windows = c.windows()
    late = 3*dt if tamper else 0.0
    ends = [b + (late if k == 1 else 0.0) for k, (_, b, _, _) in enumerate(windows)]
    n = int(round(c.endTime/dt))
    motion = ["# time block:x block:y block:rotation block:Ux block:Uy"]
    contacts = ["# time deltaT open bonded sliding bondsBroken maxPenetration"
                " iterations cuts"]
    for i in range(n + 1):
        t = i*dt
        x = c.position(t, windows)*(1.025 if tamper and t > windows[1][0] else 1.0)
        motion.append("%.12g %.12g 0.5 0 0 0" % (t, 0.5 + x))
        if i == 0:
            continue
        middle = t - 0.5*dt
        sliding = any(w[0] <= middle <= e for w, e in zip(windows, ends))
        contacts.append("%.12g %.12g 0 %d %d 0 1e-9 1 0"
                        % (t, dt, 0 if sliding else 5, 5 if sliding else 0))
    for name, rows in (("motion", motion), ("contacts", contacts)):
        path = Path(out)/"postProcessing"/name/"0"/(name + ".dat")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("\n".join(rows) + "\n")


CASES = {"cantilever": cantilever, "plateHole": plateHole, "lame": lame,
         "sneddon": sneddon, "freeFall": freeFall, "waveBar": waveBar,
         "incline": incline, "inclineStatic": inclineStatic,
         "toppleStable": toppleStable, "toppleSliding": toppleSliding,
         "toppleToppling": toppleToppling, "toppleSlip": toppleSlip,
         "bouncingBlock": bouncingBlock, "bouncingBlockDDA": bouncingBlockDDA,
         "pushedBlock": pushedBlock, "stickSlip": stickSlip}


def main(argv):
    if len(argv) < 2 or argv[0] not in CASES:
        print(__doc__)
        return 1
    kw = {}
    if "--level" in argv[2:]:
        if argv[0] != "cantilever":
            raise SystemExit("--level: cantilever only")
        kw["level"] = int(argv[argv.index("--level") + 1])
    CASES[argv[0]](argv[1], "--tamper" in argv[2:], **kw)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
