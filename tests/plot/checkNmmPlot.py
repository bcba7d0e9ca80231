#!/usr/bin/python3
"""Test bin/tools/nmmPlot on the sample VTK output of vtkSamples.

Usage:
    checkNmmPlot.py --samples <vtkSamples> --plot <nmmPlot> --work <dir>

Runs vtkSamples into <dir>/samples, then nmmPlot (with this interpreter,
/usr/bin/python3 from NMM_DEBIAN_PYTHON, which sees Debian's
python3-matplotlib, python3-numpy and python3-vtk9) on a frame:

  - a scalar (cell data sigmaEq), a tensor component (sigma xy), point
    data (D magnitude, -point -edges -undeformed), the latest frame of the
    .vtu.series, an integer field (blockId, two values) and -list;
  - each PNG must exist, be 8*dpi x 6*dpi pixels (read back with
    matplotlib.image.imread), not be blank (pixel variance > 0) and hold
    at least a minimum number of distinct colours;
  - for cell data with known values (sigmaEq: 7 distinct values, blockId:
    2), the colour of every cell value on the colour map must fill a
    polygon-sized patch of the PNG (not just the colour bar);
  - errors exit 1 with a message: unknown field (near miss: "did you
    mean"), missing file, bad component, tensor without component.

Exit code 0 when every check passes, 1 otherwise.

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


def check(cond, what):
    print("%s: %s" % ("ok  " if cond else "FAIL", what))
    if not cond:
        failures.append(what)


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def cell_values(frame, field):
    return nmmVtk.toNumpy(
        nmmVtk.readGrid(frame).GetCellData().GetArray(field)).astype(float)


def check_cell_colours(np, img, values, name):
    """Every distinct value's viridis colour (range = data range) covers
    more pixels than the colour bar alone could (a flat polygon)."""
    import matplotlib.pyplot as plt
    pixels = (img[..., :3]*255).round().astype(int).reshape(-1, 3)
    lo, hi = values.min(), values.max()
    minPixels = pixels.shape[0]//400
    for v in np.unique(values):
        rgb = (np.array(plt.get_cmap("viridis")((v - lo)/(hi - lo)))[:3]
               * 255).round().astype(int)
        n = int((np.abs(pixels - rgb).max(axis=1) <= 1).sum())
        check(n >= minPixels, "%s: value %g drawn in its colour %s "
              "(%d pixels >= %d)" % (name, v, tuple(rgb), n, minPixels))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--samples", required=True)
    ap.add_argument("--plot", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()

    try:
        import numpy as np
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.image as mpimg
    except ImportError as e:
        sys.exit("checkNmmPlot: %s cannot import %s: install the Debian "
                 "packages python3-numpy python3-matplotlib" % (sys.executable, e))

    work = Path(a.work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    rc, out, err = run([a.samples, str(work/"samples")])
    if rc != 0:
        sys.exit("checkNmmPlot: vtkSamples failed (%d):\n%s%s" % (rc, out, err))
    vtkDir = work/"samples"/"binary"/"sampleCase"/"VTK"
    frame = vtkDir/"sampleCase_100.vtu"
    series = vtkDir/"sampleCase.vtu.series"
    plot = [sys.executable, a.plot]

    # (name, arguments, dpi, minimum distinct colours in the PNG)
    cases = [
        ("scalar", [str(frame), "-field", "sigmaEq", "-cmap", "viridis"],
         60, 7),
        ("tensorComponent",
         [str(frame), "-field", "sigma", "-component", "xy", "-edges",
          "-cmap", "plasma", "-title", "sigma xy"], 50, 7),
        ("point", [str(frame), "-field", "D", "-point", "-edges",
                   "-undeformed"], 40, 20),
        ("seriesLatest", [str(series), "-time", "latest", "-field", "sigmaMin",
                          "-range", "-7e6", "0"], 30, 7),
        ("blockId", [str(frame), "-field", "blockId"], 40, 2),
    ]
    for name, args, dpi, minColours in cases:
        png = work/(name + ".png")
        rc, out, err = run(plot + args + ["-dpi", str(dpi), "-o", str(png)])
        check(rc == 0, "%s: nmmPlot exits 0 (%s)" % (name, err.strip()))
        check(png.is_file(), "%s: %s written" % (name, png.name))
        if not png.is_file():
            continue
        img = mpimg.imread(str(png))
        check(img.shape[:2] == (6*dpi, 8*dpi),
              "%s: size %s is 6*dpi x 8*dpi for dpi %d"
              % (name, img.shape[:2], dpi))
        check(float(img.var()) > 0, "%s: not blank" % name)
        colours = len(np.unique(img.reshape(-1, img.shape[-1]), axis=0))
        check(colours >= minColours, "%s: %d distinct colours >= %d"
              % (name, colours, minColours))
        if name in ("scalar", "blockId"):
            field = "sigmaEq" if name == "scalar" else "blockId"
            values = cell_values(frame, field)
            check(len(np.unique(values)) == (7 if name == "scalar" else 2),
                  "%s: the sample has the expected distinct values" % name)
            check_cell_colours(np, img, values, name)

    # The series picks the latest listed frame (150, not 200 left on disk)
    rc, out, err = run(plot + [str(series), "-time", "latest", "-list"])
    check(rc == 0 and "sampleCase_150.vtu" in out,
          "-time latest picks sampleCase_150.vtu")
    rc, out, err = run(plot + [str(series), "-time", "0", "-list"])
    check(rc == 0 and "sampleCase_0.vtu" in out, "-time 0 picks sampleCase_0.vtu")

    rc, out, err = run(plot + [str(frame), "-list"])
    check(rc == 0 and "sigmaEq" in out and "xx yy zz xy yz xz" in out
          and "point data" in out, "-list prints arrays and components")

    # Errors
    rc, out, err = run(plot + [str(frame), "-field", "sigmaEQ",
                               "-o", str(work/"x.png")])
    check(rc == 1 and "did you mean" in err and "'sigmaEq'" in err,
          "unknown field near miss: exit 1, did you mean 'sigmaEq' (%s)"
          % err.strip().splitlines()[:1])
    rc, out, err = run(plot + [str(frame), "-field", "nothingLikeIt",
                               "-o", str(work/"x.png")])
    check(rc == 1 and "available" in err and "sigmaEq" in err,
          "unknown field: exit 1 listing the available arrays")
    rc, out, err = run(plot + [str(work/"missing.vtu"), "-field", "D"])
    check(rc == 1 and "not found" in err, "missing file: exit 1")
    rc, out, err = run(plot + [str(frame), "-field", "sigma",
                               "-component", "x", "-o", str(work/"x.png")])
    check(rc == 1 and "bad component" in err, "bad component: exit 1")
    rc, out, err = run(plot + [str(frame), "-field", "sigma",
                               "-o", str(work/"x.png")])
    check(rc == 1 and "-component" in err, "tensor without component: exit 1")
    check(not (work/"x.png").exists(), "no PNG written on errors")
    rc, out, err = run(plot + ["-help"])
    check(rc == 0 and "-undeformed" in out and "deformed position" in out,
          "-help documents -undeformed")

    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    print("All nmmPlot checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
