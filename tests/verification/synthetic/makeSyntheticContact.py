#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Write nmmSolidFoam-like output of the contact verification cases
holding their closed form, to prove that their checkers pass on exact data
and fail on wrong data.

Usage:
    makeSyntheticContact.py <case> <outDir> [--tamper]

case: hertz | discOnDisc | brazilian | bondedTension | bondedShear
Writes <outDir>/VTK/contacts_<i>.vtp and contacts.vtp.series (points and
the point data contactState, bondIntact, normalForce, shearForce, normal),
and for brazilian, hertz and discOnDisc also the element frame
<name>_1.vtu (makeSynthetic.py's writer; for the Hertz cases the pressed
surface, slid inwards as Hertz's half-plane predicts, and the contacts at
its current positions). --tamper writes a wrong solution the checker must reject:
    hertz          contact pressure x 1.07
    discOnDisc     contact zone 15% wider, same load
    brazilian      stresses x 0.96
    bondedTension  bond breaks at 0.9 T L
    bondedShear    (sigma_n = 1 MPa) no drop to the residual after the peak

SPDX-License-Identifier: GPL-3.0-or-later
"""

import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))
import closedForms as cf  # noqa: E402
import makeSynthetic as ms  # noqa: E402


def writeContacts(path, x, state, intact, fn, fs, normal):
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk

    poly = vtkPolyData()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    x = np.asarray(x, float).reshape(-1, 2)
    pts.SetData(numpy_to_vtk(np.column_stack([x, np.zeros(len(x))]), deep=1))
    poly.SetPoints(pts)
    verts = vtkCellArray()
    for i in range(len(x)):
        verts.InsertNextCell(1)
        verts.InsertCellPoint(i)
    poly.SetVerts(verts)

    def add(name, arr):
        a = numpy_to_vtk(np.ascontiguousarray(arr), deep=1)
        a.SetName(name)
        poly.GetPointData().AddArray(a)
    n = len(x)
    add("contactState", np.asarray(state, np.int32).reshape(n))
    add("bondIntact", np.asarray(intact, np.int32).reshape(n))
    add("normalForce", np.asarray(fn, float).reshape(n))
    add("shearForce", np.asarray(fs, float).reshape(n))
    nrm = np.asarray(normal, float).reshape(n, 2)
    add("normal", np.column_stack([nrm, np.zeros(n)]))
    w = vtkXMLPolyDataWriter()
    w.SetFileName(str(path))
    w.SetInputData(poly)
    if w.Write() != 1:
        raise SystemExit("could not write %s" % path)


class contactWriter:
    def __init__(self, outDir):
        self.dir = Path(outDir).resolve()
        (self.dir/"VTK").mkdir(parents=True, exist_ok=True)
        self.files = []

    def frame(self, index, time, *fields):
        name = "contacts_%d.vtp" % index
        writeContacts(self.dir/"VTK"/name, *fields)
        self.files.append({"name": name, "time": time})

    def close(self):
        (self.dir/"VTK"/"contacts.vtp.series").write_text(json.dumps(
            {"file-series-version": "1.0", "files": self.files}, indent=2))


def tributary(x):
    t = np.empty(len(x))
    t[1:-1] = 0.5*(x[2:] - x[:-2])
    t[0] = 0.5*(x[1] - x[0])
    t[-1] = 0.5*(x[-1] - x[-2])
    return t


def inwardSlide(X, sol):
    """Tangential surface displacement of the pressed cylinder (half-plane,
    frictionless, plane strain): u_x = -(1 - 2 nu)(1 + nu)/(2 E) times the
    load carried over [-x, x]: the surface slides towards the symmetry
    line."""
    a = sol.halfWidth()
    z = np.minimum(np.abs(X)/a, 1.0)
    carried = sol.peakPressure()*a*(z*np.sqrt(1 - z*z) + np.arcsin(z))
    return -(1 - 2*sol.nu1)*(1 + sol.nu1)/(2*sol.E1)*carried


def hertzLike(out, sol, pScale=1.0, xScale=1.0):
    """Contacts at the upper body's surface points X (every 0.004, reference
    configuration) written at their current x = X + u_x, with the element
    frame of that surface: a ring of triangles between the arc and 0.95 R."""
    h = 0.004
    X = np.arange(0, 101)*h
    R = getattr(sol, "R1", sol.R)
    theta = np.arcsin(X/R)
    ring = lambda u, v: (v*np.sin(u), R - v*np.cos(u))  # noqa: E731
    P, cells = ms.gridMesh(theta, np.array([0.95*R, R]), ring)
    D = np.zeros_like(P)
    D[:, 0] = inwardSlide(P[:, 0], sol)
    Z = 0*P
    w = ms.writer(out)
    C = ms.centroids(P, cells)
    w.frame(1, 1.0, P, cells, D, Z, np.zeros((len(P), 6)), 0*C, 0*C,
            np.zeros((len(cells), 6)))
    w.close()
    p = sol.pressure(X/xScale)*pScale/xScale
    fn = p*tributary(X)*sol.thickness
    closed = X < sol.halfWidth()*xScale
    x = X + inwardSlide(X, sol)
    cw = contactWriter(out)
    n = len(X)
    cw.frame(1, 1.0, np.column_stack([x, 0*x]), closed.astype(int), 0*x,
             np.where(closed, fn, 0), 0*x, np.tile([0.0, -1.0], (n, 1)))
    cw.close()


def hertz(out, tamper):
    hertzLike(out, cf.hertz, pScale=1.07 if tamper else 1.0)


def discOnDisc(out, tamper):
    hertzLike(out, cf.discOnDisc, xScale=1.15 if tamper else 1.0)


def brazilian(out, tamper):
    b = cf.brazilian
    R = b.D/2
    n = 60
    X, cells = ms.gridMesh(np.linspace(0, R, n + 1), np.linspace(0, R, n + 1))
    C = ms.centroids(X, cells)
    keep = np.hypot(C[:, 0], C[:, 1]) < R
    cells = [c for c, k in zip(cells, keep) if k]
    C = C[keep]
    s = 0.96 if tamper else 1.0
    Sp = ms.sigma6(*b.stress(X[:, 0], np.minimum(X[:, 1], 0.999*R)), b.nu, False)*s
    Sc = ms.sigma6(*b.stress(C[:, 0], C[:, 1]), b.nu, False)*s
    Z = 0*X
    w = ms.writer(out)
    w.frame(1, 1.0, X, cells, Z, Z, Sp, 0*C, 0*C, Sc)
    w.close()
    cw = contactWriter(out)
    cw.frame(1, 1.0, [[0.0, R]], [1], [0], [b.P/2], [0.0], [[0.0, -1.0]])
    cw.close()


def bondedTension(out, tamper):
    b = cf.bondedInterface
    x = np.linspace(0, b.L, 51)
    trib = tributary(x)
    n = len(x)
    nrm = np.tile([0.0, 1.0], (n, 1))
    breakStep = 36 if tamper else b.stepsToPeak
    w = contactWriter(out)
    for k in range(1, b.stepsToPeak + 6):
        F = k*b.tensionPeak()/b.stepsToPeak
        if k < breakStep or (k == breakStep and not tamper):
            w.frame(k, float(k), np.column_stack([x, 0*x]), np.ones(n), np.ones(n),
                    -F*trib/b.L, 0*x, nrm)
        else:
            w.frame(k, float(k), np.column_stack([x, 0*x + 1e-3*(k - breakStep)]),
                    np.zeros(n), np.zeros(n), 0*x, 0*x, nrm)
    w.close()


def bondedShear(out, tamper, sigma=1e6):
    b = cf.bondedInterface
    x = np.linspace(0, b.L, 51)
    trib = tributary(x)
    n = len(x)
    peak, residual = b.shearPeak(sigma), b.shearResidual(sigma)
    w = contactWriter(out)
    for k in range(1, b.stepsToPeak + 6):
        S = min(k*peak/b.stepsToPeak, peak)
        intact = k <= b.stepsToPeak
        if not intact:
            S = peak if tamper else residual
        pts, st, bi, fn, fs, nrm = [], [], [], [], [], []
        for y, sign in ((0.0, 1.0), (0.2, -1.0)):
            pts.append(np.column_stack([x, 0*x + y]))
            st.append(np.full(n, 1 if intact else 2))
            bi.append(np.full(n, 1 if intact else 0))
            fn.append(sigma*trib)
            fs.append(sign*S*trib/b.L)
            nrm.append(np.tile([0.0, sign], (n, 1)))
        w.frame(k, float(k), np.vstack(pts), np.concatenate(st), np.concatenate(bi),
                np.concatenate(fn), np.concatenate(fs), np.vstack(nrm))
    w.close()


CASES = {"hertz": hertz, "discOnDisc": discOnDisc, "brazilian": brazilian,
         "bondedTension": bondedTension, "bondedShear": bondedShear}


def main(argv):
    if len(argv) < 2 or argv[0] not in CASES:
        print(__doc__)
        return 1
    CASES[argv[0]](argv[1], "--tamper" in argv[2:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
