#!/usr/bin/python3
"""Runs tutorials/paper/marbleFailure's two 11 MPa runs and the 110 MPa
run with strength ('./Allrun load11MPaStrength load11MPaNoStrength
load110MPaStrength') from a scratch copy and checks them against the
paper and against a Mohr-Coulomb estimate of the sample's strength from
the bonds' parameters, with numbers from summary.py:

    marbleFailure.py <binDir> <projectDir> <workDir>

The grain boundaries are bonded planes of every orientation (a Voronoi
polycrystal); under a uniaxial load sigma a plane whose normal is at
beta to the load carries sigma_n = sigma cos^2 beta and tau = sigma sin
beta cos beta, and slips when tau = c + sigma_n tan(phi). The weakest
plane, beta = 45 + phi/2, slips at the uniaxial compressive strength

    UCS = 2 c cos(phi)/(1 - sin(phi)) = 77.2 MPa (c 18 MPa, phi 40 deg),

and 0 without cohesion. The grains are elastic (E 85 GPa, nu 0.3, plane
strain), so a sample that stands shortens by sigma (1 - nu^2)/E x 1 mm.

  - all three runs end with End;
  - 11 MPa with strength (0.14 UCS; the paper: the sample stays intact):
    fewer than 5% of the closed contacts lose their bond (a few break at
    grain corners, where the stress is concentrated), and the top moves
    down by the elastic shortening, 0.118 um, within 10% (the grain
    boundaries' springs add a little compliance);
  - 110 MPa with strength (1.4 UCS; the paper: the right side breaks):
    the sample fails, its top moves down more than twice the elastic
    shortening at that load (1.18 um), and bonds break by the thousand:
    more than a quarter of the contacts closed at the end;
  - 11 MPa without strength (UCS 0; the paper: a fracture runs from top
    to bottom and the right side falls apart): the top moves down more
    than 1.15 times the elastic shortening, and grain boundaries open as
    the run goes on: at the end at least twice as many contacts are
    open as after the first step;
  - the contact frames tell broken bonds from intact ones and from
    contacts that never had one (bondBroken): without strength none is
    broken, none is both intact and broken, and at the end of the runs
    with strength there are no more broken ones than the bonds the log
    counts broken; at 110 MPa they are at least a tenth of the contact
    points.
Exit 1 when a check fails.

Debian's /usr/bin/python3 runs it (the tutorial's plot step needs numpy,
matplotlib and VTK, which Debian installs for that interpreter only).
SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import sys
from pathlib import Path

import paperTutorial

RUNS = ("load11MPaStrength", "load11MPaNoStrength", "load110MPaStrength")

# tutorials/paper/marbleFailure (the paper's section 4.4)
E, NU, HEIGHT = 85e9, 0.3, 1e-3
COHESION, FRICTION = 18e6, math.radians(40)


def elasticShortening_um(load):
    return load*(1 - NU**2)/E*HEIGHT*1e6


def bondPoints(run):
    """(points, broken, intact and broken) of the last contact frame of a
    run"""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
    import nmmVtk
    path = nmmVtk.readContactSeries(run)[-1][1]
    c = nmmVtk.readContacts(path)
    broken = c.data.get("bondBroken")
    if broken is None:
        raise SystemExit("%s: no point data 'bondBroken'" % path)
    broken = broken.reshape(-1) != 0
    intact = c.data["bondIntact"].reshape(-1) != 0
    return len(broken), int(broken.sum()), int((broken & intact).sum())


def checkBrokenBonds(check, case, rows):
    for run in ("load11MPaStrength", "load110MPaStrength"):
        n, broken, both = bondPoints(case/run)
        logged = rows[run]["bondsBroken"]
        check(both == 0, "%s: no contact both intact and broken (%d)" % (run, both))
        check(broken <= logged, "%s: %d contact points with a broken bond at the end, "
              "at most the %d the log counts" % (run, broken, logged))
        if run == "load110MPaStrength":
            check(broken >= 0.1*n, "%s: %d of %d contact points have a broken bond"
                  % (run, broken, n))
    _, broken, _ = bondPoints(case/"load11MPaNoStrength")
    check(broken == 0, "load11MPaNoStrength: no bonds, none broken (%d)" % broken)


def main(argv):
    case = paperTutorial.runReduced(argv, "marbleFailure", ["load*MPa*"], __doc__,
                                    allrunArgs=RUNS)
    if case is None:
        return 1
    check = paperTutorial.checks()
    if not check.ended(case, RUNS):
        return 1
    rows = paperTutorial.summary(case)
    ucs = 2*COHESION*math.cos(FRICTION)/(1 - math.sin(FRICTION))
    print("Mohr-Coulomb uniaxial strength of the bonded boundaries: %.1f MPa" % (ucs/1e6))

    s = rows["load11MPaStrength"]
    check(11e6 < ucs, "11 MPa is below the strength")
    check(s["bondsBroken"] < 0.05*s["closedEnd"],
          "11 MPa with strength: %d of %d bonds break" % (s["bondsBroken"], s["closedEnd"]))
    elastic = elasticShortening_um(11e6)
    check(0.9*elastic < -s["topDy_um"] < 1.1*elastic,
          "11 MPa with strength: top shortening %.3f um against %.3f um elastic"
          % (-s["topDy_um"], elastic))

    f = rows["load110MPaStrength"]
    check(110e6 > ucs, "110 MPa is above the strength")
    elastic = elasticShortening_um(110e6)
    check(-f["topDy_um"] > 2*elastic,
          "110 MPa with strength: the sample fails, top shortening %.3f um against "
          "%.3f um elastic" % (-f["topDy_um"], elastic))
    check(f["bondsBroken"] > 0.25*f["closedEnd"],
          "110 MPa with strength: %d bonds break (%d contacts closed at the end)"
          % (f["bondsBroken"], f["closedEnd"]))

    n = rows["load11MPaNoStrength"]
    elastic = elasticShortening_um(11e6)
    check(-n["topDy_um"] > 1.15*elastic,
          "11 MPa without strength: top shortening %.3f um, beyond %.3f um elastic"
          % (-n["topDy_um"], elastic))
    check(n["openEnd"] >= 2*n["openFirstStep"],
          "11 MPa without strength: boundaries open, %d open contacts after the first "
          "step, %d at the end" % (n["openFirstStep"], n["openEnd"]))
    checkBrokenBonds(check, case, rows)
    return check.exitCode()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
