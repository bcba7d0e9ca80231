# Needs Debian's /usr/bin/python3 (numpy from python3-numpy).
"""Closed-form solutions of the continuum verification cases.

Every function takes undeformed coordinates (numpy arrays) and returns
numpy arrays; stresses are (sxx, syy, sxy) in the plane. The parameters are
tutorials/verification/caseParameters.py's, from which makeCases.py writes
the cases (docs/verification.md, Continuum and Contact); each class here
adds the closed form to its case's parameters.

The formulas are checked on their own by selfTest.py: Hooke's law applied
to the strain of the displacement field (finite differences) must give the
stress field, the stress field must be in equilibrium, and the headline
numbers of docs/verification.md must come out.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"tutorials"/"verification"))
import caseParameters as cp  # noqa: E402


def planeModuli(E, nu, planeStress):
    """Plane Hooke's law: (lambda*, mu) such that
    sigma = lambda* tr(eps) I + 2 mu eps in the plane."""
    mu = E/(2*(1 + nu))
    lam = E*nu/((1 + nu)*(1 - 2*nu))
    if planeStress:
        lam = 2*lam*mu/(lam + 2*mu)
    return lam, mu


# --------------------------------------------------------------------------
# Cantilever with end shear (Timoshenko and Goodier), plane stress.
# Beam 0 <= x <= L, -D/2 <= y <= D/2; exact displacements at x = 0,
# parabolic shear traction at x = L whose resultant is +P (upward, +y):
# with these displacements the tip moves up by
# P L^3/(3EI) + (4+5nu) P D^2 L/(24 E I).
# --------------------------------------------------------------------------
class cantilever(cp.cantilever):
    I = cp.cantilever.D**3/12

    @classmethod
    def displacement(cls, x, y):
        L, D, E, nu, P, I = cls.L, cls.D, cls.E, cls.nu, cls.P, cls.I
        ux = -P*y/(6*E*I)*((6*L - 3*x)*x + (2 + nu)*(y*y - D*D/4))
        uy = P/(6*E*I)*(3*nu*y*y*(L - x) + (4 + 5*nu)*D*D*x/4
                        + (3*L - x)*x*x)
        return ux, uy

    @classmethod
    def stress(cls, x, y):
        L, D, P, I = cls.L, cls.D, cls.P, cls.I
        sxx = -P*(L - x)*y/I
        syy = 0*x*y
        sxy = P/(2*I)*(D*D/4 - y*y)
        return sxx, syy, sxy

    @classmethod
    def tipDeflection(cls):
        return cls.displacement(np.float64(cls.L), np.float64(0.0))[1]


# --------------------------------------------------------------------------
# Plate with a circular hole (Kirsch), infinite plate under sigma in x,
# quarter model 0 <= x, y <= 5 minus the disc r < a, plane strain.
# --------------------------------------------------------------------------
class kirsch(cp.kirsch):

    @classmethod
    def kappa(cls):
        if cls.planeStress:
            return (3 - cls.nu)/(1 + cls.nu)
        return 3 - 4*cls.nu

    @classmethod
    def displacement(cls, x, y):
        a, S = cls.a, cls.S
        mu = cls.E/(2*(1 + cls.nu))
        k = cls.kappa()
        r = np.hypot(x, y)
        t = np.arctan2(y, x)
        c = S*a/(8*mu)
        ux = c*(r/a*(k + 1)*np.cos(t)
                + 2*a/r*((1 + k)*np.cos(t) + np.cos(3*t))
                - 2*a**3/r**3*np.cos(3*t))
        uy = c*(r/a*(k - 3)*np.sin(t)
                + 2*a/r*((1 - k)*np.sin(t) + np.sin(3*t))
                - 2*a**3/r**3*np.sin(3*t))
        return ux, uy

    @classmethod
    def stress(cls, x, y):
        a, S = cls.a, cls.S
        r2 = x*x + y*y
        t = np.arctan2(y, x)
        q2 = a*a/r2
        q4 = q2*q2
        sxx = S*(1 - q2*(1.5*np.cos(2*t) + np.cos(4*t)) + 1.5*q4*np.cos(4*t))
        syy = S*(-q2*(0.5*np.cos(2*t) - np.cos(4*t)) - 1.5*q4*np.cos(4*t))
        sxy = S*(-q2*(0.5*np.sin(2*t) + np.sin(4*t)) + 1.5*q4*np.sin(4*t))
        return sxx, syy, sxy

    @classmethod
    def peak(cls):
        """sigma_xx at (0, a): 3 sigma"""
        return cls.stress(np.float64(0.0), np.float64(cls.a))[0]


# --------------------------------------------------------------------------
# Thick cylinder under inner pressure (Lame), quarter ring a <= r <= b,
# plane strain.
# --------------------------------------------------------------------------
class lame(cp.lame):

    @classmethod
    def AB(cls):
        a, b, p = cls.a, cls.b, cls.p
        return p*a*a/(b*b - a*a), p*a*a*b*b/(b*b - a*a)

    @classmethod
    def radialDisplacement(cls, r):
        A, B = cls.AB()
        E, nu = cls.E, cls.nu
        if cls.planeStress:
            return ((1 - nu)*A*r + (1 + nu)*B/r)/E
        return (1 + nu)/E*((1 - 2*nu)*A*r + B/r)

    @classmethod
    def displacement(cls, x, y):
        r = np.hypot(x, y)
        ur = cls.radialDisplacement(r)
        return ur*x/r, ur*y/r

    @classmethod
    def polarStress(cls, r):
        A, B = cls.AB()
        return A - B/(r*r), A + B/(r*r)

    @classmethod
    def stress(cls, x, y):
        r = np.hypot(x, y)
        srr, stt = cls.polarStress(r)
        c, s = x/r, y/r
        return (srr*c*c + stt*s*s, srr*s*s + stt*c*c, (srr - stt)*s*c)


# --------------------------------------------------------------------------
# Pressurised crack (Sneddon), plane strain: total opening
# w(s) = 4 p (1 - nu^2)/E sqrt(a^2 - s^2), s along the crack from its centre.
# --------------------------------------------------------------------------
class sneddon(cp.sneddon):

    @classmethod
    def Eprime(cls):
        if cls.planeStress:
            return cls.E
        return cls.E/(1 - cls.nu**2)

    @classmethod
    def opening(cls, s):
        return 4*cls.p/cls.Eprime()*np.sqrt(np.maximum(cls.a**2 - s*s, 0.0))

    @classmethod
    def centreOpening(cls):
        return float(cls.opening(np.float64(0.0)))


# --------------------------------------------------------------------------
# Free fall: one unsupported block under gravity from rest.
# --------------------------------------------------------------------------
class freeFall(cp.freeFall):

    @classmethod
    def displacementY(cls, t):
        return -0.5*cls.g*t*t

    @classmethod
    def velocityY(cls, t):
        return -cls.g*t


# --------------------------------------------------------------------------
# 1D wave in a bar: step pressure p0 on the end x = 0 from t = 0, nu = 0 so
# that the plane stress bar is exactly one-dimensional and c = sqrt(E/rho).
# Behind the front: sigma_xx = -p0, u_x = p0/E (c t - x), U_x = p0 c/E.
# --------------------------------------------------------------------------
class waveBar(cp.waveBar):

    @classmethod
    def c(cls):
        return math.sqrt(cls.E/cls.rho)

    @classmethod
    def arrivalTime(cls, x=None):
        return (cls.station if x is None else x)/cls.c()

    @classmethod
    def displacementX(cls, x, t):
        return cls.p0/cls.E*np.maximum(cls.c()*t - x, 0.0)

    @classmethod
    def velocityX(cls, x, t):
        return np.where(cls.c()*t > x, cls.p0*cls.c()/cls.E, 0.0)


# --------------------------------------------------------------------------
# Contact cases (docs/verification.md, Contact)
# --------------------------------------------------------------------------
def searchDistance(halfSize, maxDisplacementRatio=0.005):
    """The solver's automatic contact search distance (nmmSolidModel::
    createContacts): 2.5 maxDisplacementRatio half the larger side of the
    model's bounding box."""
    return 2.5*maxDisplacementRatio*halfSize


