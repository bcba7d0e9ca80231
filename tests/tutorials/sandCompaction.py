#!/usr/bin/python3
"""Runs tutorials/paper/sandCompaction with './Allrun -reduced' (cells of
50 um) from a scratch copy and checks the behaviour the paper reports,
with numbers from summary.py:

    sandCompaction.py <binDir> <projectDir> <workDir>

  - the run ends with End, and the packing has come to rest: over the
    last quarter of the pseudo-time the platen moves by less than 1% of
    its whole displacement (a packing still collapsing moves on);
  - the grains traced from sandGrains.png are the image's: their
    porosity at the start is the image's, counted here from its pixels,
    within 0.005 (the traced outlines are simplified by 1.2 pixels);
  - the porosity falls by a clear margin: at least a fifth of the pore
    space is lost (the run loses about 40%; elastic compression of the
    grains would change the porosity by 1e-5);
  - it is a compaction by rearrangement, not by elasticity: the platen
    goes down by more than 1,000 times the elastic shortening of a solid
    quartz column as high as the sample, sigma (1 - nu^2)/E H = 18 nm in
    plane strain, i.e. by more than 18 um (it goes down about 260 um).
    Were the grains only to deform, the load would pass down chains of
    grains at a few MPa (the loaded grains' mean equivalent stress at
    the end is 1 to 5 MPa), shortening them by about 0.1 um, and the
    contact springs (50 E) would add nanometres;
  - the grains turn over: at least a third of them by more than 10
    degrees and one by more than 30 degrees (elastic rotations are of
    the order of the strain, 1e-5 rad; in every variant of the run tried,
    cells of 30 to 50 um and several step controls, 11 to 20 of the 27
    grains turned by more than 10 degrees and the largest by 40 to 99);
  - the largest compaction is on the looser side. Which half of the
    sample is looser is counted here from the image's pixels (not
    written into the test): the right half, 0.474 against 0.470, the
    difference carried by the right quarter, the loosest column of the
    image (0.54). The platen goes down further over the looser half and
    that half's porosity falls more. The halves differ little at the
    start, but the result held in every variant tried (the looser side
    went down by 2 to 107 um more; 91 um in the reduced run).
Without the load nothing moves and the porosity, displacement and
rotation checks fail. Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (the tutorial's plot step needs numpy,
matplotlib and VTK, which Debian installs for that interpreter only);
the image is read with matplotlib.
SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys

import paperTutorial


def halfPorosities(path):
    """Porosity of the left and the right half of a binary image (grains
    light: above half the range, as nmmImageToBlocks reads it)"""
    from matplotlib.image import imread
    pore = imread(str(path)) <= 127/255
    half = pore.shape[1]//2
    return pore[:, :half].mean(), pore[:, half:].mean()


def main(argv):
    case = paperTutorial.runReduced(argv, "sandCompaction", ["compaction"], __doc__)
    if case is None:
        return 1
    check = paperTutorial.checks()
    if not check.ended(case, ["compaction"]):
        return 1
    r = paperTutorial.summary(case)["compaction"]

    left, right = halfPorosities(case/"sandGrains.png")
    image = 0.5*(left + right)
    total = -r["platenDy_um"]
    check(abs(r["lastQuarterDy_um"]) < 0.01*total,
          "at rest: the platen moves %.2f um over the last quarter of the run, of %.1f um"
          % (abs(r["lastQuarterDy_um"]), total))
    check(abs(r["porosityStart"] - image) < 0.005,
          "porosity at the start %.4f, the image's %.4f" % (r["porosityStart"], image))
    check(r["porosityEnd"] < 0.8*r["porosityStart"],
          "porosity %.3f to %.3f: at least a fifth of the pore space lost"
          % (r["porosityStart"], r["porosityEnd"]))
    elastic = 1e6*(1 - 0.3**2)/50e9*1e-3*1e6
    check(total > 1000*elastic,
          "platen down %.1f um, over 1000 x the elastic %.4f um" % (total, elastic))
    check(r["grainsRotatedOver10deg"] >= r["grains"]/3,
          "%d of %d grains turn by more than 10 degrees"
          % (r["grainsRotatedOver10deg"], r["grains"]))
    check(r["maxGrainRotation_deg"] > 30,
          "largest grain rotation %.1f degrees" % r["maxGrainRotation_deg"])

    looser = "Right" if right > left else "Left"
    denser = "Left" if looser == "Right" else "Right"
    print("image: porosity of the left half %.4f, right half %.4f: the %s half is looser"
          % (left, right, looser.lower()))
    check(r["platen%sDy_um" % looser] < r["platen%sDy_um" % denser],
          "the platen goes further down over the looser half (%.1f um against %.1f um)"
          % (-r["platen%sDy_um" % looser], -r["platen%sDy_um" % denser]))
    lost = {side: r["porosity%sStart" % side] - r["porosity%sEnd" % side]
            for side in ("Left", "Right")}
    # More than rounding: without a load both losses are 0 to 1e-16
    check(lost[looser] > lost[denser] + 1e-6,
          "the looser half loses more porosity (%.3f against %.3f)"
          % (lost[looser], lost[denser]))
    return check.exitCode()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
