#!/usr/bin/python3
"""The compaction against the pseudo-time: the platen's displacement
under each half, and the porosity of each half and of the whole sample
(the grains' area over the area under the platen, as in summary.py),
from the postProcessing/ tables of a run. It shows the packing giving
way fast at first, then in jumps as arches of grains fail, and coming
to rest.

    /usr/bin/python3 plotHistory.py <run folder> <output PNG>

Needs matplotlib (Debian's python3-matplotlib, hence /usr/bin/python3).
SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def table(run, name):
    path = os.path.join(run, "postProcessing", name, "0", name + ".dat")
    rows = [[float(v) for v in l.split()] for l in open(path)
            if l.strip() and not l.startswith("#")]
    return list(zip(*rows))


def main(run, output):
    left, right = table(run, "platenLeft"), table(run, "platenRight")
    sandLeft, sandRight = table(run, "sandLeft"), table(run, "sandRight")
    # Every table has a row at the start and one per step: they line up
    height = sandLeft[3][0]
    wL, wR = sandLeft[2][0]/height, sandRight[2][0]/height
    nL = [1 - s/(wL*(height + d)) for s, d in zip(sandLeft[1], left[2])]
    nR = [1 - s/(wR*(height + d)) for s, d in zip(sandRight[1], right[2])]
    n = [1 - (sl + sr)/(wL*(height + dl) + wR*(height + dr))
         for sl, sr, dl, dr in zip(sandLeft[1], sandRight[1], left[2], right[2])]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6, 5))
    ms = [1e3*t for t in left[0]]
    top.plot(ms, [-1e6*d for d in left[2]], label="left half")
    top.plot(ms, [-1e6*d for d in right[2]], label="right half")
    top.set_ylabel("platen down [um]")
    top.legend(loc="lower right")
    top.grid(alpha=0.3)
    bottom.plot(ms, nL, label="left half")
    bottom.plot(ms, nR, label="right half")
    bottom.plot(ms, n, color="k", label="whole")
    bottom.legend(loc="upper right")
    bottom.set_ylabel("porosity")
    bottom.set_xlabel("pseudo-time [ms]")
    bottom.grid(alpha=0.3)
    fig.suptitle("Compaction under 1 MPa")
    fig.tight_layout()
    fig.savefig(output, dpi=80)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(1)
    main(sys.argv[1], sys.argv[2])