def allowedPenetration(halfSize, maxDisplacementRatio=0.005):
    """The largest penetration a step may end with: 0.4 search distance."""
    return 0.4*searchDistance(halfSize, maxDisplacementRatio)


# --------------------------------------------------------------------------
# Block on an incline at a to the horizontal, dry friction phi, from rest:
# d(t) = g (sin a - cos a tan phi) t^2/2 while tan phi < tan a, else 0.
# --------------------------------------------------------------------------
class incline(cp.incline):

    @classmethod
    def slides(cls, phi):
        return math.tan(math.radians(phi)) < math.tan(math.radians(cls.a))

    @classmethod
    def acceleration(cls, phi):
        if not cls.slides(phi):
            return 0.0
        a = math.radians(cls.a)
        return cls.g*(math.sin(a) - math.cos(a)*math.tan(math.radians(phi)))

    @classmethod
    def displacement(cls, phi, t):
        return 0.5*cls.acceleration(phi)*t*t


# --------------------------------------------------------------------------
# Sliding vs toppling: a rigid b x h block from rest on the incline of
# incline (a = 30 degrees), dry friction phi. Static criteria: it slides
# when tan a > tan phi, topples when tan a > b/h. Toppling without sliding,
# it turns clockwise (downhill, x downslope) by theta about its downhill
# bottom corner: I theta'' = M(theta), I = m (b^2 + h^2)/3,
#   M = m g/2 [(h sin a - b cos a) cos theta + (h cos a + b sin a) sin theta];
# linearised in theta, theta(t) = alpha0/k (cosh(sqrt(k) t) - 1).
# --------------------------------------------------------------------------
class topple(cp.topple):
    maxRotation = 1e-3  # [rad] of the stable and the sliding block
    rotationTolerance = 0.03
    slipRatio = 0.05    # pivot's x displacement / the top corner's

    @classmethod
    def slides(cls, regime):
        b, h, phi = cls.regimes[regime]
        return math.tan(math.radians(phi)) < math.tan(math.radians(cls.a))

    @classmethod
    def topples(cls, regime):
        b, h, phi = cls.regimes[regime]
        return b/h < math.tan(math.radians(cls.a))

    @classmethod
    def displacement(cls, regime, t):
        """Slide d(t) along x (0 unless sliding without toppling)."""
        if not cls.slides(regime) or cls.topples(regime):
            return 0.0
        return incline.displacement(cls.regimes[regime][2], t)

    @classmethod
    def alpha0(cls, regime):
        """Angular acceleration from rest about the downhill corner."""
        b, h, phi = cls.regimes[regime]
        a = math.radians(cls.a)
        return 3*cls.g*(h*math.sin(a) - b*math.cos(a))/(2*(b*b + h*h))

    @classmethod
    def k(cls, regime):
        """d(moment)/d(theta)/I at theta = 0 [1/s^2]."""
        b, h, phi = cls.regimes[regime]
        a = math.radians(cls.a)
        return 3*cls.g*(h*math.cos(a) + b*math.sin(a))/(2*(b*b + h*h))

    @classmethod
    def rotation(cls, regime, t):
        """Clockwise rotation theta(t) (0 unless toppling without sliding)."""
        if cls.slides(regime) or not cls.topples(regime):
            return 0.0
        return cls.alpha0(regime)/cls.k(regime)*(math.cosh(math.sqrt(cls.k(regime))*t) - 1)

    @classmethod
    def pivotFriction(cls, regime):
        """Friction over normal force the pivot needs at the start."""
        b, h, phi = cls.regimes[regime]
        a = math.radians(cls.a)
        al = cls.alpha0(regime)
        return abs(al*h/2 - cls.g*math.sin(a))/(al*b/2 + cls.g*math.cos(a))


