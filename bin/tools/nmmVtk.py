#------------------------------------------------------------------------------
# nmmSolid: Numerical Manifold Method solver for deformable geomaterials
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Module
#     nmmVtk
#
# Description
#     Reading of what nmmSolidFoam writes to VTK/: the frames
#     <case>_<index>.vtu (polygon cells), <case>.vtu.series, the contacts
#     contacts_<index>.vtp and contacts.vtp.series. nmmPlot, the tutorials'
#     summaries and the tests all read the output through this module, so
#     that they agree on what a frame is.
#
#     Needs Debian's /usr/bin/python3: python3-vtk9 and python3-numpy are
#     installed for that interpreter only. They are imported when a file is
#     read, not when this module is, so that a script can first say which
#     package is missing in its own words.
#------------------------------------------------------------------------------
"""Read nmmSolid's VTK output (frames, series, contacts).

    entries = seriesEntries(seriesPath)   # [(time, name), ...] file order
    series = readSeries(caseDir)          # [(time, path), ...] time order
    path = latestFrame(seriesPath)        # the last frame the series lists
    f = readFrame(path)                   # x, cells, pointData, cellData
    c = readContacts(contactsFile(path))  # the frame's contacts: x, data
"""

import json
import sys
from pathlib import Path


def _vtk():
    """The VTK XML readers and vtk_to_numpy, or exit naming the package."""
    try:
        from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader,
                                         vtkXMLUnstructuredGridReader)
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError as e:
        sys.exit("%s: cannot import VTK (%s); install Debian's python3-vtk9 "
                 "and run this with /usr/bin/python3" % (Path(sys.argv[0]).name, e))
    return vtkXMLUnstructuredGridReader, vtkXMLPolyDataReader, vtk_to_numpy


def missingPackages():
    """[(Debian package, ImportError), ...] of numpy and VTK, for a script
    to say what to install before it reads anything."""
    missing = []
    try:
        import numpy  # noqa: F401
    except ImportError as e:
        missing.append(("python3-numpy", e))
    try:
        import vtkmodules.vtkIOXML  # noqa: F401
        import vtkmodules.util.numpy_support  # noqa: F401
    except ImportError as e:
        missing.append(("python3-vtk9", e))
    return missing


def newReader(kind):
    """A VTK XML reader for 'vtu' (unstructured grid) or 'vtp' (poly data)."""
    grid, poly, _ = _vtk()
    return grid() if kind == "vtu" else poly()


def _read(kind, path, errors):
    reader = newReader(kind)
    if errors is not None:
        reader.AddObserver("ErrorEvent", lambda o, e: errors.append(e))
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def readGrid(path, errors=None):
    """The vtkUnstructuredGrid of a .vtu; VTK's error events are appended to
    the list errors when one is given."""
    return _read("vtu", path, errors)


def readPolyData(path, errors=None):
    """The vtkPolyData of a .vtp (see readGrid)."""
    return _read("vtp", path, errors)


def toNumpy(vtkArray):
    return _vtk()[2](vtkArray)


def points(dataSet):
    """x, y of the points (the solver writes them in the deformed position)."""
    return toNumpy(dataSet.GetPoints().GetData()).astype(float)[:, :2].copy()


def arrays(data):
    """{name: numpy float array} of a vtkPointData or vtkCellData, in file
    order."""
    out = {}
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        if a is None:
            continue
        out[a.GetName()] = toNumpy(a).astype(float)
    return out


def cellPoints(grid):
    """The cells as lists of point indices."""
    cells = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        cells.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    return cells


class frame:
    pass


def readFrame(path):
    """A frame of a .vtu: path, x (points), cells, pointData and cellData
    ({name: numpy array})."""
    grid = readGrid(path)
    if grid is None or grid.GetNumberOfPoints() == 0:
        raise SystemExit("%s: no points" % path)
    f = frame()
    f.path = Path(path)
    f.x = points(grid)
    f.pointData = arrays(grid.GetPointData())
    f.cellData = arrays(grid.GetCellData())
    f.cells = cellPoints(grid)
    return f


# --------------------------------------------------------------------------
# Series: VTK/<case>.vtu.series and VTK/contacts.vtp.series (ParaView's
# JSON file series)
# --------------------------------------------------------------------------
def seriesEntries(path):
    """[(time, file name), ...] of a .series file, in the order it lists
    them. Raises OSError, ValueError, KeyError or TypeError for a file that
    cannot be read or is not a series."""
    data = json.loads(Path(path).read_text())
    return [(float(e["time"]), e["name"]) for e in data["files"]]


def seriesFile(caseDir):
    """VTK/<case>.vtu.series of a case folder (the case is the folder's name)."""
    caseDir = Path(caseDir).resolve()
    return caseDir/"VTK"/(caseDir.name + ".vtu.series")


def latestFrame(path):
    """The frame a .series file lists last."""
    return Path(path).parent/seriesEntries(path)[-1][1]


def _timeOrdered(path):
    frames = [(t, path.parent/name) for t, name in seriesEntries(path)]
    if not frames:
        raise SystemExit("%s lists no files" % path)
    frames.sort(key=lambda f: f[0])
    return frames


def readSeries(caseDir):
    """[(time, path), ...] of the case's VTK/<case>.vtu.series, in time
    order; exits when the case has not been run."""
    path = seriesFile(caseDir)
    if not path.is_file():
        raise SystemExit("no %s (has the case been run?)" % path)
    if json.loads(path.read_text()).get("file-series-version") != "1.0":
        raise SystemExit("%s: file-series-version is not 1.0" % path)
    return _timeOrdered(path)


def readContactSeries(caseDir):
    """[(time, path), ...] of VTK/contacts.vtp.series, in time order."""
    path = Path(caseDir).resolve()/"VTK"/"contacts.vtp.series"
    if not path.is_file():
        raise SystemExit("no %s (has the case been run? does it have contacts?)"
                         % path)
    return _timeOrdered(path)


# --------------------------------------------------------------------------
# Contacts: VTK/contacts_<index>.vtp
# --------------------------------------------------------------------------
def contactsFile(vtu):
    """VTK/contacts_<index>.vtp of the frame <case>_<index>.vtu (it exists
    only when the frame has contacts)."""
    index = Path(vtu).stem.rsplit("_", 1)[1]
    return Path(vtu).parent/("contacts_%s.vtp" % index)


def readContacts(path):
    """A contact frame: x (contact points), and the point data arrays
    (contactState, bondIntact, normalForce, shearForce, penetration, slip,
    length, normal, force, blockA, blockB; files of older runs lack the
    last two) as numpy arrays; no points gives empty arrays."""
    import numpy as np
    poly = readPolyData(path)
    c = frame()
    c.path = Path(path)
    n = poly.GetNumberOfPoints() if poly is not None else 0
    c.x = points(poly) if n else np.zeros((0, 2))
    c.data = arrays(poly.GetPointData()) if n else {}
    for name in ("contactState", "bondIntact", "normalForce", "shearForce"):
        if name not in c.data:
            c.data[name] = np.zeros(n) if n == 0 else None
            if n:
                raise SystemExit("%s: no point data '%s'" % (path, name))
    return c
