#!/usr/bin/env python3
"""Write the case files of the continuum verification tutorials.

Usage (from anywhere; plain python3, standard library only):
    tutorials/verification/makeCases.py

Writes system/, constant/ and 0/ of cantilever, plateHole, plateHoleFoam,
lame, freeFall, waveBar and sneddon/angle{0,30,45}; and the whole of the
contact cases (docs/verification.md, Contact) under contact/:
incline/phi{0,10,20,29,31}, topple/{stable,sliding,toppling},
pushedBlock, stickSlip, bouncingBlock/{trapezoidal,DDA} (their Allrun, Allclean and
README.md too). The files it writes
are committed, so running it is only needed after changing a parameter
here or in caseParameters.py (the physical parameters, which
tests/verification/closedForms.py shares); the README of each case
explains the choices. The polygons of the
curved boundaries are written out in full (64 chords per quarter circle,
256 for the plates with a hole).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
from pathlib import Path

import caseParameters as cp

HERE = Path(__file__).resolve().parent
NARC = 64           # chords per quarter circle


def header(location, obj, cls="dictionary"):
    return """/*--------------------------------*- C++ -*----------------------------------*\\
  nmmSolid: Numerical Manifold Method for deformable geomaterials
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

""" % (cls, location, obj)


FOOTER = "\n// ************************************************************************* //\n"


def pt(p):
    return "(%s %s)" % (fmt(p[0]), fmt(p[1]))


def fmt(v):
    v = float(v)
    if abs(v) < 1e-15:
        return "0"
    r = repr(v)
    return r[:-2] if r.endswith(".0") else r


def num(v):
    """A parameter as a dictionary spells it: large and small magnitudes as
    mantissa and exponent (3e7), the rest plainly (0.25); 12 significant
    digits, so that a coefficient computed from the parameters (3 nu) is
    written as the number it stands for (0.9)."""
    v = float(v)
    if v != 0 and not 1e-4 <= abs(v) < 1e4:
        m, e = ("%.11e" % v).split("e")
        return "%se%d" % (m.rstrip("0").rstrip("."), int(e))
    return "%.12g" % v


def polygon(points, indent="        "):
    lines = []
    for i in range(0, len(points), 3):
        lines.append(indent + "    " + " ".join(pt(p) for p in points[i:i + 3]))
    return "\n" + indent + "(\n" + "\n".join(lines) + "\n" + indent + ")"


def write(case, rel, location, obj, body, cls="dictionary"):
    path = HERE/case/rel
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(header(location, obj, cls) + body + FOOTER)


def controlDict(case, endTime, deltaT, comment, writeInterval=None, adjust=False,
                functions=""):
    """Every step written (writeInterval None), or every writeInterval of
    run time on adjusted steps; functions: the entries of 'functions'"""
    write(case, "system/controlDict", "system", "controlDict", """\
// %s
application     nmmSolidFoam;

startFrom       startTime;

startTime       0;

stopAt          endTime;

endTime         %s;

deltaT          %s;

writeControl    %s;

writeInterval   %s;

purgeWrite      0;

writeFormat     binary;         // VTK frames exact and compact

writePrecision  12;

timeFormat      general;

timePrecision   8;

runTimeModifiable yes;

adjustTimeStep  %s;

functions
{
%s}
""" % (comment, endTime, deltaT,
       "timeStep" if writeInterval is None else "adjustableRunTime",
       1 if writeInterval is None else writeInterval, "yes" if adjust else "no",
       functions))


def staticSolution(case, smallDisplacement=False):
    extra = """
// The closed form is linear elasticity: no geometry update
largeDisplacement no;
""" if smallDisplacement else ""
    write(case, "system/nmmSolution", "system", "nmmSolution", """\
analysis        static;

linearSolver    { type cholmod; }
""" + extra)


def mechanicalProperties(case, planeStress, name, E, nu, rho):
    write(case, "constant/mechanicalProperties", "constant", "mechanicalProperties",
          """\
planeStress     %s;

thickness       1;

materials
{
    %s { type linearElastic; E %s; nu %s; rho %s; }
}
""" % ("yes" if planeStress else "no", name, E, nu, rho))


def D(case, patches):
    write(case, "0/D", "0", "D", """\
dimensions      [0 1 0 0 0 0 0];

internalField   uniform (0 0 0);

boundaryField
{
%s}
""" % patches, cls="volVectorField")


def U(case, internalField, comment=""):
    """The initial velocity (0/U): internalField's text, e.g.
    'uniform (20 0 0)' or 'expression "vector(-y, x, 0)"'"""
    write(case, "0/U", "0", "U", comment + """\
dimensions      [0 1 -1 0 0 0 0];

internalField   %s;
""" % internalField, cls="volVectorField")


def contactProperties(case, frictionAngle, comment=""):
    write(case, "constant/contactProperties", "constant", "contactProperties",
          comment + """\
default
{
    law             mohrCoulomb;
    frictionAngle   %s;
}
""" % frictionAngle)


def meshDict(case, blocks, patches, cover, joints=None):
    body = "blocks\n(\n%s);\n\n" % blocks
    if joints:
        body += "joints\n(\n%s);\n\n" % joints
    body += "patches\n{\n%s}\n\ncover\n{\n%s}\n" % (patches, cover)
    write(case, "system/nmmMeshDict", "system", "nmmMeshDict", body)


def arc(r, t0, t1, n, ends=False):
    """Points on a circle of radius r from angle t0 to t1 (n chords);
    the end points only when ends."""
    ks = range(0, n + 1) if ends else range(1, n)
    return [(r*math.cos(t0 + (t1 - t0)*k/n), r*math.sin(t0 + (t1 - t0)*k/n))
            for k in ks]


# --------------------------------------------------------------------------
def cantilever():
    c = "cantilever"
    p = cp.cantilever
    L, h, nu = p.L, p.D/2, p.nu
    I = p.D**3/12
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    staticSolution(c, smallDisplacement=True)
    mechanicalProperties(c, p.planeStress, "beam", num(p.E), num(nu), num(p.rho))
    meshDict(c, """\
    beam { material beam; polygon (%s %s %s %s); }
""" % (pt((0, -h)), pt((L, -h)), pt((L, h)), pt((0, h))), """\
    fixedEnd    { type box; min (-1e-6 %s); max (1e-6 %s); }
    loadedEnd   { type box; min (%s %s); max (%s %s); }
""" % (num(-h - 1), num(h + 1), num(L - 1e-6), num(-h - 1), num(L + 1e-6), num(h + 1)),
        """\
    type        structured;
    cellSize    0.5;
""")
    # Timoshenko and Goodier's displacements, P/(6EI) written out
    k = "%s/(6*%s*%s)" % (num(p.P), num(p.E), num(I))
    D(c, """\
    // Timoshenko-Goodier displacements (exact at x = 0)
    fixedEnd
    {
        type    fixedValue;
        value   expression
            "vector(-%s*y*((6*%s - 3*x)*x + %s*(y*y - %s)), %s*(%s*y*y*(%s - x) + %s*%s*x/4 + (%s - x)*x*x), 0)";
    }
    // Parabolic shear, resultant +P = %s (upward)
    loadedEnd
    {
        type        tractionDisplacement;
        traction    expression "vector(0, %s/%s*(%s - y*y), 0)";
        pressure    uniform 0;
    }
""" % (k, num(L), num(2 + nu), num(h*h), k, num(3*nu), num(L), num(4 + 5*nu),
       num(p.D**2), num(3*L), num(p.P), num(p.P), num(2*I), num(h*h)))


# --------------------------------------------------------------------------
def kirschStress():
    k = cp.kirsch
    q2 = "%s/(x*x + y*y)" % num(k.a**2)
    q4 = "%s/sqr(x*x + y*y)" % num(k.a**4)
    c2, c4 = "cos(2*atan2(y, x))", "cos(4*atan2(y, x))"
    s2, s4 = "sin(2*atan2(y, x))", "sin(4*atan2(y, x))"

    def scaled(e):
        return e if k.S == 1 else "%s*(%s)" % (num(k.S), e)
    sxx = scaled("1 - %s*(1.5*%s + %s) + 1.5*%s*%s" % (q2, c2, c4, q4, c4))
    syy = scaled("-%s*(0.5*%s - %s) - 1.5*%s*%s" % (q2, c2, c4, q4, c4))
    sxy = scaled("-%s*(0.5*%s + %s) + 1.5*%s*%s" % (q2, s2, s4, q4, s4))
    return sxx, syy, sxy


def plateHole():
    c = "plateHole"
    k = cp.kirsch
    a, s = k.a, k.side
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    staticSolution(c, smallDisplacement=True)
    mechanicalProperties(c, k.planeStress, "plate", num(k.E), num(k.nu), num(k.rho))
    # 256 chords: the L2 error of the finest rate mesh (h = 0.025) would
    # otherwise be that of the polygon, not of the discretisation
    corners = [(a, 0), (s, 0), (s, s), (0, s), (0, a)]
    pts = corners + arc(a, math.pi/2, 0.0, 4*NARC)
    meshDict(c, """\
    plate
    {
        material plate;
        // %s, then the hole r = %s back to %s
        polygon%s;
    }
""" % (" ".join(pt(q) for q in corners), num(a), pt(corners[0]), polygon(pts)), """\
    right       { type box; min (%s -1); max (%s %s); }
    top         { type box; min (-1 %s); max (%s %s); }
    symmetryX   { type box; min (-1e-6 %s); max (1e-6 %s); }
    symmetryY   { type box; min (%s -1e-6); max (%s 1e-6); }
""" % (num(s - 1e-6), num(s + 1), num(s + 1), num(s - 1e-6), num(s + 1), num(s + 1),
       num(a/2), num(s + 1), num(a/2), num(s + 1)), """\
    type        structured;
    cellSize    0.05;
""")
    sxx, syy, sxy = kirschStress()
    D(c, """\
    // Kirsch's stresses (a = %s, sigma = %s in x) as tractions on the outer
    // edges: n = (1 0) on x = %s, n = (0 1) on y = %s
    right
    {
        type        tractionDisplacement;
        traction    expression
            "vector(%s, %s, 0)";
        pressure    uniform 0;
    }
    top
    {
        type        tractionDisplacement;
        traction    expression
            "vector(%s, %s, 0)";
        pressure    uniform 0;
    }
    symmetryX   { type fixedNormal; }
    symmetryY   { type fixedNormal; }
""" % (num(a), num(k.S), num(s), num(s), sxx, sxy, sxy, syy))


# --------------------------------------------------------------------------
def lame():
    c = "lame"
    m = cp.lame
    a, b = m.a, m.b
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    staticSolution(c, smallDisplacement=True)
    mechanicalProperties(c, m.planeStress, "steel", num(m.E), num(m.nu), num(m.rho))
    pts = [(b, 0)] + arc(b, 0.0, math.pi/2, NARC) + [(0, b), (0, a)] \
        + arc(a, math.pi/2, 0.0, NARC) + [(a, 0)]
    meshDict(c, """\
    ring
    {
        material steel;
        // outer arc r = %s from %s to %s, inner arc r = %s back
        polygon%s;
    }
""" % (num(b), pt((b, 0)), pt((0, b)), num(a), polygon(pts)), """\
    inner       { type box; min (-1e-6 -1e-6); max (%s %s); }
    symmetryX   { type box; min (-1e-6 %s); max (1e-6 %s); }
    symmetryY   { type box; min (%s -1e-6); max (%s 1e-6); }
""" % (num(a + 1e-6), num(a + 1e-6), num(a/2), num(b + 0.1), num(a/2), num(b + 0.1)),
        """\
    type        structured;
    cellSize    0.0025;
""")
    D(c, """\
    inner
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %s;
    }
    symmetryX   { type fixedNormal; }
    symmetryY   { type fixedNormal; }
""" % num(m.p))


# --------------------------------------------------------------------------
def freeFall():
    c = "freeFall"
    f = cp.freeFall
    controlDict(c, f.nSteps*f.deltaT, f.deltaT,
                "%d steps of %s s, every step written" % (f.nSteps, num(f.deltaT)))
    write(c, "system/nmmSolution", "system", "nmmSolution", """\
analysis        dynamic;

// DDA: Newmark beta = 1/2, gamma = 1; the velocity is carried over whole
timeScheme      { type DDA; velocityRatio 1; }

linearSolver    { type cholmod; }
""")
    mechanicalProperties(c, False, "rock", num(f.E), num(f.nu), num(f.rho))
    gravity(c, 0, -f.g)
    meshDict(c, """\
    cube { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
""", "", """\
    type        structured;
    cellSize    0.25;
""")
    D(c, "    // No patch: every edge is traction free\n")


# --------------------------------------------------------------------------
def waveBar():
    c = "waveBar"
    w = cp.waveBar
    cell = 0.1
    controlDict(c, w.endTime, w.deltaT,
                "%d steps of %s s (Courant number c dt/h = %s), every step written"
                % (round(w.endTime/w.deltaT), num(w.deltaT),
                   num(math.sqrt(w.E/w.rho)*w.deltaT/cell)))
    write(c, "system/nmmSolution", "system", "nmmSolution", """\
analysis        dynamic;

// Trapezoidal rule: no numerical damping, second order
timeScheme      { type Newmark; beta 0.25; gamma 0.5; }

linearSolver    { type cholmod; }
""")
    mechanicalProperties(c, w.planeStress, "bar", num(w.E), num(w.nu), num(w.rho))
    meshDict(c, """\
    bar { material bar; polygon (%s %s %s %s); }
""" % (pt((0, 0)), pt((w.L, 0)), pt((w.L, w.H)), pt((0, w.H))), """\
    loaded      { type box; min (-1e-6 -1); max (1e-6 1); }
    fixed       { type box; min (%s -1); max (%s 1); }
""" % (num(w.L - 1e-6), num(w.L + 1e-6)), """\
    type        structured;
    cellSize    %s;
""" % num(cell))
    D(c, """\
    // Step load: %s MPa from t = 0 on
    loaded
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %s;
    }
    fixed       { type fixedValue; value uniform (0 0 0); }
""" % (num(w.p0/1e6), num(w.p0)))


# --------------------------------------------------------------------------
def sneddon(angleDeg):
    c = "sneddon/angle%d" % angleDeg
    p = cp.sneddon
    a, h = p.a, p.side/2
    t = math.radians(angleDeg)
    tip = (a*math.cos(t), a*math.sin(t))
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    # E = 1 and p = 1 open the crack by 4 times its length: the closed form
    # holds for the linear problem only
    staticSolution(c, smallDisplacement=True)
    mechanicalProperties(c, p.planeStress, "solid", num(p.E), num(p.nu), num(p.rho))
    contactProperties(c, 0, "// The pressurised crack opens: its faces never touch\n")
    meshDict(c, """\
    plate { material solid; polygon (%s %s %s %s); }
""" % (pt((-h, -h)), pt((h, -h)), pt((h, h)), pt((-h, h))), """\
    crack       { type joint; joint crack1; }
    bottom      { type box; min (%s %s); max (%s %s); }
""" % (num(-2*h), num(-h - 1e-6), num(2*h), num(-h + 1e-6)), """\
    // Fine triangles in a band of half a crack length around the crack:
    // the opening depends on the resolution of the whole near field
    type        delaunay;
    cellSize    0.02;
    refineNearBoundaries { cellSize 0.002; distance 0.05; near joints; }
""", joints="""\
    // half-length a = %s at %d degrees to the x axis (and the cover lines)
    crack1 { points (%s %s); }
""" % (num(a), angleDeg, pt((-tip[0], -tip[1])), pt(tip)))
    D(c, """\
    crack
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %s;
    }
    // Rigid motion restrained on the far boundary, %s a from the crack
    bottom      { type fixedValue; value uniform (0 0 0); }
""" % (num(p.p), num(h/a)))


# --------------------------------------------------------------------------
def plateHoleFoam():
    """OpenFOAM's stressAnalysis/solidDisplacementFoam/plateHole as it
    ships: quarter plate 2 x 2, hole r = 0.5, traction 10 kPa in x on the
    right edge, symmetry on the left and bottom edges, top edge and hole
    traction-free; E = 200 GPa, nu = 0.3, rho = 7854, plane stress."""
    c = "plateHoleFoam"
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    staticSolution(c, smallDisplacement=True)
    mechanicalProperties(c, True, "steel", "2e+11", "0.3", "7854")
    pts = [(0.5, 0), (2, 0), (2, 2), (0, 2), (0, 0.5)] \
        + arc(0.5, math.pi/2, 0.0, 4*NARC)
    meshDict(c, """\
    plate
    {
        material steel;
        // (0.5 0) (2 0) (2 2) (0 2) (0 0.5), then the hole r = 0.5 back
        // to (0.5 0) (256 chords)
        polygon%s;
    }
""" % polygon(pts), """\
    right       { type box; min (1.999999 -1); max (3 3); }
    left        { type box; min (-1e-6 0.25); max (1e-6 3); }
    down        { type box; min (0.25 -1e-6); max (3 1e-6); }
""", """\
    type        structured;
    cellSize    0.025;
""")
    D(c, """\
    // OpenFOAM's tutorial: uniform traction on the right edge, the top
    // edge and the hole traction-free (no patch: natural boundary)
    right
    {
        type        tractionDisplacement;
        traction    uniform (10000 0 0);
        pressure    uniform 0;
    }
    left        { type fixedNormal; }
    down        { type fixedNormal; }
""")


# --------------------------------------------------------------------------
# Contact cases (docs/verification.md, Contact). Each is a whole tutorial:
# the dictionaries, Allrun, Allclean and a README.md.

def scripts(case, checker):
    """Allrun and Allclean of a case under contact/ (depth from the
    project folder taken from the case path)."""
    up = "/".join([".."]*(len(Path(case).parts) + 2))
    for name, tools, body in (
            ("Allrun", "RunFunctions", """\
# Covers and manifold elements (constant/nmmMesh, VTK/mesh.vtu), then the
# solver (VTK/<case>_<index>.vtu, VTK/<case>.vtu.series, contacts_<index>.vtp).
# Compare with the closed form: tests/verification/%s (see README.md).
runApplication nmmMesh || exit 1
runApplication $(getApplication) || exit 1
""" % checker),
            ("Allclean", "CleanFunctions", "cleanCase\n")):
        path = HERE/case/name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("""\
#!/bin/bash
cd "${0%%/*}" || exit                                # Run from this directory
. ${NMM_PROJECT_DIR:-$(cd %s && pwd)}/bin/tools/%s
#------------------------------------------------------------------------------

%s
#------------------------------------------------------------------------------
""" % (up, tools, body))
        path.chmod(0o755)


def readme(case, text):
    (HERE/case).mkdir(parents=True, exist_ok=True)
    (HERE/case/"README.md").write_text(text)


def dynamicControlDict(case, endTime, deltaT, writeInterval, comment,
                       adjust=False, functions=""):
    controlDict(case, endTime, deltaT, comment, writeInterval, adjust, functions)


def gravity(case, gx, gy, comment=""):
    write(case, "constant/g", "constant", "g", comment + """\
dimensions      [0 1 -2 0 0 0 0];

value           (%s %s 0);
""" % (fmt(gx), fmt(gy)), cls="uniformDimensionedVectorField")


def contactLaw(case, frictionAngle, cohesion=0, tensileStrength=0,
               initialState="open", comment=""):
    write(case, "constant/contactProperties", "constant", "contactProperties",
          comment + """\
default
{
    law             mohrCoulomb;
    frictionAngle   %s;         // degrees
    cohesion        %s;          // [Pa]
    tensileStrength %s;          // [Pa]
    initialState    %s;
}
""" % (fmt(frictionAngle), fmt(cohesion), fmt(tensileStrength), initialState))


def contactSolution(case, scheme, contact="", stepControl="", comment="",
                    extra=""):
    write(case, "system/nmmSolution", "system", "nmmSolution", comment + """\
analysis        dynamic;

timeScheme      %s

contact
{
    method                  penalty;
%s}

stepControl
{
%s}

linearSolver    { type cholmod; }
""" % (scheme, contact, stepControl) + extra)


DDA = "{ type DDA; velocityRatio 1; }"
TRAPEZOIDAL = "{ type Newmark; beta 0.25; gamma 0.5; }"
DAMPED = "{ type Newmark; beta 1; gamma 1.5; }"
# Friction angles of the incline within this of the slope's are near the
# edge of sliding: there DDA's undamped velocity of the contact springs
# makes the block slip ahead (docs/case-reference.md), and DAMPED is used
NEAR_CRITICAL = 2


def inclineSetup(c, a, scheme=DDA, initialEquilibrium=False):
    """Rock and gravity tilted by a, the base's top face being the incline;
    DDA or the damped Newmark scheme; from the initial equilibrium or from
    unloaded contact springs."""
    comment = ("// DDA (Newmark beta = 1/2, gamma = 1): exact for constant\n"
               "// accelerations; automatic penalties (50 E normal)\n"
               if scheme == DDA else
               "// Newmark beta = 1, gamma = 3/2: exact for constant accelerations\n"
               "// and damps the velocity of the stiff contact springs, which DDA\n"
               "// does not (near the friction angle it makes the block slip\n"
               "// ahead); automatic penalties (50 E normal)\n")
    i = cp.incline
    contactSolution(c, scheme, stepControl="    maxDisplacementRatio    %s;\n"
                    % num(i.maxDisplacementRatio), comment=comment,
                    extra="\n// The block starts resting on loaded springs, friction let go\n"
                    "// at t = 0\ninitialEquilibrium yes;\n" if initialEquilibrium else "")
    mechanicalProperties(c, False, "rock", "1e9", "0.25", "2000")
    gravity(c, i.g*math.sin(a), -i.g*math.cos(a),
            "// |g| = %s at a = %s degrees to -y: the base is the incline\n"
            % (num(i.g), num(i.a)))


def incline(phiDeg):
    """A 1 x 1 block on a 4 x 0.5 base fixed at its bottom; the slope is
    made by tilting gravity by a = 30 degrees, not the geometry."""
    c = "contact/incline/phi%d" % phiDeg
    a = math.radians(cp.incline.a)
    dynamicControlDict(c, 1, 0.01, 0.1, "100 steps of 0.01 s, written every 0.1 s")
    nearCritical = 0 < cp.incline.a - phiDeg <= NEAR_CRITICAL
    # Near the friction angle the damped scheme's start from the released
    # friction lags (0.87% at 1 s at phi 29, against 0.61% from unloaded
    # springs): that case keeps its start
    inclineSetup(c, a, DAMPED if nearCritical else DDA,
                 initialEquilibrium=not nearCritical)
    contactLaw(c, phiDeg, comment="// Dry friction only: phi = %d degrees (tan a = %.4f, tan phi = %.4f)\n"
               % (phiDeg, math.tan(a), math.tan(math.radians(phiDeg))))
    meshDict(c, """\
    base   { material rock; polygon ((0 -0.5) (4 -0.5) (4 0) (0 0)); }
    slider { material rock; polygon ((0.25 0) (1.25 0) (1.25 1) (0.25 1)); }
""", """\
    fixed       { type box; min (-1 -0.500001); max (5 -0.499999); }
""", """\
    type        structured;
    cellSize    0.25;
""")
    D(c, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
""")
    scripts(c, "checkIncline.py")
    schemeText = ("Newmark (`beta 1; gamma 1.5`)" if nearCritical
                  else "DDA (`velocityRatio 1`)")
    schemeNote = ("""
The slope is within %d degrees of the friction angle, where the friction
force nearly balances the weight and the net acceleration is small (here
0.196 m/s^2): DDA, which leaves the velocity of the stiff contact springs
undamped (V1 = 2 D/dt - V0 turns into -V0), makes the block slip ahead by
a velocity of 2.4e-3 m/s gained in the first steps, as the block settles
onto its springs (+2.4%% at 1 s). Newmark with beta 1 and gamma 3/2 is as
exact for this constant acceleration and damps that velocity within a few
steps (docs/case-reference.md).
""" % NEAR_CRITICAL) if nearCritical else ""
    readme(c, """\
# incline/phi%d: a block sliding (or not) on an incline

Dry (Mohr-Coulomb, no cohesion) friction at phi = %d degrees on a slope of
a = 30 degrees. The slope is made by tilting gravity: g = 9.81 (sin a,
-cos a), so that the base's top face is the incline and the slider moves
along x. From rest,

    d(t) = g (sin a - cos a tan phi) t^2/2   if tan phi < tan a,
    d(t) = 0                                  otherwise.

Base 4 x 0.5 (bottom edge fixed), slider 1 x 1 resting on it at
x = 0.25..1.25; E = 1e9, nu = 0.25, rho = 2000, plane strain; automatic
penalties (normal 50 E); structured cover, cellSize 0.25.
%s, deltaT 0.01 s, 100 steps, frames every 0.1 s.%s

Check (`tests/verification/checkIncline.py <case> %d`): the mean x
displacement of the slider's elements in the last frame (t about 1 s,
compared at the frame's own time) within 1%% of d(t); when the block
sticks (phi >= a), its drift below the allowed penetration, 0.4 times
the search distance (2.5 maxDisplacementRatio half the larger side of
the model's bounding box: 0.01 m here).
%s""" % (phiDeg, phiDeg, schemeText, "" if nearCritical else """ The run starts
from the initial equilibrium (`initialEquilibrium yes`): the slider rests
on springs loaded by its weight, friction held until t = 0, so that it
does not sink into them and slip ahead in the first steps.""", phiDeg, schemeNote))


# Sliding vs toppling: block b x h on the incline of incline() (a = 30
# degrees, gravity tilted), dry friction phi; regime -> (b, h, phi).
TOPPLE = cp.topple.regimes


def topple(regime):
    """A b x h block from rest on a 4 x 0.5 base fixed at its bottom, the
    slope made by tilting gravity by a = 30 degrees (as incline()): stable,
    sliding without toppling, or toppling about its downhill bottom
    corner without sliding."""
    c = "contact/topple/%s" % regime
    b, h, phiDeg = TOPPLE[regime]
    a = math.radians(cp.topple.a)
    tanA, tanPhi = math.tan(a), math.tan(math.radians(phiDeg))
    x0 = cp.topple.x0
    if regime == "toppling":
        # theta(t) = (alpha0/k)(cosh(sqrt(k) t) - 1) reaches 0.0453 rad at
        # 0.15 s: the early motion, small rotation
        endTime, deltaT, writeInterval, cell = 0.15, 0.005, 0.01, 0.125
        comment = "30 steps of 0.005 s, written every 0.01 s"
    else:
        endTime, deltaT, writeInterval, cell = 1, 0.01, 0.1, 0.25
        comment = "100 steps of 0.01 s, written every 0.1 s"
    dynamicControlDict(c, endTime, deltaT, writeInterval, comment)
    inclineSetup(c, a)
    contactLaw(c, phiDeg, comment="// Dry friction only: phi = %d degrees (tan a = %.4f, "
               "tan phi = %.4f, b/h = %s)\n" % (phiDeg, tanA, tanPhi, fmt(b/h)))
    meshDict(c, """\
    base   { material rock; polygon ((0 -0.5) (4 -0.5) (4 0) (0 0)); }
    block  { material rock; polygon (%s %s %s %s); }
""" % (pt((x0, 0)), pt((x0 + b, 0)), pt((x0 + b, h)), pt((x0, h))), """\
    fixed       { type box; min (-1 -0.500001); max (5 -0.499999); }
""", """\
    type        structured;
    cellSize    %s;
""" % fmt(cell))
    D(c, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
""")
    scripts(c, "checkTopple.py")
    if regime == "stable":
        closed = """\
tan a = 0.577 < tan phi = %.3f and tan a < b/h = 1: the block neither
slides nor rotates.""" % tanPhi
        check = """\
Check (`tests/verification/checkTopple.py <case> stable`): in the last
frame (t about 1 s) the block's mean |D| and the largest |D| of its points
below the allowed penetration, 0.4 times the search distance (2.5
maxDisplacementRatio half the larger side of the model's bounding box:
0.01 m here), and its rotation (least squares rigid fit of its points)
below 1e-3 rad."""
    elif regime == "sliding":
        closed = """\
tan phi = %.3f < tan a = 0.577 < b/h = 1: the block slides without
toppling (the friction's moment keeps the normal force's resultant within
the base while tan phi < b/h),

    d(t) = g (sin a - cos a tan phi) t^2/2,   no rotation.""" % tanPhi
        check = """\
Check (`tests/verification/checkTopple.py <case> sliding`): the mean x
displacement of the block's elements in the last frame (t about 1 s,
compared at the frame's own time) within 1% of d(t), and its rotation
(least squares rigid fit of its points) below 1e-3 rad."""
    else:
        closed = """\
b/h = 0.25 < tan a = 0.577 < tan phi = %.3f: the block topples about its
downhill bottom corner P without sliding. Gravity's clockwise moment
about P, with the block turned clockwise by theta,

    M(theta) = m g/2 [(h sin a - b cos a) cos theta
                      + (h cos a + b sin a) sin theta],

and the moment of inertia about P, I = m (b^2 + h^2)/3, give
I theta'' = M(theta). From rest the angular acceleration is

    alpha0 = 3 g (h sin a - b cos a)/(2 (b^2 + h^2)) = 3.926 rad/s^2,

and, linearised in theta (k = 3 g (h cos a + b sin a)/(2 (b^2 + h^2))
= 13.72 s^-2),

    theta(t) = alpha0/k (cosh(sqrt(k) t) - 1) = alpha0 t^2/2 + O(t^4),

0.0453 rad at t = 0.15 s (the full equation gives 7e-5 of theta less;
alpha0 t^2/2 alone is 2.5%% low). The pivot holds: from rest the
friction it needs is |alpha0 h/2 - g sin a|/(alpha0 b/2 + g cos a) = 0.33
of the normal force, below tan phi.""" % tanPhi
        check = """\
Check (`tests/verification/checkTopple.py <case> toppling`): in the last
frame (t about 0.15 s, compared at the frame's own time) the block's
clockwise rotation (least squares rigid fit of its points) within 3% of
theta(t), and the x displacement of the pivot corner below 5% of that of
the downhill top corner (no slip). The other frames are reported, with
alpha0 t^2/2."""
    readme(c, """\
# topple/%s: sliding vs toppling on an incline

A b x h = %s x %s block, from rest, on a slope of a = 30 degrees, dry
(Mohr-Coulomb, no cohesion) friction at phi = %d degrees. The slope is made
by tilting gravity: g = 9.81 (sin a, -cos a), so that the base's top face
is the incline and x points downslope. For a rigid block, the static
criteria are

- stable: tan a < tan phi and tan a < b/h;
- sliding without toppling: tan a > tan phi and tan a < b/h;
- toppling without sliding: tan a < tan phi and tan a > b/h.

%s

Base 4 x 0.5 (bottom edge fixed), block at x = %s..%s; E = 1e9,
nu = 0.25, rho = 2000, plane strain; automatic penalties (normal 50 E);
structured cover, cellSize %s.
DDA (`velocityRatio 1`), %s.

%s
""" % (regime, fmt(b), fmt(h), phiDeg, closed, fmt(x0), fmt(x0 + b), fmt(cell),
       "deltaT %s s, %d steps, frames every %s s" % (fmt(deltaT), round(endTime/deltaT),
                                                   fmt(writeInterval)),
       check))


def bouncingBlock(scheme):
    """A 1 x 1 block dropped from h0 = 1 onto a base fixed at its bottom.
    The contact spring is much softer than the blocks (normalPenalty 5e6
    against E = 1e9), so that the blocks stay rigid and the impact is
    that of a mass on a spring: with the trapezoidal rule it rebounds to
    h0; DDA damps it (restitution reported against omega dt)."""
    c = "contact/bouncingBlock/%s" % scheme
    bb = cp.bouncingBlock
    trapezoidal = scheme == "trapezoidal"
    dynamicControlDict(c, 1.9, bb.deltaT, 0.005,
                       "1900 steps of 1e-3 s (two bounces), written every 5e-3 s")
    contactSolution(
        c, TRAPEZOIDAL if trapezoidal else DDA,
        contact="    normalPenalty           %s;\n" % num(bb.normalPenalty),
        stepControl="    maxDisplacementRatio    0.05;\n",
        comment=("// Trapezoidal rule: no numerical damping\n" if trapezoidal else
                 "// DDA (Newmark beta = 1/2, gamma = 1): numerically damped\n")
        + "// Contact springs 5e6 N/m per contact point, far softer than the\n"
        "// blocks; maxDisplacementRatio 0.05 gives a search distance of\n"
        "// 0.156 m, so that the impact's penetration (v/omega) is allowed\n")
    mechanicalProperties(c, False, "rock", "1e9", "0.25", num(bb.rho))
    gravity(c, 0, -bb.g)
    contactLaw(c, 0, comment="// Frictionless: the block only bounces\n")
    side = math.sqrt(bb.area)
    meshDict(c, """\
    base  { material rock; polygon ((-0.5 -0.5) (1.5 -0.5) (1.5 0) (-0.5 0)); }
    block { material rock; polygon (%s %s %s %s); }
""" % (pt((0, bb.h0)), pt((side, bb.h0)), pt((side, bb.h0 + side)), pt((0, bb.h0 + side))),
        """\
    fixed       { type box; min (-1 -0.500001); max (2 -0.499999); }
""", """\
    type        structured;
    cellSize    0.25;
""")
    D(c, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
""")
    scripts(c, "checkBouncingBlock.py")
    readme(c, """\
# bouncingBlock/%s: a block dropped onto a fixed base

A 1 x 1 block falls from rest from h0 = 1 (the gap between its bottom and
the base's top face) onto a 2 x 0.5 base fixed at its bottom; g = 9.81,
frictionless contact. E = 1e9, nu = 0.25, rho = 2000, plane strain;
normalPenalty 5e6 N/m per contact point, so that the blocks are rigid
next to the springs and the impact is that of a mass m = 2000 on the
parallel springs of the n closed contact points: omega = sqrt(n kN/m).
deltaT 1e-3 s, 1900 steps (two bounces), frames every 5e-3 s;
maxDisplacementRatio 0.05 (search distance 0.156 m; the impact's
penetration v/omega must stay below 0.4 of it).

%s

Check (`tests/verification/checkBouncingBlock.py <case> %s`): the rebound
heights (largest height of the block's bottom between impacts, from its
mean D_y) and the number n of closed contacts at the deepest
penetration (contacts_<index>.vtp), for omega dt.
""" % (scheme, "Trapezoidal rule (Newmark beta = 1/4, gamma = 1/2): no "
       "numerical damping; each rebound must reach h0 within 3% and lose "
       "less than 1% of the energy per bounce (rebound height over the "
       "previous one)." if trapezoidal else
       "DDA (Newmark beta = 1/2, gamma = 1, velocityRatio 1): numerically "
       "damped; the restitution (rebound over drop height) is reported "
       "against omega dt; it must be finite and below 1.", scheme))


def pushedBlock():
    """A 1 x 1 block bonded to a base fixed at its bottom, pushed on its
    left side by a traction ramped linearly in time."""
    c = "contact/pushedBlock"
    pb = cp.pushedBlock
    dynamicControlDict(c, 1, pb.deltaT, pb.deltaT,
                       "100 steps of %s s (load increments of %s N/m), every step written"
                       % (num(pb.deltaT), num(pb.rate*pb.deltaT)))
    contactSolution(
        c, DDA,
        contact="    normalPenalty           1e3;\n",
        comment="// DDA (Newmark beta = 1/2, gamma = 1): the push is quasi-static\n"
        "// until the bond breaks. Contact springs 1e3 N/m per contact point,\n"
        "// softer than the blocks (E = 1e4), so that the blocks move rigidly\n"
        "// on them and share the load evenly\n")
    write(c, "constant/mechanicalProperties", "constant", "mechanicalProperties", """\
// Units: m, kg, s; rho = %s and g = %s make the weight per unit thickness
// W = %s N/m and the mass m = %s kg/m
planeStress     no;

thickness       1;

materials
{
    rock { type linearElastic; E 1e4; nu 0.25; rho %s; }
}
""" % (num(pb.m/pb.L**2), num(pb.W/pb.m), num(pb.W), num(pb.m), num(pb.m/pb.L**2)))
    gravity(c, 0, -pb.W/pb.m, "// g = %s: W = rho g L^2 = %s N/m\n"
            % (num(pb.W/pb.m), num(pb.W)))
    contactLaw(c, pb.phi, cohesion=pb.c, tensileStrength=1, initialState="bonded",
               comment="// Bonded at the start: c = %s Pa, phi = %s degrees; the\n"
               "// tensile strength only keeps the bond from failing in tension\n"
               % (num(pb.c), num(pb.phi)))
    meshDict(c, """\
    base  { material rock; polygon ((-0.5 -0.5) (2.5 -0.5) (2.5 0) (-0.5 0)); }
    block { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
""", """\
    fixed       { type box; min (-1 -0.500001); max (3 -0.499999); }
    push        { type box; min (-1e-6 -1e-6); max (1e-6 1.000001); }
""", """\
    type        structured;
    cellSize    0.25;
""")
    D(c, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
    // F(t) = t [N/m] in +x, distributed as F (4 - 6 y) over 0 <= y <= 1:
    // resultant F, no moment about the interface y = 0, so that the
    // normal stress on the bond stays uniform (W/L)
    push
    {
        type        tractionDisplacement;
        traction    expression "vector(%s*(4 - 6*y), 0, 0)";
        pressure    uniform 0;
    }
""" % ("t" if pb.rate == 1 else "%s*t" % num(pb.rate)))
    scripts(c, "checkPushedBlock.py")
    readme(c, """\
# pushedBlock: a bonded block pushed horizontally

A 1 x 1 block bonded (Mohr-Coulomb, `initialState bonded`) to a 3 x 0.5
base fixed at its bottom, pushed on its left side by F(t) = t N/m per unit
thickness. Units m, kg, s with rho = 1 and g = 1: W = 1 N/m, m = 1 kg/m.
c = 0.1 Pa, phi = 30 degrees, contact length L = 1. The bond breaks in
shear at

    F = c L + W tan phi = 0.6774 N/m,

and the block then slides (cohesion lost for good) with
a = (F - W tan phi)/m. The push is distributed as F (4 - 6 y) over the
side so that it has no moment about the interface: the normal stress on
the bond stays uniform. E = 1e4, nu = 0.25, plane strain;
normalPenalty 1e3 N/m per contact point (softer than the blocks). DDA,
deltaT 0.01 s (load increments of 0.01 N/m), every step written.

Check (`tests/verification/checkPushedBlock.py <case>`): the onset of
sliding, the load of the first frame in which no contact of the block is
bonded any more (contactState of contacts_<index>.vtp: 0 open, 1 bonded,
2 sliding), within one load increment of c L + W tan phi. The first
sliding contact and the displacement after the onset against the closed
form are reported.
""")


def stickSlip():
    """A 1 x 1 block of 1 kg/m on a base fixed at its bottom, dry friction
    mu = 0.8, pushed on its left side by F(t) = 8 cos t (Potra's
    stick-slip benchmark), from the initial equilibrium."""
    c = "contact/stickSlip"
    ss = cp.stickSlip
    phi = math.degrees(math.atan(ss.mu))
    functions = """\
    motion   { type blockMotion; blocks (block); }
    contacts { type contactStatistics; }
"""
    dynamicControlDict(c, num(ss.endTime), num(ss.deltaT), 0.1,
                       "%d steps of %s s, frames every 0.1 s; the block's motion and the"
                       "\n// contact states of every step in postProcessing/"
                       % (round(ss.endTime/ss.deltaT), num(ss.deltaT)),
                       functions=functions)
    contactSolution(
        c, DAMPED,
        comment="// Newmark beta = 1, gamma = 3/2: the block slides at nearly its\n"
        "// friction limit, where DDA's undamped velocity of the stiff contact\n"
        "// springs makes it slip ahead and chatter when it stops (as for the\n"
        "// incline near its friction angle); first order in dt. Automatic\n"
        "// penalties (50 E normal). The block starts from the static\n"
        "// equilibrium under its weight and F(0), so that its springs carry\n"
        "// them from the first step\n",
        extra="\ninitialEquilibrium yes;\n")
    write(c, "constant/mechanicalProperties", "constant", "mechanicalProperties", """\
// rho = %s on a %s x %s block: m = %s kg/m
planeStress     no;

thickness       1;

materials
{
    rock { type linearElastic; E %s; nu 0.25; rho %s; }
}
""" % (num(ss.m/ss.L**2), num(ss.L), num(ss.L), num(ss.m), num(ss.E), num(ss.m/ss.L**2)))
    gravity(c, 0, -ss.g, "// g = %s: mu m g = %s N/m\n" % (num(ss.g), num(ss.mu*ss.m*ss.g)))
    contactLaw(c, phi,
               comment="// Dry friction: mu = tan(phi) = %s\n" % num(ss.mu))
    meshDict(c, """\
    base  { material rock; polygon ((-0.5 -0.5) (2.5 -0.5) (2.5 0) (-0.5 0)); }
    block { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
""", """\
    fixed       { type box; min (-1 -0.500001); max (3 -0.499999); }
    push        { type box; min (-1e-6 -1e-6); max (1e-6 1.000001); }
""", """\
    type        structured;
    cellSize    0.25;
""")
    D(c, """\
    fixed       { type fixedValue; value uniform (0 0 0); }
    // F(t) = %s cos(t) [N/m] in +x, distributed as F (4 - 6 y) over
    // 0 <= y <= 1: resultant F, no moment about the interface y = 0, so
    // that the normal stress on the interface stays uniform
    push
    {
        type        tractionDisplacement;
        traction    expression "vector(%s*cos(%st)*(4 - 6*y), 0, 0)";
        pressure    uniform 0;
    }
""" % (num(ss.F0), num(ss.F0), "" if ss.omega == 1 else num(ss.omega) + "*"))
    scripts(c, "checkStickSlip.py")
    readme(c, """\
# stickSlip: a block on a base under a harmonic push

Potra's stick-slip benchmark. A 1 x 1 block of rho = 1 (m = 1 kg/m) on a
3 x 0.5 base fixed at its bottom, dry friction mu = 0.8 (Mohr-Coulomb,
phi = atan 0.8, no cohesion), g = 9.81, pushed on its left side by
F(t) = 8 cos t N/m, to T = 10 s. For the rigid block

    m x'' = F(t) - mu m g sgn(x')    while it slides,
    x' = 0                           while |F| <= mu m g = 7.848 N/m:

slips in [0, 0.3386], [2.9463, 3.5328], [6.0879, 6.6744] and
[9.2295, 9.8160] s, the position held between them at 4.3486e-3,
-8.6972e-3, 4.3486e-3 m (`tests/verification/closedForms.py stickSlip`
prints them; `selfTest.py contactClosedForms` checks them against a
direct integration). F(0) = 8 > 7.848, so the block slides from the
start: the case starts from the initial equilibrium
(`initialEquilibrium yes` in system/nmmSolution), so that its springs
carry the weight and the push from the first step, friction held until
then. The push is distributed as F (4 - 6 y) over the side so that it has
no moment about the interface. E = 1e9 (the block nearly rigid), nu =
0.25, plane strain; automatic penalties (normal 50 E); structured cover,
cellSize 0.25. Newmark with beta 1 and gamma 3/2, which damps the velocity
of the stiff contact springs (DDA does not: at nearly the friction limit
the block slips ahead and chatters as it stops); it is first order, and
the first plateau's error is about 17 dt/s (1.7e-1 at deltaT 0.01, 8.5e-2
at 0.005, 4.3e-2 at 0.0025, 2.1e-2 at 0.00125), hence deltaT 6.25e-4 s
(16000 steps, a few seconds). blockMotion and contactStatistics write every
step to postProcessing/.

Without the initial equilibrium (`initialEquilibrium no`) the block
starts on unloaded springs and slides too far while it sinks into them:
the first plateau 8.9% high at deltaT 6.25e-4 (0.82% with it), the first
slip ending 3.6e-3 s late.

Check (`tests/verification/checkStickSlip.py <case>`): a slip is a run
of steps in which every closed contact slides (postProcessing/contacts;
the elastic block slips partially before, single contacts first), its
start and end the middle of the step in which the last contact starts
sliding and the first one sticks again;
every slip's start and end within 2 deltaT of the closed form, the same
number of slips, and the block's mean x displacement (postProcessing/
motion, its centre against the start) on every plateau within 2% of the
closed form.
""")


# --------------------------------------------------------------------------
# Contact cases loaded in steps: Hertz, disc on disc, Brazilian disc, and
# the bonded interface in tension and in shear.

def contactMaterials(case, materials, planeStress=False):
    write(case, "constant/mechanicalProperties", "constant", "mechanicalProperties",
          """\
planeStress     %s;

thickness       1;

materials
{
%s}
""" % ("yes" if planeStress else "no",
       "".join("    %s { type linearElastic; E %s; nu %s; rho %s; }\n" % m
               for m in materials)))


def loadStepSolution(case, analysis, contact, extra=""):
    """nmmSolution of a case loaded in steps: static, or quasi-static
    (dynamic with the velocity dropped at every step)."""
    scheme = """
// Quasi-static: DDA with the velocity dropped at every step; the mass is
// only a soft anchor to the last position
timeScheme      { type DDA; velocityRatio 0; }
""" if analysis == "dynamic" else """
// The closed form is linear elasticity: no geometry update
largeDisplacement no;
"""
    write(case, "system/nmmSolution", "system", "nmmSolution", """\
analysis        %s;
%s
contact
{
%s}
%s
linearSolver    { type cholmod; }
""" % (analysis, scheme, contact, extra))


def gradedArc(c, r, t0, t1, fine, coarse, fineLength):
    """Points on the circle of centre c, radius r, from angle t0 to t1
    (both ends included): chords of about 'fine' for an arc length
    fineLength from t0, then of about 'coarse'."""
    total = abs(t1 - t0)*r
    sgn = 1 if t1 > t0 else -1
    nf = max(1, int(round(min(fineLength, total)/fine)))
    s = [min(fineLength, total)*k/nf for k in range(nf + 1)]
    rest = total - s[-1]
    if rest > 1e-12:
        nc = max(1, int(math.ceil(rest/coarse)))
        s += [s[-1] + rest*k/nc for k in range(1, nc + 1)]
    return [(c[0] + r*math.cos(t0 + sgn*q/r), c[1] + r*math.sin(t0 + sgn*q/r))
            for q in s]


HERTZ = {"R": cp.hertz.R, "P": cp.hertz.P, "E": cp.hertz.E1, "nu": cp.hertz.nu1,
         "Eflat": cp.hertz.E2, "nuFlat": cp.hertz.nu2, "fine": cp.hertz.fine,
         "fineLength": cp.hertz.fineLength, "coarse": cp.hertz.coarse}


def hertzCase(c, discOnDisc=False):
    """Half models (x >= 0, symmetry roller on x = 0) of a cylinder of
    radius R pressed by P per unit thickness, static, plane strain,
    frictionless. Upper body: the lower half of the disc of centre (0, R),
    loaded by a uniform pressure P/(2R) on its flat top (y = R). Lower
    body: a stiff flat (E = 1e4), or the upper half of an identical disc
    of centre (0, -R); fixed on its bottom edge."""
    h = HERTZ
    R = h["R"]
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    # above the gap x^2/(2 Reff) at x = 1.4 a before loading
    Reff = R/2 if discOnDisc else R
    reach = (1.4*0.1076)**2/(2*Reff)
    loadStepSolution(c, "static", """\
    method                  penalty;
    normalPenalty           auto;       // 50 x largest E
    shearPenalty            auto;
    // above the gap x^2/(2R) = %.3g%s at x = 1.4 a before loading:
    // every contact the load can close is found (see ../README.md)
    searchDistance          %s;
    // one step from all contacts open: at the finest chords (0.0025) the
    // damped iteration settles in 44
    maxOpenCloseIterations  100;
""" % (reach, " (R = 1/2)" if discOnDisc else "", fmt(math.ceil(reach*500)/500)))
    if discOnDisc:
        contactMaterials(c, [("disc", h["E"], h["nu"], 1)])
        lower = "disc"
    else:
        contactMaterials(c, [("cylinder", h["E"], h["nu"], 1),
                             ("flat", h["Eflat"], h["nuFlat"], 1)])
        lower = "flat"
    upperMaterial = "disc" if discOnDisc else "cylinder"
    contactLaw(c, 0, comment="// Hertz's contact is frictionless\n")
    # (0 R), then the arc from the contact point (0 0) to (R R)
    upper = [(0.0, R)] + gradedArc((0.0, R), R, -math.pi/2, 0.0,
                                   h["fine"], h["coarse"], h["fineLength"])
    if discOnDisc:
        arcPts = gradedArc((0.0, -R), R, math.pi/2, 0.0,
                           h["fine"], h["coarse"], h["fineLength"])
        # (0 0) ... (R -R) (0 -R)
        lowerPts = arcPts + [(0.0, -R)]
        bottom = -R
    else:
        bottom = -0.15
        lowerPts = [(0.0, 0.0), (0.0, bottom), (0.4, bottom), (0.4, 0.0)]
        # vertices of the flat's top every 'fine' near the contact
        n = int(round(h["fineLength"]/h["fine"]))
        lowerPts += [(h["fineLength"]*(n - k)/n, 0.0) for k in range(1, n)]
    meshDict(c, """\
    upper
    {
        material %s;
        // quarter of the disc of centre (0 %s): chords of %s up to an
        // arc length %s from the contact point (0 0), then of %s
        polygon%s;
    }
    lower
    {
        material %s;
        polygon%s;
    }
""" % (upperMaterial, fmt(R), h["fine"], h["fineLength"], h["coarse"],
       polygon(upper), lower, polygon(lowerPts)), """\
    loaded      { type box; min (-1 %s); max (2 %s); }
    fixed       { type box; min (-2 %s); max (2 %s); }
    symmetry    { type box; min (-1e-9 -2); max (1e-9 2); }
""" % (fmt(R - 1e-6), fmt(R + 1e-6), fmt(bottom - 1e-6), fmt(bottom + 1e-6)), """\
    // Fine triangles along the boundaries (the contact zone is 0.11 wide)
    type        delaunay;
    cellSize    0.025;
    refineNearBoundaries { cellSize %s; distance 0.012; near blocks; }
""" % h["fine"])
    D(c, """\
    // P/2 = %s on the half width R: pressure P/(2R)
    loaded
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %s;
    }
    fixed       { type fixedValue; value uniform (0 0 0); }
    symmetry    { type fixedNormal; }
""" % (fmt(h["P"]/2), fmt(h["P"]/(2*R))))
    scripts(c, "checkHertz.py")


def hertzCylinder():
    hertzCase("contact/hertz", False)


def discOnDisc():
    hertzCase("contact/discOnDisc", True)



BRAZILIAN = {k: getattr(cp.brazilian, k) for k in
             ("D", "P", "E", "nu", "Eplaten", "platenWidth", "platenHeight")}


def brazilian():
    """Quarter model of a disc of diameter D squeezed by P per unit
    thickness through a steel platen in contact with it (frictionless,
    static, plane strain); rollers on the symmetry lines x = 0 and y = 0."""
    c = "contact/brazilian"
    b = BRAZILIAN
    R = b["D"]/2
    w, t = b["platenWidth"], b["platenHeight"]
    controlDict(c, 1, 1, "Static: one step, loads evaluated at t = 1")
    loadStepSolution(c, "static", """\
    method                  penalty;
    normalPenalty           auto;       // 50 x largest E
    shearPenalty            auto;
    searchDistance          2e-4;
    maxOpenCloseIterations  40;
""")
    contactMaterials(c, [("rock", b["E"], b["nu"], 2650),
                         ("steel", b["Eplaten"], 0.3, 7850)])
    contactLaw(c, 0, comment="// Frictionless platen\n")
    disc = [(0.0, 0.0)] + gradedArc((0.0, 0.0), R, math.pi/2, 0.0, 2e-4, 1e-3, 2e-3)[::-1]
    meshDict(c, """\
    disc
    {
        material rock;
        // quarter disc of radius %s: (0 0), the arc from (R 0) to (0 R)
        // with chords of 2e-4 over 2e-3 from the loaded point
        polygon%s;
    }
    platen { material steel; polygon (%s %s %s %s); }
""" % (fmt(R), polygon(disc), pt((0, R)), pt((w, R)), pt((w, R + t)),
       pt((0, R + t))), """\
    loaded      { type box; min (-1 %s); max (1 1); }
    symmetryX   { type box; min (-1e-9 -1); max (1e-9 1); }
    symmetryY   { type box; min (-1 -1e-9); max (1 1e-9); }
""" % fmt(R + t - 1e-9), """\
    type        delaunay;
    cellSize    1e-3;
    refineNearBoundaries { cellSize 2.5e-4; distance 5e-4; near blocks; }
""")
    D(c, """\
    // P/2 = %s N/m on the half platen width %s
    loaded
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %s;
    }
    symmetryX   { type fixedNormal; }
    symmetryY   { type fixedNormal; }
""" % (fmt(b["P"]/2), fmt(w), fmt(b["P"]/2/w)))
    scripts(c, "checkBrazilian.py")


BOND = {k: getattr(cp.bondedInterface, k) for k in
        ("L", "T", "c", "phi", "stepsToPeak", "extraSteps")}


def bondedLaw(c):
    b = BOND
    contactLaw(c, b["phi"], b["c"], b["T"], "bonded",
               comment="// Blocks sharing an edge at t = 0 start bonded\n")


def quasiStaticControls(c, nSteps, comment):
    controlDict(c, nSteps, 1, comment)
    # deltaT = 1: a pseudo time that counts load steps


# Load steps of deltaT 1 (a counter); a block that breaks free may move
# far in one step
LOAD_STEP_CONTROL = """
stepControl
{
    maxDisplacementRatio    0.1;
    maxDeltaT               1;
    minDeltaT               1e-6;
}
"""


def bondedTension():
    """Two blocks L x L/2 sharing the edge y = 0 (length L), bonded; the
    lower one fixed at its bottom, the upper one pulled by a uniform
    traction on its top that grows by T/40 a step. nu = 0: the stress is
    uniform (sigma_yy = traction) in both blocks, so every contact carries
    the consistent share of the load and the bond breaks everywhere at
    once when the traction reaches T."""
    c = "contact/bondedTension"
    b = BOND
    L = b["L"]
    n = b["stepsToPeak"]
    quasiStaticControls(c, n + b["extraSteps"],
                        "Quasi-static: %d load steps of T/%d" % (n + b["extraSteps"], n))
    loadStepSolution(c, "dynamic", """\
    method                  penalty;
    normalPenalty           auto;
    shearPenalty            auto;
    searchDistance          0.005;
    maxOpenCloseIterations  20;
""", LOAD_STEP_CONTROL)
    # rho: after the break the free block moves F/(2 rho A/dt^2) ~ 0.01 a
    # step; before it, the mass term is 0.5% of the blocks' stiffness
    contactMaterials(c, [("rock", "1e10", "0", "1e8")])
    bondedLaw(c)
    meshDict(c, """\
    lower { material rock; polygon ((0 %s) (%s %s) (%s 0) (0 0)); }
    upper { material rock; polygon ((0 0) (%s 0) (%s %s) (0 %s)); }
""" % (fmt(-L/2), fmt(L), fmt(-L/2), fmt(L), fmt(L), fmt(L), fmt(L/2), fmt(L/2)),
             """\
    pulled      { type box; min (-1 %s); max (2 1); }
    fixed       { type box; min (-1 -1); max (2 %s); }
""" % (fmt(L/2 - 1e-9), fmt(-L/2 + 1e-9)), """\
    type        structured;
    cellSize    0.05;
""")
    D(c, """\
    // Pull: a negative pressure growing by T/%d a step, on past T (a
    // load held at T exactly would leave the break to rounding)
    pulled
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    table ((0 0) (%d %s) (%d %s));
    }
    fixed       { type fixedValue; value uniform (0 0 0); }
""" % (n, n, fmt(-b["T"]), 2*n, fmt(-2*b["T"])))
    scripts(c, "checkBondedInterface.py")


def bondedShear(sigmaMPa):
    """Double shear: a middle block 1.2 L x 0.2 between a bottom block
    (its bottom on rollers) and a top block (pressure sigma_n on its top),
    both L long, bonded to it along y = 0 and y = 0.2 (two interfaces of
    length L). The middle block is pulled in x by a traction on its right
    edge growing so that the shear of each interface reaches its peak
    c L + sigma_n L tan(phi) half-way between steps 40 and 41: at a step
    that reaches the peak exactly, rounding would decide whether the bond
    holds. The outer blocks are held in
    x by rollers on their sides next to the interfaces, the same for both:
    the pull acts on the mid-plane of the middle block and the two
    interfaces share it equally, with (almost) no moment. The blocks are
    nearly rigid (E = 1e14 against springs of 1e9 N/m), so that every
    contact of an interface slips by the same amount: with E = 1e13 the
    middle block's stretch under the pull loaded the contacts at its
    pulled end 1.5% above the mean (shear lag), and they broke first."""
    c = "contact/bondedShear/sigma%d" % sigmaMPa
    b = BOND
    L = b["L"]
    n = b["stepsToPeak"]
    sn = sigmaMPa*1e6
    h = 0.2
    cell = 0.0125
    # the rollers' height: the arm of the interface's shear about them
    roller = 0.001
    peak = b["c"]*L + sn*L*math.tan(math.radians(b["phi"]))
    atPeak = n + 0.5
    quasiStaticControls(c, n + b["extraSteps"],
                        "Quasi-static: %d load steps, the peak at step %s"
                        % (n + b["extraSteps"], fmt(atPeak)))
    loadStepSolution(c, "dynamic", """\
    method                  penalty;
    normalPenalty           1e9;        // soft against the blocks
    shearPenalty            4e8;
    searchDistance          0.005;
    maxOpenCloseIterations  20;
""", LOAD_STEP_CONTROL)
    contactMaterials(c, [("rock", "1e14", "0", "1e10")])
    bondedLaw(c)
    y = lambda v: fmt(round(v, 12))  # noqa: E731
    meshDict(c, """\
    bottom { material rock; polygon ((0 %s) (%s %s) (%s %s) (%s 0) (0 0) (0 %s)); }
    middle { material rock; polygon ((%s 0) (%s 0) (%s %s) (%s %s)); }
    top    { material rock; polygon ((0 %s) (%s %s) (%s %s) (%s %s) (0 %s) (0 %s)); }
""" % (y(-h), fmt(L), y(-h), fmt(L), y(-roller), fmt(L), y(-roller),
       fmt(-0.1*L), fmt(1.1*L), fmt(1.1*L), y(h), fmt(-0.1*L), y(h),
       y(h), fmt(L), y(h), fmt(L), y(h + roller), fmt(L), y(2*h), y(2*h),
       y(h + roller)), """\
    pulled      { type box; min (%s -1e-9); max (2 %s); }
    supported   { type box; min (-1 -1); max (2 %s); }
    pressed     { type box; min (-1 %s); max (2 1); }
    bottomLeft  { type box; min (-1e-9 %s); max (1e-9 1e-9); }
    bottomRight { type box; min (%s %s); max (%s 1e-9); }
    topLeft     { type box; min (-1e-9 %s); max (1e-9 %s); }
    topRight    { type box; min (%s %s); max (%s %s); }
""" % (fmt(1.1*L - 1e-9), y(h + 1e-9), y(-h + 1e-9), y(2*h - 1e-9),
       y(-roller - 1e-9),
       fmt(L - 1e-9), y(-roller - 1e-9), fmt(L + 1e-9),
       y(h - 1e-9), y(h + roller + 1e-9),
       fmt(L - 1e-9), y(h - 1e-9), fmt(L + 1e-9), y(h + roller + 1e-9)), """\
    type        structured;
    cellSize    %s;
""" % fmt(cell))
    D(c, """\
    // Twice the interface peak %s N/m over the height %s at step %s
    pulled
    {
        type        tractionDisplacement;
        traction    table ((0 (0 0 0)) (%s (%s 0 0)) (%s (%s 0 0)));
        pressure    uniform 0;
    }
    supported   { type fixedNormal; }
    pressed
    {
        type        tractionDisplacement;
        traction    uniform (0 0 0);
        pressure    uniform %s;
    }
    // Rollers on the %s of the outer blocks' sides next to the
    // interfaces: they move only in y, held in x close to the interfaces'
    // planes, so that the interfaces' shear puts (almost) no moment on
    // them, and both interfaces are held alike
    bottomLeft  { type fixedNormal; }
    bottomRight { type fixedNormal; }
    topLeft     { type fixedNormal; }
    topRight    { type fixedNormal; }
""" % (fmt(peak), fmt(h), fmt(atPeak), fmt(atPeak), fmt(2*peak/h), fmt(2*atPeak),
       fmt(4*peak/h), fmt(sn), fmt(roller)))
    scripts(c, "checkBondedInterface.py")


if __name__ == "__main__":
    cantilever()
    plateHole()
    plateHoleFoam()
    lame()
    freeFall()
    waveBar()
    for angle in cp.sneddon.angles:
        sneddon(int(angle))
    for phi in cp.incline.phis:
        incline(phi)
    for regime in ("stable", "sliding", "toppling"):
        topple(regime)
    for scheme in ("trapezoidal", "DDA"):
        bouncingBlock(scheme)
    pushedBlock()
    stickSlip()
    hertzCylinder()
    discOnDisc()
    brazilian()
    bondedTension()
    for sigma in cp.bondedInterface.sigmas:
        bondedShear(round(sigma/1e6))
