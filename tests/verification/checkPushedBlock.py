#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Check tutorials/verification/contact/pushedBlock: a block bonded to a
fixed base (c = 0.1, phi = 30 degrees, L = 1, W = 1, m = 1) pushed by
F(t) = t.

Usage:
    checkPushedBlock.py <caseDir>

The onset of sliding is the first frame in which no contact is bonded any
more (contactState of VTK/contacts_<index>.vtp: 0 open, 1 bonded,
2 sliding; the index that of the frame's .vtu) while some are closed;
its load F = t must be within one load increment (0.01) of
c L + W tan phi = 0.6774, and the block (block 1) must then move. The
first frame with a sliding contact and the block's mean D_x after the
onset against m x'' = F - W tan phi are reported.
Exit 1 when any check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import closedForms as cf  # noqa: E402
import nmmFrames as nf  # noqa: E402
from checkIncline import blockDisplacement  # noqa: E402

BLOCK = 1


def contactStates(vtu):
    """contactState of the contacts file of a frame (numpy array), or None."""
    path = nf.contactsFile(vtu)
    if not path.is_file():
        return None
    a = nf.nmmVtk.readPolyData(path).GetPointData().GetArray("contactState")
    if a is None:
        raise SystemExit("%s: no point data contactState" % path)
    return nf.nmmVtk.toNumpy(a).astype(int)


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "-help", "--help"):
        print(__doc__)
        return 0 if argv else 1
    c = cf.pushedBlock
    series = nf.readSeries(argv[0])
    r = nf.report("pushedBlock")
    firstSliding = onset = None
    times = []
    dx = []
    missing = 0
    for t, path in series:
        s = contactStates(path)
        mean, _ = blockDisplacement(nf.readFrame(path), BLOCK)
        times.append(t)
        dx.append(float(mean[0]))
        if s is None:
            missing += 1
            continue
        if firstSliding is None and (s == 2).any():
            firstSliding = t
        if onset is None and t > 0 and not (s == 1).any() and (s > 0).any():
            onset = t
    times = np.array(times)
    dx = np.array(dx)
    r.info("frames without a contacts file", float(missing))
    r.info("first sliding contact: F [N/m]",
           c.rate*firstSliding if firstSliding is not None else float("nan"),
           c.onsetForce())
    if onset is None:
        r.info("no frame without bonded contacts", float("nan"))
        r.failed = True
        return r.finish()
    r.absolute("onset of sliding: F [N/m]", c.rate*onset, c.onsetForce(),
               c.loadIncrement()*(1 + 1e-9))
    before = dx[times < onset - 0.5*c.deltaT]
    r.info("D_x of the block before the onset, largest [m]",
           float(np.abs(before).max()) if len(before) else 0.0)
    t, d = float(times[-1]), float(dx[-1])
    r.info("D_x at t = %.4g [m]" % t, d, c.displacement(t))
    r.info("D_x at t = %.4g from the observed onset [m]" % t, d,
           c.displacement(t, onset))
    r.upper("block moves after the onset: -D_x [m]", -d, 0.0)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
