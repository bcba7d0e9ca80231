#!/usr/bin/python3
"""Run nmmMesh on a valid case and read its VTK/mesh.vtu back with VTK.

Usage:
    checkValidCase.py --nmmMesh <exe> --case <dir> --work <dir> --area <A>
        [--holes <n>] [--materials <id of block 0> <id of block 1> ...]
        [--says <text> ...]

The case is copied to <work>, nmmMesh runs there (without -check) and
must exit with 0, print "Mesh OK." and each --says text, and write
constant/nmmMesh/nmmMesh.h5 and VTK/mesh.vtu. The .vtu is read with
vtkXMLUnstructuredGridReader (VTK errors and warnings fail the check) and
must have:

  - as many cells as the report's "elements:", all VTK_POLYGON;
  - the cell data blockId, materialId, area, areaRatio, triangle,
    patches (3 components) and hasHoles, with n cells flagged hasHoles
    (--holes, default 0) and materialId the one given for each block
    (--materials);
  - counter-clockwise polygons whose area (shoelace formula) is the
    cell's 'area' to 1e-12 relative, except for the elements with holes,
    whose polygon is the outer loop only and must be larger;
  - summed over the elements (the polygon areas for elements without
    holes, 'area' for those with holes) the material area A of the
    geometry, to 1e-12 relative.

Run with /usr/bin/python3: VTK's bindings come from the Debian package
python3-vtk9 (see tests/vtk).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
import nmmVtk  # noqa: E402


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nmmMesh", required=True)
    ap.add_argument("--case", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--area", required=True, type=float)
    ap.add_argument("--holes", type=int, default=0)
    ap.add_argument("--materials", type=int, nargs="*")
    ap.add_argument("--says", nargs="*", default=[])
    args = ap.parse_args()

    try:
        import vtk
    except ImportError as e:
        fail(f"cannot import VTK ({e}): install the Debian package python3-vtk9")

    work = Path(args.work)
    shutil.rmtree(work, ignore_errors=True)
    work.parent.mkdir(parents=True, exist_ok=True)
    shutil.copytree(args.case, work)

    run = subprocess.run([args.nmmMesh, "-case", str(work)],
                         capture_output=True, text=True)
    print(run.stdout)
    print(run.stderr, file=sys.stderr)
    if run.returncode != 0:
        fail(f"nmmMesh exit code {run.returncode}")
    if "Mesh OK." not in run.stdout:
        fail("no 'Mesh OK.' in the output")
    for text in args.says:
        if text not in run.stdout:
            fail(f"no '{text}' in the output")
    m = re.search(r"^\s*elements:\s+(\d+)\s*$", run.stdout, re.M)
    if not m:
        fail("no 'elements:' line in the report")
    nElements = int(m.group(1))

    h5 = work / "constant" / "nmmMesh" / "nmmMesh.h5"
    vtu = work / "VTK" / "mesh.vtu"
    for f in (h5, vtu):
        if not f.is_file():
            fail(f"{f} was not written")
    with open(h5, "rb") as f:
        if f.read(8) != b"\x89HDF\r\n\x1a\n":
            fail(f"{h5} is not an HDF5 file")

    messages = vtk.vtkStringOutputWindow()
    vtk.vtkOutputWindow.SetInstance(messages)
    problems = []
    reader = nmmVtk.newReader("vtu")
    reader.AddObserver("ErrorEvent", lambda *a: problems.append("error"))
    reader.AddObserver("WarningEvent", lambda *a: problems.append("warning"))
    reader.SetFileName(str(vtu))
    reader.Update()
    if problems or messages.GetOutput().strip():
        fail(f"VTK reported {problems}: {messages.GetOutput()}")
    grid = reader.GetOutput()

    if grid.GetNumberOfCells() != nElements:
        fail(f"{grid.GetNumberOfCells()} cells, the report says {nElements} elements")
    cd = grid.GetCellData()
    expected = {"blockId": 1, "materialId": 1, "area": 1, "areaRatio": 1,
                "triangle": 1, "patches": 3, "hasHoles": 1}
    for name, nc in expected.items():
        a = cd.GetArray(name)
        if a is None:
            fail(f"no cell data '{name}'")
        if a.GetNumberOfComponents() != nc:
            fail(f"'{name}' has {a.GetNumberOfComponents()} components, expected {nc}")
    hasHoles = nmmVtk.toNumpy(cd.GetArray("hasHoles"))
    area = nmmVtk.toNumpy(cd.GetArray("area"))
    if int(hasHoles.sum()) != args.holes or not set(hasHoles) <= {0, 1}:
        fail(f"{int(hasHoles.sum())} cells flagged hasHoles, expected {args.holes}")
    if args.materials is not None:
        blockId = nmmVtk.toNumpy(cd.GetArray("blockId"))
        materialId = nmmVtk.toNumpy(cd.GetArray("materialId"))
        for b, m in zip(blockId, materialId):
            if args.materials[b] != m:
                fail(f"a cell of block {b} has materialId {m}, expected {args.materials[b]}")

    points = nmmVtk.toNumpy(grid.GetPoints().GetData())
    parts = []
    for c in range(grid.GetNumberOfCells()):
        if grid.GetCellType(c) != 7:
            fail(f"cell {c} is of type {grid.GetCellType(c)}, not VTK_POLYGON")
        ids = grid.GetCell(c).GetPointIds()
        xy = [points[ids.GetId(k)][:2] for k in range(ids.GetNumberOfIds())]
        a = 0.0
        bound = 0.0     # rounding bound of the shoelace sum
        for k in range(len(xy)):
            x0, y0 = xy[k]
            x1, y1 = xy[(k + 1) % len(xy)]
            a += x0*y1 - x1*y0
            bound += abs(x0*y1) + abs(x1*y0)
        a /= 2
        bound *= 8*2.2e-16
        # Exact slivers (a cover node an ulp off a block edge) round to
        # zero area in double precision, and their shoelace area is only
        # known to about 1e-15 of their triangle's; a clockwise polygon is
        # still an error
        if a < -bound:
            fail(f"cell {c} is not counter-clockwise (signed area {a})")
        if hasHoles[c]:
            if not a > area[c]:
                fail(f"cell {c} has holes but its outer loop ({a}) is not larger "
                     f"than its area ({area[c]})")
            parts.append(area[c])
        else:
            if abs(a - area[c]) > 1e-12*area[c] + bound:
                fail(f"cell {c}: polygon area {a}, element area {area[c]}")
            parts.append(a)
    total = math.fsum(parts)
    rel = abs(total - args.area)/args.area
    print(f"{nElements} cells; polygon area {total!r}, geometry {args.area!r}, "
          f"relative difference {rel:.3g}")
    if rel > 1e-12:
        fail("polygon area differs from the geometry's")
    print("PASS")


if __name__ == "__main__":
    main()
