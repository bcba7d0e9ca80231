#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""A crack filled with a compressible fluid, coupled implicitly to the
solid through sneddonCrack.fmu: the fluid's pressure depends on the
crack's volume, and the crack's volume on the pressure.

Usage:
    fluidCrackMaster.py <sneddonCrack.fmu>

The fluid: a volume V0 per unit thickness at zero pressure, bulk modulus
K, so that in a crack of volume V its pressure is p = K (V0/V - 1). The
solid: the crack opens under p by Sneddon's w(s), a volume V = C p with
C = 2 pi (1 - nu^2) a^2/E. Together: C p^2 + K C p - K V0 = 0, whose
positive root is the hand solution.

The loop is the implicit coupling of an FMI importer: save the state;
then, until the residual r(p) = p - K (V0/V(p) - 1) is below 1e-12 of
p, restore the state, set crack.pressure, do the step, read the faces'
displacements and take the crack's volume from them; the next pressure
is the secant step on r. It prints each iteration and the converged p
and V against the hand solution.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import sys
from pathlib import Path

# The importer sits beside the tutorials (or in the project's copy)
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
if os.environ.get("NMM_PROJECT_DIR"):
    sys.path.append(os.path.join(os.environ["NMM_PROJECT_DIR"], "tutorials", "coupling"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import fmi3Master  # noqa: E402
import sneddonMaster as sm  # noqa: E402

K = 1e-3                # the fluid's bulk modulus (E = 1)
V0 = 6.75e-6            # the fluid's volume at zero pressure [m2]
TOLERANCE = 1e-12


def handSolution():
    C = 2*math.pi*(1 - sm.NU**2)*sm.A**2/sm.E
    p = (-K*C + math.sqrt((K*C)**2 + 4*C*K*V0))/(2*C)
    return p, C*p


def couple(path, log=print):
    """The converged (p, V) and the iterations it took"""
    fmu = fmi3Master.fmu(path)
    try:
        solid = fmu.initialized("fluidCrack")
        saved = solid.getState()

        def volume(p):
            solid.setState(saved)
            solid.set("crack.pressure", p)
            status, _ = solid.doStep(0.0, 1.0)
            if status != fmi3Master.OK:
                raise SystemExit("the step was not completed: " + solid.lastMessage())
            return sum(l*w for s, l, w in sm.openings(solid))

        def residual(p):
            V = volume(p)
            return p - K*(V0/V - 1), V

        # Two starting points: a guess, and the pressure the fluid would
        # have in the crack that guess opens
        p0, (r0, V) = 1e-4, residual(1e-4)
        p1 = K*(V0/V - 1)
        log("%4s %16s %16s %12s" % ("it", "p", "V", "r/p"))
        log("%4d %16.9e %16.9e %12.3e" % (1, p0, V, r0/p0))
        iterations = 1
        while True:
            r1, V = residual(p1)
            iterations += 1
            log("%4d %16.9e %16.9e %12.3e" % (iterations, p1, V, r1/p1))
            if abs(r1) < TOLERANCE*abs(p1) or iterations >= 20:
                break
            p0, p1, r0 = p1, p1 - r1*(p1 - p0)/(r1 - r0), r1
        solid.freeState(saved)
        solid.terminate()
        solid.free()
        return p1, V, iterations, abs(r1/p1)
    finally:
        fmu.remove()


def main():
    p, V, iterations, r = couple(sys.argv[1])
    pHand, VHand = handSolution()
    print("converged in %d iterations (residual %.1e of p)" % (iterations, r))
    print("pressure p = %.6e, hand solution %.6e, error %.2f %%"
          % (p, pHand, 100*(p/pHand - 1)))
    print("volume   V = %.6e, hand solution %.6e, error %.2f %%"
          % (V, VHand, 100*(V/VHand - 1)))


if __name__ == "__main__":
    main()