# --------------------------------------------------------------------------
# Bouncing block: a rigid 1 x 1 block dropped from h0 onto a fixed base
# through frictionless penalty springs (kN per closed contact point, all in
# parallel for a vertical impact): omega = sqrt(n kN/m). Elastic contact
# conserves energy, so every rebound reaches h0 (trapezoidal rule).
# --------------------------------------------------------------------------
class bouncingBlock(cp.bouncingBlock):
    trapezoidalTolerance = 0.03     # rebound height / h0
    energyDriftPerBounce = 0.01

    @classmethod
    def mass(cls):
        return cls.rho*cls.area

    @classmethod
    def impactSpeed(cls):
        return math.sqrt(2*cls.g*cls.h0)

    @classmethod
    def impactTime(cls):
        return math.sqrt(2*cls.h0/cls.g)

    @classmethod
    def omega(cls, nContacts):
        return math.sqrt(nContacts*cls.normalPenalty/cls.mass())


# --------------------------------------------------------------------------
# Block bonded to a fixed base (cohesion c, friction phi over the length L),
# pushed horizontally by F(t) = rate t; weight W = m g. The bond breaks at
# F = c L + W tan phi; then m x'' = F - W tan phi.
# --------------------------------------------------------------------------
class pushedBlock(cp.pushedBlock):

    @classmethod
    def onsetForce(cls):
        return cls.c*cls.L + cls.W*math.tan(math.radians(cls.phi))

    @classmethod
    def onsetTime(cls):
        return cls.onsetForce()/cls.rate

    @classmethod
    def loadIncrement(cls):
        return cls.rate*cls.deltaT

    @classmethod
    def displacement(cls, t, t0=None):
        """x(t) after the onset at t0 (from rest): m x'' = rate t - W tan phi."""
        t0 = cls.onsetTime() if t0 is None else t0
        s = max(t - t0, 0.0)
        f0 = cls.rate*t0 - cls.W*math.tan(math.radians(cls.phi))
        return (cls.rate*s**3/6 + f0*s*s/2)/cls.m


