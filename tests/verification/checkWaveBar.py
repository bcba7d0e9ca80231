#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/waveBar: the front travels at c = sqrt(E/rho).

Usage:
    checkWaveBar.py <caseDir>

Bar 10 x 0.5, E = 1e9, rho = 1000, nu = 0 (plane stress; with nu = 0 the
bar is exactly one-dimensional), so c = 1000 m/s; step pressure
p0 = 1e6 on x = 0 from t = 0. Behind the front U_x = p0 c/E = 1 m/s and
u_x = p0/E (c t - x). The station is the column of points whose
undeformed x is nearest 5 (expected arrival x_s/c = 5e-3 s). From the
whole time series (the station's mean over its points):
  - arrival time: first time the mean U_x reaches half of p0 c/E, linear
    in time between frames; within 2%;
  - arrival time from the displacement: a straight line fitted to the
    mean D_x over x_s/c + 1e-3 <= t <= min(end, (2L - x_s)/c) (before
    the reflection from x = L is back), where it crosses zero; within 2%;
    its slope gives c (E/p0 x slope), within 2%.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402

TOL = 0.02


def errors(caseDir):
    """Error measures of the time series, as numbers (no pass/fail): the
    relative errors of the arrival time at the station (half U_x; D_x
    line) and of c from the D_x slope, as main() computes them (nan when
    a measure cannot be formed)."""
    c = cf.waveBar
    series = nf.readSeries(caseDir)
    last = nf.readFrame(series[-1][1])
    xs = last.X[np.argmin(np.abs(last.X[:, 0] - c.station)), 0]
    idx = np.flatnonzero(np.abs(last.X[:, 0] - xs) < 1e-6*c.L)
    times, dx, ux = [], [], []
    for t, path in series:
        f = nf.readFrame(path)
        times.append(t)
        dx.append(f.D[idx, 0].mean())
        ux.append(f.U[idx, 0].mean() if f.U is not None else np.nan)
    times, dx, ux = np.array(times), np.array(dx), np.array(ux)
    speed = c.c()
    ta = xs/speed
    out = {"arrivalUError": np.nan, "arrivalDError": np.nan, "cError": np.nan}
    half = 0.5*c.p0*speed/c.E
    k = np.flatnonzero(ux >= half)
    if len(k) and k[0] > 0:
        i = k[0]
        tc = times[i - 1] + (half - ux[i - 1])*(times[i] - times[i - 1]) \
            / (ux[i] - ux[i - 1])
        out["arrivalUError"] = abs(tc - ta)/ta
    window = (times >= ta + 1e-3) & (times <= min(times[-1], (2*c.L - xs)/speed))
    if window.sum() >= 3:
        slope, icpt = np.polyfit(times[window], dx[window], 1)
        out["arrivalDError"] = abs(-icpt/slope - ta)/ta
        out["cError"] = abs(slope*c.E/c.p0 - speed)/speed
    return {k: float(v) for k, v in out.items()}


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    c = cf.waveBar
    series = nf.readSeries(argv[0])
    last = nf.readFrame(series[-1][1])
    xs = last.X[np.argmin(np.abs(last.X[:, 0] - c.station)), 0]
    idx = np.flatnonzero(np.abs(last.X[:, 0] - xs) < 1e-6*c.L)
    times, dx, ux = [], [], []
    haveU = True
    for t, path in series:
        f = nf.readFrame(path)
        if len(f.X) != len(last.X) or np.abs(f.X[idx, 0] - xs).max() > 1e-6*c.L:
            raise SystemExit("%s: the station's points moved in the numbering" % path)
        times.append(t)
        dx.append(f.D[idx, 0].mean())
        if f.U is None:
            haveU = False
        else:
            ux.append(f.U[idx, 0].mean())
    times = np.array(times)
    dx = np.array(dx)
    speed = c.c()
    ta = xs/speed
    r = nf.report("waveBar (station x = %.6g, %d points, %d frames)"
                  % (xs, len(idx), len(times)))
    if haveU:
        ux = np.array(ux)
        half = 0.5*c.p0*speed/c.E
        k = np.flatnonzero(ux >= half)
        if len(k) == 0 or k[0] == 0:
            r._add("arrival time, half U_x", float("nan"), ta, float("nan"),
                   TOL, False, True)
        else:
            i = k[0]
            tc = times[i - 1] + (half - ux[i - 1])*(times[i] - times[i - 1]) \
                / (ux[i] - ux[i - 1])
            r.relative("arrival time, half U_x", float(tc), ta, TOL)
    else:
        r._add("arrival time, half U_x (no U written)", float("nan"), ta,
               float("nan"), TOL, False, True)
    window = (times >= ta + 1e-3) & (times <= min(times[-1], (2*c.L - xs)/speed))
    if window.sum() < 3:
        r._add("arrival time, D_x line", float("nan"), ta, float("nan"),
               TOL, False, True)
    else:
        slope, icpt = np.polyfit(times[window], dx[window], 1)
        r.relative("arrival time, D_x line", float(-icpt/slope), ta, TOL)
        r.relative("c from the D_x slope", float(slope*c.E/c.p0), speed, TOL)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
