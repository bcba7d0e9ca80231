#!/usr/bin/python3
"""The point data of a solver frame against its cell data.

Usage:
    checkPointData.py --bin <folder of nmmMesh and nmmSolidFoam>
        --case <dir> --work <dir> --materials <id of block 0> ...

The case is copied to <work>; nmmMesh and nmmSolidFoam run there and
must exit with 0. The last frame VTK/<case>_<index>.vtu is read with
VTK's XML reader (any VTK error or warning fails) and must have:

  - the point data blockId and materialId (Int32, one component) as well
    as the cell data of those names (case-format.md, Output);
  - for every cell and every point it uses: the point's blockId and
    materialId those of the cell (a point belongs to one block: points
    are duplicated across blocks), and every point used by some cell;
  - materialId the one given for each block (--materials, in the order
    of mechanicalProperties' materials), so that blockId and materialId
    are not swapped;
  - every block present, and a point of the crack's faces twice at the
    same reference position in the same block;
  - sigmaEq, sigmaMax, sigmaMid and sigmaMin as point data, equal to the
    von Mises stress and the eigenvalues of the point's sigma (computed
    here with numpy) to 1e-9 of the largest stress, and not all zero.

Run with /usr/bin/python3: VTK's bindings come from the Debian package
python3-vtk9 (see tests/vtk). Exit code 0 when every check passes.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
import nmmVtk  # noqa: E402

failures = []


def check(ok, what):
    print("%s: %s" % ("ok  " if ok else "FAIL", what))
    if not ok:
        failures.append(what)


def run(exe, case):
    p = subprocess.run([str(exe), "-case", str(case)], capture_output=True, text=True)
    (case/("log." + exe.name)).write_text(p.stdout + p.stderr)
    if p.returncode != 0:
        print(p.stdout[-3000:], p.stderr, sep="\n")
        sys.exit("FAIL: %s exit code %d" % (exe.name, p.returncode))


def intArray(data, name):
    a = data.GetArray(name)
    if a is None:
        return None, "no array '%s'" % name
    if a.GetDataTypeAsString() != "int" or a.GetNumberOfComponents() != 1:
        return None, "'%s' is %s with %d components, not Int32 scalars" % (
            name, a.GetDataTypeAsString(), a.GetNumberOfComponents())
    return nmmVtk.toNumpy(a), ""


def checkIds(grid, materials):
    cells = nmmVtk.cellPoints(grid)
    ids = {}
    for kind, data in (("cell", grid.GetCellData()), ("point", grid.GetPointData())):
        for name in ("blockId", "materialId"):
            a, why = intArray(data, name)
            check(a is not None, "%s data %s (Int32)%s" % (kind, name, ": " + why if why else ""))
            ids[kind, name] = a
    if any(a is None for a in ids.values()):
        return
    used = set()
    wrong = []
    for c, points in enumerate(cells):
        used.update(points)
        for p in points:
            for name in ("blockId", "materialId"):
                if ids["point", name][p] != ids["cell", name][c]:
                    wrong.append("point %d: %s %d, its cell %d has %d" % (
                        p, name, ids["point", name][p], c, ids["cell", name][c]))
    check(not wrong, "every point has the blockId and materialId of the cells using it"
          + ("" if not wrong else ": %d wrong, e.g. %s" % (len(wrong), wrong[0])))
    check(used == set(range(grid.GetNumberOfPoints())),
          "every point is used by a cell (%d of %d)" % (len(used), grid.GetNumberOfPoints()))
    blocks = sorted(set(ids["cell", "blockId"]))
    check(blocks == list(range(len(materials))),
          "the blocks %s are 0 .. %d" % (blocks, len(materials) - 1))
    bad = [(b, m) for b, m in zip(ids["point", "blockId"], ids["point", "materialId"])
           if materials[b] != m]
    check(not bad, "point materialId is the block's material %s%s"
          % (materials, "" if not bad else ": not for %s" % (bad[:3],)))
    return ids


def checkCrack(grid, ids):
    """Points of one block at one reference position: the crack's faces."""
    x = nmmVtk.points(grid)
    D = nmmVtk.toNumpy(grid.GetPointData().GetArray("D"))[:, :2]
    X = x - D
    seen = {}
    twice = 0
    for p in range(len(X)):
        key = (int(ids["point", "blockId"][p]), round(X[p, 0], 9), round(X[p, 1], 9))
        twice += key in seen
        seen[key] = p
    check(twice > 0, "%d points of a block are duplicated at one reference position "
          "(the crack's faces)" % twice)


def checkInvariants(grid):
    import numpy as np
    pd = grid.GetPointData()
    names = ("sigma", "sigmaEq", "sigmaMax", "sigmaMid", "sigmaMin")
    missing = [n for n in names if pd.GetArray(n) is None]
    check(not missing, "point data %s%s" % (" ".join(names),
          "" if not missing else ": missing " + " ".join(missing)))
    if missing:
        return
    s = nmmVtk.toNumpy(pd.GetArray("sigma"))       # xx yy zz xy yz xz
    xx, yy, zz, xy = s[:, 0], s[:, 1], s[:, 2], s[:, 3]
    eq = np.sqrt(0.5*((xx - yy)**2 + (yy - zz)**2 + (zz - xx)**2) + 3*xy**2)
    tensors = np.zeros((len(s), 3, 3))
    tensors[:, 0, 0], tensors[:, 1, 1], tensors[:, 2, 2] = xx, yy, zz
    tensors[:, 0, 1] = tensors[:, 1, 0] = xy
    principal = np.linalg.eigvalsh(tensors)[:, ::-1]     # largest first
    scale = np.abs(s).max()
    check(scale > 0, "the point stresses are not all zero (largest %.3g Pa)" % scale)
    for name, expected in (("sigmaEq", eq), ("sigmaMax", principal[:, 0]),
                           ("sigmaMid", principal[:, 1]), ("sigmaMin", principal[:, 2])):
        got = nmmVtk.toNumpy(pd.GetArray(name))
        err = np.abs(got - expected).max() if len(got) == len(expected) else np.inf
        check(err <= 1e-9*scale, "point %s from the point's sigma (largest difference "
              "%.3g Pa)" % (name, err))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--case", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--materials", type=int, nargs="+", required=True)
    args = ap.parse_args()
    missing = nmmVtk.missingPackages()
    if missing:
        sys.exit("FAIL: cannot import %s: install %s" % (
            missing, " ".join(p for p, _ in missing)))

    work = Path(args.work).resolve()
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(args.case, work)
    run(Path(args.bin)/"nmmMesh", work)
    run(Path(args.bin)/"nmmSolidFoam", work)

    frames = sorted((work/"VTK").glob(work.name + "_*.vtu"),
                    key=lambda f: int(f.stem.rsplit("_", 1)[1]))
    if not frames:
        sys.exit("FAIL: no VTK/%s_<index>.vtu written" % work.name)
    errors = []
    grid = nmmVtk.readGrid(frames[-1], errors)
    check(not errors, "VTK reads %s without a message%s" % (
        frames[-1].name, "" if not errors else ": " + "; ".join(errors)))
    ids = checkIds(grid, args.materials)
    if ids:
        checkCrack(grid, ids)
    checkInvariants(grid)

    print("\n%d failure%s" % (len(failures), "" if len(failures) == 1 else "s"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