# --------------------------------------------------------------------------
# Stick-slip under a harmonic load (Potra's benchmark): a rigid block of
# mass m, m x'' = F0 cos(omega t) - mu m g sgn(x') while it slides; it
# sticks while |F| <= mu m g. Piecewise in closed form: a slip from rest at
# t0 in the direction s of F(t0) has
#     v(t) = F0/omega (sin omega t - sin omega t0)/m - s mu g (t - t0)
# and ends at the first root of v after t0; the stick after it ends when
# |F| next exceeds mu m g.
# --------------------------------------------------------------------------
class stickSlip(cp.stickSlip):

    @classmethod
    def force(cls, t):
        return cls.F0*math.cos(cls.omega*t)

    @classmethod
    def friction(cls):
        return cls.mu*cls.m*cls.g

    @classmethod
    def slipVelocity(cls, t0, s, t):
        w = cls.omega
        return (cls.F0/w*(math.sin(w*t) - math.sin(w*t0))/cls.m
                - s*cls.mu*cls.g*(t - t0))

    @classmethod
    def slipDisplacement(cls, t0, s, t):
        """x(t) - x(t0) of a slip from rest at t0 in the direction s."""
        w, dt = cls.omega, t - t0
        return (cls.F0/w*((math.cos(w*t0) - math.cos(w*t))/w - math.sin(w*t0)*dt)/cls.m
                - s*cls.mu*cls.g*dt*dt/2)

    @staticmethod
    def _root(f, a, b):
        """The root of f between a and b (f(a) f(b) <= 0), by bisection to
        rounding."""
        fa = f(a)
        for _ in range(200):
            c = 0.5*(a + b)
            fc = f(c)
            if fa*fc <= 0:
                b = c
            else:
                a, fa = c, fc
            if b - a < 1e-14*max(1.0, abs(b)):
                break
        return 0.5*(a + b)

    @classmethod
    def _nextSlipStart(cls, t):
        """The first time >= t at which |F| exceeds the friction."""
        limit, h = cls.friction(), 1e-3
        over = lambda u: abs(cls.force(u)) - limit  # noqa: E731
        if over(t) > 0:
            return t
        while t < cls.endTime and over(t + h) <= 0:
            t += h
        if t >= cls.endTime:
            return None
        return cls._root(over, t, t + h)

    @classmethod
    def windows(cls):
        """[(start, end, direction, x at start)] of the slips up to
        endTime; x is 0 at t = 0."""
        result, t, x, h = [], 0.0, 0.0, 1e-3
        while True:
            t0 = cls._nextSlipStart(t)
            if t0 is None:
                return result
            s = 1.0 if cls.force(t0) > 0 else -1.0
            v = lambda u: cls.slipVelocity(t0, s, u)  # noqa: E731
            # The velocity leaves zero in the direction s; the slip ends
            # where it returns (the first sign change)
            u = t0 + h
            while u < cls.endTime and s*v(u) > 0:
                u += h
            t1 = cls._root(v, u - h, u) if u < cls.endTime else cls.endTime
            result.append((t0, t1, s, x))
            x += cls.slipDisplacement(t0, s, t1)
            if t1 >= cls.endTime:
                return result
            t = t1 + 1e-9

    @classmethod
    def position(cls, t, windows=None):
        """x(t): the plateau of the last slip before t, or within a slip
        (windows: those of windows(), to reuse them)."""
        x = 0.0
        for t0, t1, s, x0 in (windows or cls.windows()):
            if t < t0:
                return x
            if t <= t1:
                return x0 + cls.slipDisplacement(t0, s, t)
            x = x0 + cls.slipDisplacement(t0, s, t1)
        return x

    @classmethod
    def plateaus(cls):
        """[(from, to, x)]: the position held between two slips (to the
        end time after the last)."""
        w = cls.windows()
        result = []
        for i, (t0, t1, s, x0) in enumerate(w):
            end = w[i + 1][0] if i + 1 < len(w) else cls.endTime
            if t1 < end:
                result.append((t1, end, x0 + cls.slipDisplacement(t0, s, t1)))
        return result


