# Needs Debian's /usr/bin/python3 (python3-vtk9 and python3-numpy).
"""The frames an nmmSolidFoam run writes (read by bin/tools/nmmVtk.py), for
the verification checks.

    series = readSeries(caseDir)        # [(time, path), ...] time order
    f = readFrame(path)                 # a frame: numpy arrays
    c = readContacts(path)              # its contacts: numpy arrays

A frame holds the deformed points x, the point data D, U, sigma, the
polygons (lists of point indices) and the cell data. Undeformed positions
are X = x - D (the solver writes points in the deformed position).

Also: a table printer, a linear-field-per-polygon L2 norm, and least
squares extrapolation of element (cell) values to a boundary.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np


# The reading itself is bin/tools/nmmVtk.py's, shared with nmmPlot and the
# tutorials' summaries
sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
from nmmVtk import contactsFile, readContacts, readContactSeries  # noqa: E402,F401
from nmmVtk import readSeries, seriesFile  # noqa: E402,F401
import nmmVtk  # noqa: E402


def readFrame(path):
    """nmmVtk's frame with the displacement: D, U (None when not written),
    the undeformed points X = x - D and the cells' undeformed centroids and
    areas."""
    f = nmmVtk.readFrame(path)
    for name in ("D",):
        if name not in f.pointData:
            raise SystemExit("%s: no point data '%s'" % (path, name))
    f.D = f.pointData["D"][:, :2]
    f.X = f.x - f.D
    f.U = f.pointData["U"][:, :2] if "U" in f.pointData else None
    f.cellCentroid, f.cellArea = polygonCentroids(f.X, f.cells)
    return f


def contactsOfFrame(vtu):
    """The point data of the contacts file of a frame (VTK/contacts_<index>
    .vtp next to <case>_<index>.vtu) as {name: numpy array} (readContacts);
    None if the frame has no contacts file."""
    path = contactsFile(vtu)
    return readContacts(path).data if path.is_file() else None


def polygonCentroids(X, cells):
    """Area centroids and areas of the polygons (undeformed)."""
    cen = np.zeros((len(cells), 2))
    area = np.zeros(len(cells))
    for k, c in enumerate(cells):
        p = X[c]
        q = np.roll(p, -1, axis=0)
        cr = p[:, 0]*q[:, 1] - q[:, 0]*p[:, 1]
        A = 0.5*cr.sum()
        if abs(A) < 1e-300:
            cen[k] = p.mean(axis=0)
        else:
            cen[k, 0] = ((p[:, 0] + q[:, 0])*cr).sum()/(6*A)
            cen[k, 1] = ((p[:, 1] + q[:, 1])*cr).sum()/(6*A)
        area[k] = abs(A)
    return cen, area


def cellSize(f):
    """Typical element edge length: sqrt(2 x median area) (right triangles
    of the structured cover have area h^2/2)."""
    return float(np.sqrt(2*np.median(f.cellArea[f.cellArea > 0])))


def cellStress(f):
    """Cell sxx, syy, sxy from the 6-component 'sigma' (xx yy zz xy yz xz)."""
    if "sigma" not in f.cellData:
        raise SystemExit("%s: no cell data 'sigma'" % f.path)
    s = f.cellData["sigma"]
    return s[:, 0], s[:, 1], s[:, 3]


# Triangle quadrature, degree 2 (three edge midpoints... interior points)
_qp = np.array([[1/6, 1/6], [2/3, 1/6], [1/6, 2/3]])
_qw = np.array([1/3, 1/3, 1/3])


def l2Error(f, exactDisplacement):
    """Relative L2 norm of D - exact over the undeformed body. In each
    polygon the displacement is the linear field through its vertex values
    (least squares: exact for the linear manifold elements); each polygon
    is split into triangles from its centroid, three-point rule on each."""
    errSq = 0.0
    refSq = 0.0
    for k, c in enumerate(f.cells):
        xc = f.cellCentroid[k]
        M = np.column_stack([np.ones(len(c)), f.X[c] - xc])
        coef, *_ = np.linalg.lstsq(M, f.D[c], rcond=None)
        q, w = _subTriangles(f, k)
        if len(w) == 0:
            continue
        uh = coef[0] + np.outer(q[:, 0] - xc[0], coef[1]) \
            + np.outer(q[:, 1] - xc[1], coef[2])
        ue = np.column_stack(exactDisplacement(q[:, 0], q[:, 1]))
        errSq += (w*((uh - ue)**2).sum(axis=1)).sum()
        refSq += (w*(ue**2).sum(axis=1)).sum()
    return float(np.sqrt(errSq/refSq))


def _subTriangles(f, k):
    """Quadrature points and weights of polygon k: triangles from the
    centroid, three-point rule on each."""
    c = f.cells[k]
    P = f.X[c]
    xc = f.cellCentroid[k]
    pts = []
    wts = []
    n = len(c)
    # signed areas: the fan is exact for non-convex polygons too (elements
    # cut by a concave boundary), its orientation taken from the polygon
    orient = 1.0 if f.cellArea[k] == 0 else np.sign(
        0.5*(P[:, 0]*np.roll(P[:, 1], -1) - np.roll(P[:, 0], -1)*P[:, 1]).sum())
    for i in range(n):
        a, b = P[i], P[(i + 1) % n]
        A = 0.5*orient*((a[0] - xc[0])*(b[1] - xc[1]) - (b[0] - xc[0])*(a[1] - xc[1]))
        if A == 0:
            continue
        for (s, t), w in zip(_qp, _qw):
            pts.append(xc + s*(a - xc) + t*(b - xc))
            wts.append(w*A)
    return np.array(pts).reshape(-1, 2), np.array(wts)


def energyError(f, exactStress, lam, mu):
    """Relative energy norm of the stress error: the element (cell) stress
    is constant in each manifold element (linear displacement), the exact
    stress is integrated with the sub-triangle rule of l2Error:
    sqrt(int e:C^-1:e / int s:C^-1:s), plane form."""
    sxx, syy, sxy = cellStress(f)

    def energy(a, b, c):
        det = 4*mu*(lam + mu)
        exx = ((lam + 2*mu)*a - lam*b)/det
        eyy = ((lam + 2*mu)*b - lam*a)/det
        return a*exx + b*eyy + c*c/mu

    errSq = 0.0
    refSq = 0.0
    for k in range(len(f.cells)):
        q, w = _subTriangles(f, k)
        if len(w) == 0:
            continue
        ex = np.broadcast_to(np.array(exactStress(q[:, 0], q[:, 1]), dtype=float),
                             (3, len(w)))
        errSq += (w*energy(sxx[k] - ex[0], syy[k] - ex[1], sxy[k] - ex[2])).sum()
        refSq += (w*energy(ex[0], ex[1], ex[2])).sum()
    return float(np.sqrt(errSq/refSq))


def extrapolate(dist, values, extra=None, maxDegree=2, area=None):
    """Least squares fit of values = c0 + c1 d + c2 d^2 (+ extra columns)
    and its value at d = 0; rows weighted by sqrt(element area) when area
    is given, so that slivers cut off by the boundary count little."""
    cols = [np.ones_like(dist), dist]
    if maxDegree >= 2:
        cols.append(dist*dist)
    if extra is not None:
        cols.extend(extra)
    M = np.column_stack(cols)
    if len(values) < M.shape[1] + 2:
        raise SystemExit("extrapolation: only %d cells in the band" % len(values))
    if area is not None:
        w = np.sqrt(area)
        M = M*w[:, None]
        values = values*w
    coef, *_ = np.linalg.lstsq(M, values, rcond=None)
    return float(coef[0])


def rate(h, err):
    """Observed orders between successive levels."""
    return [float(np.log(err[i]/err[i + 1])/np.log(h[i]/h[i + 1]))
            for i in range(len(h) - 1)]


class report:
    """Rows of quantity, computed, expected, error, tolerance, verdict."""

    def __init__(self, title):
        self.title = title
        self.rows = []
        self.failed = False

    def relative(self, name, computed, expected, tol, gate=True):
        err = abs(computed - expected)/abs(expected)
        ok = err <= tol
        self._add(name, computed, expected, err, tol, ok, gate)

    def absolute(self, name, computed, expected, tol, gate=True):
        err = abs(computed - expected)
        ok = err <= tol
        self._add(name, computed, expected, err, tol, ok, gate)

    def upper(self, name, computed, tol, gate=True):
        self._add(name, computed, float("nan"), computed, tol, computed <= tol, gate)

    def info(self, name, computed, expected=float("nan")):
        err = (abs(computed - expected)/abs(expected)
               if expected == expected and expected != 0 else float("nan"))
        self.rows.append((name, computed, expected, err, float("nan"), "info"))

    def _add(self, name, computed, expected, err, tol, ok, gate):
        ok = bool(ok) and computed == computed
        verdict = ("pass" if ok else "FAIL") if gate else "info"
        if gate and not ok:
            self.failed = True
        self.rows.append((name, computed, expected, err, tol, verdict))

    def finish(self):
        print(self.title)
        w = max([len(r[0]) for r in self.rows] + [8])
        print("  %-*s %14s %14s %11s %9s  %s"
              % (w, "quantity", "computed", "expected", "error", "tolerance", ""))
        for name, c, e, err, tol, v in self.rows:
            def num(z, fmt):
                return fmt % z if z == z else "-"
            print("  %-*s %14s %14s %11s %9s  %s"
                  % (w, name, num(c, "%.6g"), num(e, "%.6g"), num(err, "%.3e"),
                     num(tol, "%.3g"), v))
        print("%s: %s" % (self.title, "FAILED" if self.failed else "passed"))
        return 1 if self.failed else 0
