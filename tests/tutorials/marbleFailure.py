#!/usr/bin/python3
"""Runs tutorials/paper/marbleFailure with './Allrun -reduced' (only
the two 11 MPa runs) from a scratch copy and checks the behaviour
the paper reports, with numbers from summary.py:

    marbleFailure.py <binDir> <projectDir> <workDir>

  - both runs end with End;
  - with the bonds' strength (cohesion 18 MPa, tensile strength 28 MPa)
    the sample stays intact: fewer than 5% of the closed contacts lose
    their bond (a few break at grain corners, where the stress is
    concentrated), and the top moves down by the elastic shortening of
    an intact sample, sigma (1 - nu^2)/E x height = 0.118 um in plane
    strain, within 10% (the grain boundaries' springs add a little
    compliance);
  - without it (friction only) grain boundaries open: at the end at
    least twice as many contacts are open as with strength, the largest
    displacement is larger (the grains move apart), and the top moves
    down more than 1.15 times the elastic shortening.
Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (the tutorial's plot step needs numpy,
matplotlib and VTK, which Debian installs for that interpreter only).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys

import paperTutorial


def main(argv):
    case = paperTutorial.runReduced(argv, "marbleFailure", ["load*MPa*"], __doc__)
    if case is None:
        return 1
    check = paperTutorial.checks()
    if not check.ended(case, ("load11MPaStrength", "load11MPaNoStrength")):
        return 1
    rows = paperTutorial.summary(case)

    s, n = rows["load11MPaStrength"], rows["load11MPaNoStrength"]
    check(s["bondsBroken"] < 0.05*s["closedEnd"],
          "11 MPa with strength: %d of %d bonds break" % (s["bondsBroken"], s["closedEnd"]))
    check(n["openEnd"] >= 2*s["openEnd"],
          "11 MPa without strength: twice the open contacts (%d against %d)"
          % (n["openEnd"], s["openEnd"]))
    check(n["maxD_um"] > s["maxD_um"],
          "11 MPa without strength: the grains move further apart")
    elastic = 11e6*(1 - 0.3**2)/85e9*1e-3*1e6
    check(-n["topDy_um"] > 1.15*elastic,
          "11 MPa without strength: top shortening %.3f um, beyond elastic" % -n["topDy_um"])
    check(0.9*elastic < -s["topDy_um"] < 1.1*elastic,
          "11 MPa with strength: top shortening %.3f um against %.3f um elastic"
          % (-s["topDy_um"], elastic))
    return check.exitCode()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