if __name__ == "__main__" and sys.argv[1:] == ["stickSlip"]:
    for t0, t1, s, x0 in stickSlip.windows():
        print("slip %+d: %.6f .. %.6f s, from x = %.6e m" % (s, t0, t1, x0))
    for a, b, x in stickSlip.plateaus():
        print("plateau %.6f .. %.6f s: x = %.6e m" % (a, b, x))


# --------------------------------------------------------------------------
# Contact cases loaded in steps (tutorials/verification/contact/): plane
# strain throughout.
# --------------------------------------------------------------------------

# --------------------------------------------------------------------------
# Hertz, cylinder on a flat (2D): contact half-width a = sqrt(4 P R/(pi E*)),
# p(x) = p0 sqrt(1 - x^2/a^2), p0 = 2P/(pi a), 1/E* = sum (1 - nu_i^2)/E_i
# (plane strain), P the load per unit thickness. The flat is stiff
# (E = 1e4), not rigid; its compliance is in E*.
# --------------------------------------------------------------------------
class hertz(cp.hertz):

    @classmethod
    def Reff(cls):
        return cls.R

    @classmethod
    def Estar(cls):
        return 1/((1 - cls.nu1**2)/cls.E1 + (1 - cls.nu2**2)/cls.E2)

    @classmethod
    def halfWidth(cls):
        return math.sqrt(4*cls.P*cls.Reff()/(math.pi*cls.Estar()))

    @classmethod
    def peakPressure(cls):
        return 2*cls.P/(math.pi*cls.halfWidth())

    @classmethod
    def pressure(cls, x):
        a = cls.halfWidth()
        return cls.peakPressure()*np.sqrt(np.maximum(1 - (x/a)**2, 0.0))


# Two identical discs (R1 = R2 = 1, both E = 1): R = R1 R2/(R1 + R2) = 1/2,
# E* halved: a and p0 come out as for the cylinder on the (stiff) flat
class discOnDisc(hertz, cp.discOnDisc):

    @classmethod
    def Reff(cls):
        return cls.R1*cls.R2/(cls.R1 + cls.R2)


# --------------------------------------------------------------------------
# Brazilian disc: two opposite point loads P (per unit thickness t) on the
# vertical diameter of a disc of diameter D (centre at the origin): the
# superposition of two Flamant solutions and a uniform tension 2P/(pi D t)
# (Frocht; Jaeger and Cook). At the centre sigma_x = 2P/(pi D t) (tension),
# sigma_y = -6P/(pi D t).
# --------------------------------------------------------------------------
class brazilian(cp.brazilian):

    @classmethod
    def centreTension(cls):
        return 2*cls.P/(math.pi*cls.D*cls.t)

    @classmethod
    def stress(cls, x, y):
        R = cls.D/2
        k = -2*cls.P/(math.pi*cls.t)
        r1 = (x*x + (R - y)**2)**2
        r2 = (x*x + (R + y)**2)**2
        sxx = k*((R - y)*x*x/r1 + (R + y)*x*x/r2 - 1/cls.D)
        syy = k*((R - y)**3/r1 + (R + y)**3/r2 - 1/cls.D)
        sxy = -k*((R - y)**2*x/r1 - (R + y)**2*x/r2)
        return sxx, syy, sxy


# --------------------------------------------------------------------------
# Bonded interface of length L (Mohr-Coulomb bond that breaks for good):
# in tension it breaks when the normal force reaches T L; in shear under a
# normal stress sigma_n the peak shear force is c L + sigma_n L tan(phi),
# the residual after the break sigma_n L tan(phi). Forces per unit thickness.
# --------------------------------------------------------------------------
class bondedInterface(cp.bondedInterface):

    @classmethod
    def tensionPeak(cls):
        return cls.T*cls.L

    @classmethod
    def shearPeak(cls, sigma):
        return cls.c*cls.L + sigma*cls.L*math.tan(math.radians(cls.phi))

    @classmethod
    def shearResidual(cls, sigma):
        return sigma*cls.L*math.tan(math.radians(cls.phi))
