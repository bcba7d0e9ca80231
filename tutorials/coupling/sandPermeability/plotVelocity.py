#!/usr/bin/python3
# Debian's /usr/bin/python3 on purpose: numpy, matplotlib and vtk are
# Debian's packages (python3-numpy, python3-matplotlib, python3-vtk9),
# which an interpreter that comes first on PATH may not see.
"""The velocity magnitude in the pore space of an nmmPoreFlow case, from
OpenFOAM's foamToVTK output (VTK/<case>_<iteration>/internal.vtu, the
last one): each cell drawn as its polygon at z = 0, coloured by |U|,
without ParaView.

    /usr/bin/python3 plotVelocity.py <poreFlow/time> <png> [title]

SPDX-License-Identifier: GPL-3.0-or-later
"""
import glob
import math
import os
import sys


def last_internal(case):
    files = glob.glob(os.path.join(case, "VTK", "*", "internal.vtu"))
    if not files:
        raise SystemExit("no VTK/*/internal.vtu in %s: run foamToVTK there" % case)
    return max(files, key=lambda f: int(os.path.basename(os.path.dirname(f)).split("_")[-1]))


def cells(path):
    """Each cell's polygon (its points at the lower face, in order around
    the centroid: the cells are star-shaped about it), |U|, and the
    direction the flow takes on the whole (sum of U)"""
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    U = vtk_to_numpy(grid.GetCellData().GetArray("U"))
    z0 = pts[:, 2].min()
    tol = 1e-3*(pts[:, 2].max() - z0)
    polys, mags = [], []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        low = [pts[ids.GetId(i)][:2] for i in range(ids.GetNumberOfIds())
               if pts[ids.GetId(i)][2] - z0 < tol]
        if len(low) < 3:
            continue
        cx = sum(p[0] for p in low)/len(low)
        cy = sum(p[1] for p in low)/len(low)
        low.sort(key=lambda p: math.atan2(p[1] - cy, p[0] - cx))
        polys.append(low)
        mags.append(math.hypot(U[c][0], U[c][1]))
    Ux, Uy = U[:, 0].sum(), U[:, 1].sum()
    if abs(Ux) >= abs(Uy):
        direction = "left to right" if Ux > 0 else "right to left"
    else:
        direction = "bottom to top" if Uy > 0 else "top to bottom"
    return polys, mags, direction


def main():
    case, png = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else "velocity magnitude [m/s]"
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    polys, mags, direction = cells(last_internal(case))
    fig, ax = plt.subplots(figsize=(6.4, 5.6), dpi=100)
    coll = PolyCollection([[(1e3*x, 1e3*y) for x, y in p] for p in polys], array=mags,
                          cmap="viridis", edgecolors="face", linewidths=0.1)
    ax.add_collection(coll)
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_facecolor("0.85")
    ax.set_xlabel("x [mm] (flow from %s)" % direction)
    ax.set_ylabel("y [mm]")
    ax.set_title(title, fontsize=10)
    fig.colorbar(coll, ax=ax, shrink=0.8)
    fig.tight_layout()
    fig.savefig(png)
    print("%s: %d cells, |U| up to %.3g m/s" % (png, len(polys), max(mags)))


if __name__ == "__main__":
    main()
