#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-vtk9, python3-numpy).
"""Self-tests of the verification checks (they must be able to fail).

Usage:
    selfTest.py closedForms
        the closed forms of closedForms.py: Hooke's law on the finite
        difference strain of each displacement field gives its stress
        field, the stress is in equilibrium and traction free where it must
        be, and the numbers quoted in docs/verification.md come out
    selfTest.py tutorials <projectDir>
        the tutorials' data match closedForms.py: material constants, and
        every 'expression' of 0/D evaluated (the #eval grammar, in Python)
        on its boundary against the closed-form displacement or traction
    selfTest.py checker <case> <workDir>
        checker of <case> on synthetic frames (synthetic/makeSynthetic.py):
        exit 0 on the exact solution, 1 on the tampered one
    selfTest.py contactClosedForms
        the closed forms of the contact cases: the numbers quoted in
        docs/verification.md (Hertz a and p0, Brazilian 1.273 MPa), the
        Brazilian stress field in equilibrium and traction free on the rim
        away from the loads
    selfTest.py contactChecker <case> <workDir>
        checker of a contact case on synthetic output
        (synthetic/makeSyntheticContact.py): exit 0 on the exact solution,
        1 on the tampered one
    selfTest.py rates <workDir>
        checkCantilever.py over three synthetic refinement levels: the
        observed rates pass on exact data, fail on data with an O(h) error

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import closedForms as cf  # noqa: E402

failures = []


def expect(ok, what):
    print("  %-70s %s" % (what, "ok" if ok else "FAILED"))
    if not ok:
        failures.append(what)


# --------------------------------------------------------------------------
def fdStrain(disp, x, y, h):
    uxp, uyp = disp(x + h, y)
    uxm, uym = disp(x - h, y)
    vxp, vyp = disp(x, y + h)
    vxm, vym = disp(x, y - h)
    exx = (uxp - uxm)/(2*h)
    eyy = (vyp - vym)/(2*h)
    gxy = (vxp - vxm)/(2*h) + (uyp - uym)/(2*h)
    return exx, eyy, gxy


def fdDivergence(stress, x, y, h):
    sxp = stress(x + h, y)
    sxm = stress(x - h, y)
    syp = stress(x, y + h)
    sym = stress(x, y - h)
    fx = (sxp[0] - sxm[0])/(2*h) + (syp[2] - sym[2])/(2*h)
    fy = (sxp[2] - sxm[2])/(2*h) + (syp[1] - sym[1])/(2*h)
    return fx, fy


def checkField(name, sol, x, y, h, length):
    lam, mu = cf.planeModuli(sol.E, sol.nu, sol.planeStress)
    exx, eyy, gxy = fdStrain(sol.displacement, x, y, h)
    s = sol.stress(x, y)
    hooke = (lam*(exx + eyy) + 2*mu*exx, lam*(exx + eyy) + 2*mu*eyy, mu*gxy)
    scale = max(np.abs(np.array(s)).max(), 1e-300)
    err = max(np.abs(np.array(hooke) - np.array(s)).max()/scale, 0)
    expect(err < 1e-6, "%s: Hooke(strain of u) = sigma (%.1e)" % (name, err))
    fx, fy = fdDivergence(sol.stress, x, y, h)
    err = max(np.abs(fx).max(), np.abs(fy).max())*length/scale
    expect(err < 1e-6, "%s: div sigma = 0 (%.1e)" % (name, err))


def closedForms():
    rng = np.random.default_rng(1)
    b = cf.cantilever
    x = rng.uniform(0, b.L, 200)
    y = rng.uniform(-b.D/2, b.D/2, 200)
    checkField("cantilever", b, x, y, 1e-3, b.L)
    xe = np.linspace(0, b.L, 50)
    s = b.stress(xe, 0*xe + b.D/2)
    expect(np.abs(s[1]).max() == 0 and np.abs(s[2]).max() < 1e-9,
           "cantilever: top edge traction free")
    yy = np.linspace(-b.D/2, b.D/2, 2001)
    shear = b.stress(0*yy + b.L, yy)[2]
    resultant = np.trapz(shear, yy)
    expect(abs(resultant - b.P)/b.P < 1e-6,
           "cantilever: end shear resultant = +P (%.6g)" % resultant)
    expect(abs(b.tipDeflection() - 8.9e-3)/8.9e-3 < 1e-12,
           "cantilever: tip deflection 8.9000e-3 (%.10g)" % b.tipDeflection())

    k = cf.kirsch
    r = rng.uniform(k.a, 4*k.a, 200)
    t = rng.uniform(0, math.pi/2, 200)
    checkField("kirsch", k, r*np.cos(t), r*np.sin(t), 1e-5, k.a)
    th = np.linspace(0.01, math.pi/2 - 0.01, 50)
    xs, ys = k.a*np.cos(th), k.a*np.sin(th)
    sxx, syy, sxy = k.stress(xs, ys)
    tx = sxx*np.cos(th) + sxy*np.sin(th)
    ty = sxy*np.cos(th) + syy*np.sin(th)
    expect(max(np.abs(tx).max(), np.abs(ty).max()) < 1e-12,
           "kirsch: hole traction free")
    far = k.stress(np.array([1e4]), np.array([3e3]))
    expect(abs(far[0][0] - k.S) < 1e-6 and abs(far[1][0]) < 1e-6,
           "kirsch: far field (sigma, 0, 0)")
    ux, uy = k.displacement(np.array([0.0, 2.0]), np.array([2.0, 0.0]))
    expect(abs(ux[0]) < 1e-15 and abs(uy[1]) < 1e-15,
           "kirsch: symmetry lines move only along themselves")
    expect(abs(k.peak() - 3) < 1e-12, "kirsch: sigma_xx(0, a) = 3 sigma (%.10g)" % k.peak())

    c = cf.lame
    r = rng.uniform(c.a, c.b, 200)
    t = rng.uniform(0, math.pi/2, 200)
    checkField("lame", c, r*np.cos(t), r*np.sin(t), 1e-6, c.a)
    srr_a, stt_a = c.polarStress(c.a)
    srr_b, _ = c.polarStress(c.b)
    expect(abs(srr_a + c.p) < 1e-6 and abs(srr_b) < 1e-6,
           "lame: sigma_r(a) = -p, sigma_r(b) = 0")
    expect(abs(stt_a - 16.6667e6)/16.6667e6 < 1e-5,
           "lame: sigma_t(a) = 16.67 MPa (%.6g)" % stt_a)
    expect(abs(c.radialDisplacement(c.a) - 1.875e-4) < 1e-12,
           "lame: u_r(a) = 0.1875 mm (%.6g)" % c.radialDisplacement(c.a))

    s = cf.sneddon
    expect(abs(s.centreOpening() - 0.391) < 1e-12,
           "sneddon: w(0) = 4 p a (1 - nu^2)/E = 0.391 (%.10g)" % s.centreOpening())

    f = cf.freeFall
    expect(abs(f.displacementY(0.1) + 0.04905) < 1e-15, "freeFall: y(0.1) = -0.04905")
    w = cf.waveBar
    expect(abs(w.c() - 1000) < 1e-9 and abs(w.arrivalTime() - 5e-3) < 1e-15,
           "waveBar: c = 1000 m/s, arrival at x = 5 at 5e-3 s")

    i = cf.incline
    expect(abs(i.displacement(20, 1.0) - 0.9064) < 5e-5,
           "incline: d(1 s) = 0.9064 m at phi = 20 (%.6g)" % i.displacement(20, 1.0))
    expect(abs(i.displacement(0, 1.0) - 9.81/4) < 1e-12 and i.displacement(31, 1.0) == 0
           and i.slides(29), "incline: g sin(a)/2 at phi = 0, static at 31, slides at 29")
    expect(abs(cf.allowedPenetration(2.0) - 0.01) < 1e-15,
           "incline: allowed penetration 0.01 m (half size 2)")
    tp = cf.topple
    expect([(not tp.slides(r), not tp.topples(r)) for r in ("stable", "sliding", "toppling")]
           == [(True, True), (False, True), (True, False)],
           "topple: stable, sliding, toppling by the static criteria")
    expect(abs(tp.alpha0("toppling") - 3.9262) < 5e-5 and tp.pivotFriction("toppling")
           < math.tan(math.radians(tp.regimes["toppling"][2])),
           "topple: alpha0 = 3.9262 rad/s^2 (%.6g), the pivot holds (friction %.3g)"
           % (tp.alpha0("toppling"), tp.pivotFriction("toppling")))
    err = abs(toppleRK4(0.15)/tp.rotation("toppling", 0.15) - 1)
    expect(err < 2e-4, "topple: theta(0.15) linearised = full equation (%.1e)" % err)
    pb = cf.pushedBlock
    expect(abs(pb.onsetForce() - 0.67735) < 1e-5,
           "pushedBlock: onset at c L + W tan phi = 0.6774 (%.6g)" % pb.onsetForce())
    ss = cf.stickSlip
    windows = [(round(a, 4), round(b, 4)) for a, b, _, _ in ss.windows()[:3]]
    expect(windows == [(0.0, 0.3386), (2.9463, 3.5328), (6.0879, 6.6744)],
           "stickSlip: slip windows [0, 0.3386], [2.9463, 3.5328], [6.0879, 6.6744] (%s)"
           % windows)
    numeric = stickSlipIntegrated()
    expect(len(numeric) == len(ss.windows()) and all(
        abs(a - n[0]) < 2e-5 and abs(b - n[1]) < 2e-5 and abs(x - n[2]) < 1e-8
        for (a, b, _, _), (_, _, x), n in zip(ss.windows(), ss.plateaus(), numeric)),
        "stickSlip: the windows and plateaus of a direct integration (%s)"
        % [tuple(round(v, 5) for v in n) for n in numeric])


def toppleRK4(tEnd, n=3000):
    """theta(tEnd) of the toppling block from the full equation
    I theta'' = M(theta) (closedForms.topple), RK4 from rest."""
    tp = cf.topple
    b, h, _ = tp.regimes["toppling"]
    a = math.radians(tp.a)
    c = 3*tp.g/(2*(b*b + h*h))

    def f(y):
        th = y[0]
        return np.array([y[1], c*((h*math.sin(a) - b*math.cos(a))*math.cos(th)
                                  + (h*math.cos(a) + b*math.sin(a))*math.sin(th))])
    y = np.zeros(2)
    dt = tEnd/n
    for _ in range(n):
        k1 = f(y)
        k2 = f(y + dt/2*k1)
        k3 = f(y + dt/2*k2)
        k4 = f(y + dt*k3)
        y = y + dt/6*(k1 + 2*k2 + 2*k3 + k4)
    return float(y[0])


def stickSlipIntegrated(dt=1e-5):
    """[(start, end, plateau x)] of the stick-slip block by a direct
    integration of m x'' = F(t) - mu m g sgn(x') with sticking while
    |F| <= mu m g (midpoint rule, the switches located within a step),
    independent of closedForms.stickSlip's piecewise solution."""
    ss = cf.stickSlip
    limit = ss.mu*ss.m*ss.g
    t, x, v, s = 0.0, 0.0, 0.0, 0.0
    result = []
    start = None
    n = int(round(ss.endTime/dt))
    for i in range(n):
        t = i*dt
        if s == 0:
            if abs(ss.force(t)) > limit:
                # |F| crosses the friction within the step: start there
                f = lambda u: abs(ss.force(u)) - limit  # noqa: E731
                start = ss._root(f, t - dt, t) if i else 0.0
                s = 1.0 if ss.force(t) > 0 else -1.0
            else:
                continue
        a = (ss.force(t + dt/2) - s*limit)/ss.m
        v1 = v + a*dt
        if s*v1 < 0:
            # Stops within the step: the fraction where v reaches 0
            h = -v/a
            x += v*h + a*h*h/2
            result.append((start, t + h, x))
            v, s = 0.0, 0.0
            continue
        x += (v + v1)/2*dt
        v = v1
    return result


# --------------------------------------------------------------------------
EVAL_NAMES = {
    "sqrt": np.sqrt, "sin": np.sin, "cos": np.cos, "exp": np.exp,
    "log": np.log, "atan2": np.arctan2, "hypot": np.hypot, "mag": np.abs,
    "pow": np.power, "sqr": np.square, "pi": lambda: math.pi,
    "vector": lambda a, b, c: (a, b, c),
}


def expressions(text):
    """name -> {keyword: expression} for the patches of a 0/D file."""
    out = {}
    for m in re.finditer(r"(\w+)\s*\{([^{}]*)\}", text):
        exprs = dict(re.findall(r"(\w+)\s+expression\s+\"([^\"]*)\"", m.group(2)))
        if exprs:
            out[m.group(1)] = exprs
    return out


def evaluate(expr, x, y, t=1.0):
    return eval(expr, {"__builtins__": {}}, dict(EVAL_NAMES, x=x, y=y, t=t))


def material(caseDir):
    text = (caseDir/"constant/mechanicalProperties").read_text()
    E = float(re.search(r"\bE\s+([-+0-9.eE]+)\s*;", text).group(1))
    nu = float(re.search(r"\bnu\s+([-+0-9.eE]+)\s*;", text).group(1))
    ps = re.search(r"planeStress\s+(\w+)\s*;", text).group(1) == "yes"
    return E, nu, ps


def tutorials(projectDir):
    tut = Path(projectDir)/"tutorials/verification"
    for name, sol in (("cantilever", cf.cantilever), ("plateHole", cf.kirsch),
                      ("lame", cf.lame), ("sneddon/angle0", cf.sneddon),
                      ("sneddon/angle30", cf.sneddon), ("sneddon/angle45", cf.sneddon),
                      ("waveBar", cf.waveBar)):
        E, nu, ps = material(tut/name)
        expect(E == sol.E and nu == sol.nu and ps == sol.planeStress,
               "%s: E, nu, planeStress as in closedForms" % name)

    b = cf.cantilever
    ex = expressions((tut/"cantilever/0/D").read_text())
    y = np.linspace(-b.D/2, b.D/2, 41)
    v = evaluate(ex["fixedEnd"]["value"], 0*y, y)
    u = b.displacement(0*y, y)
    err = max(np.abs(v[0] - u[0]).max(), np.abs(v[1] - u[1]).max())/b.tipDeflection()
    expect(err < 1e-12, "cantilever: fixedEnd value = exact u at x = 0 (%.1e)" % err)
    v = evaluate(ex["loadedEnd"]["traction"], 0*y + b.L, y)
    s = b.stress(0*y + b.L, y)
    err = max(np.abs(v[0] - s[0]).max(), np.abs(v[1] - s[2]).max())/b.P
    expect(err < 1e-12, "cantilever: loadedEnd traction = sigma.n at x = L (%.1e)" % err)

    k = cf.kirsch
    ex = expressions((tut/"plateHole/0/D").read_text())
    q = np.linspace(0, k.side, 41)
    side = 0*q + k.side
    v = evaluate(ex["right"]["traction"], side, q)
    s = k.stress(side, q)
    err = max(np.abs(v[0] - s[0]).max(), np.abs(v[1] - s[2]).max())
    expect(err < 1e-12, "plateHole: right traction = sigma.(1 0) on x = 5 (%.1e)" % err)
    v = evaluate(ex["top"]["traction"], q, side)
    s = k.stress(q, side)
    err = max(np.abs(v[0] - s[2]).max(), np.abs(v[1] - s[1]).max())
    expect(err < 1e-12, "plateHole: top traction = sigma.(0 1) on y = 5 (%.1e)" % err)


# --------------------------------------------------------------------------
CHECKERS = {"cantilever": ("checkCantilever.py", []),
            "plateHole": ("checkPlateHole.py", []),
            "lame": ("checkLame.py", []),
            "sneddon": ("checkSneddon.py", ["30"]),
            "freeFall": ("checkFreeFall.py", []),
            "waveBar": ("checkWaveBar.py", []),
            "incline": ("checkIncline.py", ["20"]),
            "inclineStatic": ("checkIncline.py", ["31"]),
            "toppleStable": ("checkTopple.py", ["stable"]),
            "toppleSliding": ("checkTopple.py", ["sliding"]),
            "toppleToppling": ("checkTopple.py", ["toppling"]),
            "toppleSlip": ("checkTopple.py", ["toppling"]),
            "bouncingBlock": ("checkBouncingBlock.py", ["trapezoidal"]),
            "bouncingBlockDDA": ("checkBouncingBlock.py", ["DDA"]),
            "pushedBlock": ("checkPushedBlock.py", []),
            "stickSlip": ("checkStickSlip.py", [])}


def checker(case, workDir, generator="makeSynthetic.py", checkers=CHECKERS):
    """The case's checker passes on exact synthetic data and fails on
    tampered data (generator: the script under synthetic/)."""
    script, extra = checkers[case]
    work = Path(workDir)
    for tamper, expected in ((False, 0), (True, 1)):
        out = work/(case + ("Tampered" if tamper else "Exact"))
        if out.exists():
            import shutil
            shutil.rmtree(out)
        gen = [sys.executable, str(HERE/"synthetic"/generator), case, str(out)]
        subprocess.run(gen + (["--tamper"] if tamper else []), check=True)
        res = subprocess.run([sys.executable, str(HERE/script), str(out)] + extra,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True)
        print(res.stdout)
        expect(res.returncode == expected, "%s on %s data exits %d (got %d)"
               % (script, "tampered" if tamper else "exact", expected, res.returncode))


def rates(workDir):
    """checkCantilever.py on three synthetic levels: exact data (nodal
    values, element stresses at centroids: L2 rate 2, energy rate 1) must
    pass, data with an O(h) error must fail."""
    import shutil
    for tamper, expected in ((False, 0), (True, 1)):
        dirs = []
        for level in range(3):
            out = Path(workDir)/("cantilever%s_L%d" % ("Tampered" if tamper else "Exact", level))
            if out.exists():
                shutil.rmtree(out)
            subprocess.run([sys.executable, str(HERE/"synthetic/makeSynthetic.py"),
                            "cantilever", str(out), "--level", str(level)]
                           + (["--tamper"] if tamper else []), check=True)
            dirs.append(str(out))
        res = subprocess.run([sys.executable, str(HERE/"checkCantilever.py")] + dirs,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True)
        print(res.stdout)
        expect(res.returncode == expected, "checkCantilever.py rates on %s data exits %d (got %d)"
               % ("tampered" if tamper else "exact", expected, res.returncode))


# --------------------------------------------------------------------------
# Contact cases (docs/verification.md, Contact table)
# --------------------------------------------------------------------------
def contactClosedForms():
    h = cf.hertz
    expect(abs(h.halfWidth() - 0.1076) < 5e-5 and abs(h.peakPressure() - 0.0591) < 5e-5,
           "hertz: a = 0.1076, p0 = 0.0591 (%.5g, %.5g)" % (h.halfWidth(), h.peakPressure()))
    xs = np.linspace(-h.halfWidth(), h.halfWidth(), 20001)
    load = np.trapz(h.pressure(np.abs(xs)), xs)
    expect(abs(load - h.P)/h.P < 1e-6, "hertz: pressure integrates to P (%.8g)" % load)
    d = cf.discOnDisc
    expect(abs(d.Reff() - 0.5) < 1e-15 and abs(d.halfWidth() - h.halfWidth())/h.halfWidth() < 1e-3,
           "discOnDisc: R = 1/2, a within 0.1%% of the flat's (%.5g)" % d.halfWidth())
    b = cf.brazilian
    expect(abs(b.centreTension() - 1.273e6)/1.273e6 < 5e-4,
           "brazilian: 2P/(pi D t) = 1.273 MPa (%.6g)" % b.centreTension())
    sxx, syy, sxy = b.stress(np.array([0.0]), np.array([0.0]))
    expect(abs(sxx[0] - b.centreTension()) < 1e-6*b.centreTension()
           and abs(sxy[0]) < 1e-9*b.centreTension(),
           "brazilian: stress field gives the centre value")
    rng = np.random.default_rng(2)
    R = b.D/2
    r = rng.uniform(0, 0.8*R, 200)
    t = rng.uniform(0, 2*math.pi, 200)
    fx, fy = fdDivergence(b.stress, r*np.cos(t), r*np.sin(t), 1e-7)
    err = max(np.abs(fx).max(), np.abs(fy).max())*R/b.centreTension()
    expect(err < 1e-5, "brazilian: div sigma = 0 (%.1e)" % err)
    th = np.linspace(-1.2, 1.2, 50)
    X, Y = R*np.cos(th), R*np.sin(th)
    sxx, syy, sxy = b.stress(X, Y)
    tx = sxx*np.cos(th) + sxy*np.sin(th)
    ty = sxy*np.cos(th) + syy*np.sin(th)
    err = max(np.abs(tx).max(), np.abs(ty).max())/b.centreTension()
    expect(err < 1e-9, "brazilian: rim traction free away from the loads (%.1e)" % err)
    bi = cf.bondedInterface
    expect(bi.tensionPeak() == 1e6 and abs(bi.shearPeak(5e6) - (2e6 + 5e6/math.sqrt(3))) < 1e-6
           and abs(bi.shearResidual(1e6) - 1e6/math.sqrt(3)) < 1e-6,
           "bondedInterface: T L, c L + sigma_n L tan 30, sigma_n L tan 30")


CONTACT_CHECKERS = {"hertz": ("checkHertz.py", ["hertz"]),
                    "discOnDisc": ("checkHertz.py", ["discOnDisc"]),
                    "brazilian": ("checkBrazilian.py", []),
                    "bondedTension": ("checkBondedInterface.py", ["tension"]),
                    "bondedShear": ("checkBondedInterface.py", ["shear", "1"])}


def contactChecker(case, workDir):
    checker(case, workDir, "makeSyntheticContact.py", CONTACT_CHECKERS)


def main(argv):
    if not argv:
        print(__doc__)
        return 1
    if argv[0] == "closedForms":
        closedForms()
    elif argv[0] == "tutorials" and len(argv) == 2:
        tutorials(argv[1])
    elif argv[0] == "contactClosedForms":
        contactClosedForms()
    elif argv[0] == "contactChecker" and len(argv) == 3 and argv[1] in CONTACT_CHECKERS:
        contactChecker(argv[1], argv[2])
    elif argv[0] == "rates" and len(argv) == 2:
        rates(argv[1])
    elif argv[0] == "checker" and len(argv) == 3 and argv[1] in CHECKERS:
        checker(argv[1], argv[2])
    else:
        print(__doc__)
        return 1
    print("%s: %s" % (" ".join(argv[:2]), "FAILED: %d" % len(failures) if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
