"""The physical parameters of the verification cases (docs/verification.md):
makeCases.py writes the cases from them and tests/verification/closedForms.py
computes the closed-form answers from them, so that the two cannot
disagree. Plain python3, standard library only (makeCases.py needs no
more); units SI unless a case says otherwise.

After changing a value here, run makeCases.py and commit the cases it
rewrites.

SPDX-License-Identifier: GPL-3.0-or-later
"""


# --------------------------------------------------------------------------
# Continuum cases
# --------------------------------------------------------------------------
class cantilever:
    """Beam 0 <= x <= L, -D/2 <= y <= D/2, end shear P, plane stress."""
    L = 48.0
    D = 12.0
    E = 3e7
    nu = 0.3
    rho = 1.0
    P = 1000.0
    planeStress = True


class kirsch:
    """tutorials/verification/plateHole: quarter plate side x side minus
    the hole r < a, sigma S in x on the far edges, plane strain."""
    a = 1.0
    side = 5.0
    S = 1.0
    E = 1000.0
    nu = 0.3
    rho = 1.0
    planeStress = False


class lame:
    """Quarter ring a <= r <= b under inner pressure p, plane strain."""
    a = 0.1
    b = 0.2
    p = 10e6
    E = 10e9
    nu = 0.25
    rho = 7800.0
    planeStress = False


class sneddon:
    """Crack of half-length a in a side x side plate, pressure p on its
    faces, at each of the angles to x, plane strain."""
    a = 0.1
    side = 2.0          # 20 a, centred on the crack
    E = 1.0
    nu = 0.15
    rho = 1.0
    p = 1.0
    planeStress = False
    angles = (0.0, 30.0, 45.0)


class freeFall:
    """A 1 x 1 block from rest under gravity g, nSteps of deltaT."""
    g = 9.81
    deltaT = 0.01
    nSteps = 10
    E = 1e8
    nu = 0.3
    rho = 2000.0


class waveBar:
    """Bar L x H, step pressure p0 on x = 0, the far end fixed; the
    displacement is compared at x = station."""
    L = 10.0
    H = 0.5
    E = 1e9
    nu = 0.0
    planeStress = True
    rho = 1000.0
    p0 = 1e6
    station = 5.0
    deltaT = 5e-5
    endTime = 1e-2


# --------------------------------------------------------------------------
# Contact cases
# --------------------------------------------------------------------------
class incline:
    """Block on a base, gravity g tilted by a (degrees) so that the base's
    top face is the incline; friction angles phis."""
    a = 30.0            # degrees
    g = 9.81
    phis = (0, 10, 20, 29, 31)
    maxDisplacementRatio = 0.005


class topple:
    """A b x h block on the incline of incline, its uphill bottom corner
    at (x0, 0); regime -> (b, h, phi)."""
    a = incline.a
    g = incline.g
    maxDisplacementRatio = incline.maxDisplacementRatio
    regimes = {"stable": (1.0, 1.0, 40.0), "sliding": (1.0, 1.0, 20.0),
               "toppling": (0.25, 1.0, 40.0)}     # b, h, phi
    x0 = 0.25


class bouncingBlock:
    """A block of the given area dropped from h0 onto a fixed base through
    penalty springs of normalPenalty per contact point."""
    h0 = 1.0
    g = 9.81
    rho = 2000.0
    area = 1.0
    normalPenalty = 5e6
    deltaT = 1e-3


class pushedBlock:
    """Block of weight W (mass m) bonded over the length L to a fixed base
    (cohesion c, friction angle phi), pushed by F(t) = rate t."""
    L = 1.0
    W = 1.0
    m = 1.0
    c = 0.1
    phi = 30.0
    rate = 1.0          # N/m per s
    deltaT = 0.01


class stickSlip:
    """Block of mass m (L x L, density m/L^2) on a fixed base, dry friction
    mu, pushed by F(t) = F0 cos(omega t) to endTime (Potra's benchmark)."""
    L = 1.0
    m = 1.0
    g = 9.81
    mu = 0.8
    F0 = 8.0
    omega = 1.0
    endTime = 10.0
    deltaT = 6.25e-4
    E = 1e9


class hertz:
    """Cylinder of radius R (E1, nu1) on a flat (E2, nu2), P per unit
    thickness; fine, fineLength, coarse: the chords of the boundaries."""
    R = 1.0             # cylinder radius
    P = 0.01            # load per unit thickness [N/m]
    E1, nu1 = 1.0, 0.3          # cylinder
    E2, nu2 = 1e4, 0.3          # flat
    thickness = 1.0
    fine = 0.005
    fineLength = 0.25
    coarse = 0.05


class discOnDisc(hertz):
    """Two identical discs of radii R1 = R2 = R."""
    R1 = hertz.R
    R2 = hertz.R
    E2, nu2 = hertz.E1, hertz.nu1


class brazilian:
    """Disc of diameter D (E, nu), P per unit thickness t, through a steel
    platen (Eplaten) platenWidth x platenHeight."""
    D = 0.05
    t = 1.0
    P = 1e5
    E, nu = 20e9, 0.25
    Eplaten = 200e9
    platenWidth = 0.01
    platenHeight = 0.005


class bondedInterface:
    """Bonded interface of length L: tensile strength T, cohesion c,
    friction angle phi; shear under each normal stress of sigmas; the
    load reaches the peak in stepsToPeak steps, extraSteps after it."""
    L = 1.0
    T = 1e6
    c = 2e6
    phi = 30.0
    sigmas = (0.0, 1e6, 5e6)
    stepsToPeak = 40
    extraSteps = 5
