#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""A co-simulation master driving the FMUs the way an FMI 3.0 importer does
(tutorials/coupling/fmi3Master.py: unzip, read modelDescription.xml, load
binaries/x86_64-linux/<modelIdentifier>.so by name, call the sequence):

    fmuMaster.py <fmuDir> <projectDir> <binDir> <workDir>

1. fractureFlow.fmu's model description: unique value references, FMI 3.0
   causalities, every array dimension a UInt64 structural parameter, every
   unit defined; the binary exports every co-simulation function of the
   standard and fmi3GetVersion() is "3.0".
2. The call sequence on fractureFlow.fmu (two blocks pressed together by
   5 MPa on the top, a fracture between them): instantiate, initialize,
   load in one step and settle in a second; then
     - equilibrium of the upper block: the contacts carry the top load,
       sum(t_n L) = 5 MPa x 40 mm, to 1e-5;
     - a closed contact's aperture is the residual aperture; the entries
       of the fracture arrays beyond fractures.nFaces are zero;
     - a fluid pressure p = 1 MPa set on every contact: the contacts then
       carry sum(t_n L) = 5 MPa x 40 mm - p sum(L) (Terzaghi's effective
       stress, the paper's Eq. 8), to 1e-5;
     - rolled back with fmi3SetFMUState: the time, the outputs and the
       inputs are those of the saved state, and the step repeated with the
       same pressure gives the same outputs bit for bit;
     - the VTK frames its couplingDict asks for are at t = 0, 1, 2 and 3,
       the repeated step's in place of the first.
3. Wrong calls on thermalBlocks.fmu, each an error status with a logged
   message that says what was wrong, never a crash: a wrong
   instantiationToken or resource path, calls out of order, an unknown
   value reference, the wrong number of values, NaN and negative
   temperatures, setting an output or a structural parameter, a type the
   FMU has no variables of, a step from the wrong time or of zero length,
   and calls after fmi3Terminate. None changes anything: the instance
   then expands by the closed form's (1 + nu) alpha dT. fmi3Reset takes
   it back to the start.
4. Two instances of thermalBlocks.fmu at once, each heated by its own dT,
   each expand by their own closed form; fmi3GetFMUState on a state it
   gave before overwrites it.
5. With loggingOn, the solver's steps and open-close iterations come as
   logSolver messages, until fmi3SetDebugLogging turns them off.
6. A dynamic case (tutorials/verification/freeFall, packed here): two
   communication steps, each the solid's own steps, fall by -g t^2/2 to
   1e-10 (DDA with the velocity carried over is exact for a free fall).
7. A step the solid cannot complete (fractureFlow allowed one open-close
   iteration, packed here, its fracture pressed open): fmi3Discard with
   the last time reached and a logged reason; restored, the instance
   steps on.
8. A pile (tutorials/contact/grainsInBox, packed here): grains falling
   into a box, contacts opening, sticking and sliding, stepped to
   t = 0.3 in communication steps of 0.01; states saved with
   fmi3GetFMUState at t = 0.05, 0.15 and 0.25 and each restored with
   fmi3SetFMUState and stepped to t = 0.3 again end with the same
   contacts and contact tractions, bit for bit.
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import ctypes as C
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fmuChecks  # noqa: E402
sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
import nmmVtk  # noqa: E402

COSIMULATION_FUNCTIONS = """GetVersion SetDebugLogging InstantiateModelExchange
InstantiateCoSimulation InstantiateScheduledExecution FreeInstance
EnterInitializationMode ExitInitializationMode EnterEventMode Terminate Reset
GetFloat32 GetFloat64 GetInt8 GetUInt8 GetInt16 GetUInt16 GetInt32 GetUInt32
GetInt64 GetUInt64 GetBoolean GetString GetBinary GetClock SetFloat32 SetFloat64
SetInt8 SetUInt8 SetInt16 SetUInt16 SetInt32 SetUInt32 SetInt64 SetUInt64
SetBoolean SetString SetBinary SetClock GetNumberOfVariableDependencies
GetVariableDependencies GetFMUState SetFMUState FreeFMUState
SerializedFMUStateSize SerializeFMUState DeserializeFMUState
GetDirectionalDerivative GetAdjointDerivative EnterConfigurationMode
ExitConfigurationMode GetIntervalDecimal GetIntervalFraction GetShiftDecimal
GetShiftFraction SetIntervalDecimal SetIntervalFraction SetShiftDecimal
SetShiftFraction EvaluateDiscreteStates UpdateDiscreteStates EnterStepMode
GetOutputDerivatives DoStep""".split()

F_TOP = 5e6*0.04        # the top load per unit thickness [N/m]


def modelDescription(t, fmi3Master, fmu):
    root = ET.parse(fmu.dir/"modelDescription.xml").getroot()
    units = {u.get("name") for u in root.iter("Unit")}
    vrs = [v.vr for v in fmu.variables.values()]
    t.check(len(vrs) == len(set(vrs)), "%d variables, unique value references" % len(vrs))
    allowed = {"independent", "structuralParameter", "parameter", "input", "output"}
    t.check(all(v.causality in allowed for v in fmu.variables.values()),
            "every causality is one of FMI 3.0's")
    dims = [fmu.byVr.get(n) for v in fmu.variables.values() for k, n in v.dimensions if k == "ref"]
    t.check(dims and all(d is not None and d.type == "UInt64" and d.causality
                         == "structuralParameter" for d in dims),
            "every array dimension is a UInt64 structural parameter")
    t.check(all(v.unit is None or v.unit in units for v in fmu.variables.values()),
            "every unit is defined in UnitDefinitions")
    missing = [f for f in COSIMULATION_FUNCTIONS if not hasattr(fmu.lib, "fmi3" + f)]
    t.check(not missing, "the binary exports the %d co-simulation functions (missing: %s)"
            % (len(COSIMULATION_FUNCTIONS), missing))
    t.check(fmu.lib.fmi3GetVersion() == b"3.0", "fmi3GetVersion() is 3.0")


def contacts(solid):
    n = int(solid.get("fractures.nFaces"))
    return n, solid.get("fractures.length")[:n], solid.get("fractures.contactTraction")[:n]


def sequence(t, fmi3Master, fmu):
    solid = fmu.initialized("fracture")
    capacity = int(solid.get("fractures.capacity"))
    for k in range(2):
        status, last = solid.doStep(float(k), 1.0)
        t.check(status == fmi3Master.OK and last == k + 1.0, "step %d to t = %g" % (k + 1, last))
    n, L, tr = contacts(solid)
    t.check(0 < n <= capacity, "%d contacts, within the capacity %d" % (n, capacity))
    t.close(1e-5, float(tr[:, 0] @ L), F_TOP, F_TOP, "the contacts carry the top load")
    jump = solid.get("fractures.normalJump")
    aperture = solid.get("fractures.aperture")
    residual = solid.get("fractures.residualAperture")
    closed = jump[:n] <= 0
    t.check(closed.any() and np.all(aperture[:n][closed] == residual),
            "%d closed contacts, at the residual aperture %g" % (closed.sum(), residual))
    bodies = solid.get("fractures.bodies")
    t.check(all(sorted(b) == [0, 1] for b in bodies[:n].tolist()),
            "every contact separates the lower block (0) from the upper (1)")
    t.check(solid.get("top.bodies").tolist() == [[1, 1]], "the top's face is the upper block's")
    t.check(not aperture[n:].any() and not jump[n:].any() and not bodies[n:].any()
            and not solid.get("fractures.contactTraction")[n:].any(),
            "the arrays are zero beyond fractures.nFaces")

    saved = solid.getState()
    topSaved = solid.get("top.displacement").copy()
    p = np.zeros(capacity)
    p[:n] = 1e6
    solid.set("fractures.pressure", p)
    solid.doStep(2.0, 1.0)
    n3, L3, tr3 = contacts(solid)
    t.close(1e-5, float(tr3[:, 0] @ L3), F_TOP - 1e6*L3.sum(), F_TOP,
            "with p = 1 MPa the contacts carry the top load less p sum(L)")
    first = (solid.get("top.displacement"), solid.get("fractures.contactTraction"),
             solid.get("fractures.aperture"))

    solid.setState(saved)
    t.check(solid.get("time") == 2.0, "fmi3SetFMUState: back at t = 2")
    t.check(np.array_equal(solid.get("top.displacement"), topSaved),
            "fmi3SetFMUState: the outputs are the saved state's")
    t.check(not solid.get("fractures.pressure").any(),
            "fmi3SetFMUState: the pressure is the saved state's (none)")
    solid.set("fractures.pressure", p)
    solid.doStep(2.0, 1.0)
    again = (solid.get("top.displacement"), solid.get("fractures.contactTraction"),
             solid.get("fractures.aperture"))
    t.check(all(np.array_equal(a, b) for a, b in zip(first, again)),
            "the repeated step gives the same outputs bit for bit")
    solid.freeState(saved)
    solid.terminate()
    solid.free()

    # vtkDirectory "VTK": a frame at the start and after every step, the
    # repeated step's replacing the first
    series = nmmVtk.seriesEntries(t.work/"VTK"/"fractureFlow.vtu.series")
    times = [time for time, _ in series]
    t.check(times == [0, 1, 2, 3], "VTK frames at t = %s" % times)
    t.check(all((t.work/"VTK"/name).is_file() for _, name in series),
            "every frame of the series exists")


def expectError(t, solid, what, phrase, function, *args):
    before = len(solid.messages)
    status = solid.call(function, *args)
    logged = solid.messages[before:]
    text = logged[-1][2] if logged else ""
    t.check(status == 3 and phrase in text and logged[-1][1] == "logStatusError",
            "%s: fmi3Error, logged: %s" % (what, text or "(nothing)"))


def wrongCalls(t, fmi3Master, fmu):
    for what, kwargs, phrase in (
            ("wrong instantiationToken", {"token": "{0}"}, "instantiationToken"),
            ("no case at resourcePath", {"resources": str(t.work/"nowhere") + "/"}, "nowhere")):
        try:
            fmu.instantiate("thermal", **kwargs)
            t.check(False, what + ": instantiated")
        except fmi3Master.fmiError as e:
            t.check(phrase in str(e), "%s: no instance, logged: %s" % (what, e))

    s = fmu.instantiate("thermal")
    V = fmi3Master.VR
    vr = {name: v.vr for name, v in fmu.variables.items()}
    one = lambda name: (V*1)(vr[name])                          # noqa: E731
    two = lambda *x: (C.c_double*len(x))(*x)                    # noqa: E731
    out = (C.c_double*8)()
    flags = [C.c_bool() for _ in range(3)]
    last = C.c_double()
    step = lambda t0, h: ("DoStep", t0, h, False, *(C.byref(f) for f in flags),  # noqa: E731
                          C.byref(last))

    expectError(t, s, "an output before initialization", "reading blocks.stress is not allowed in instantiated mode",
                "GetFloat64", one("blocks.stress"), 1, out, 8)
    expectError(t, s, "a step before initialization", "a step is not allowed in instantiated mode",
                *step(0.0, 1.0))
    expectError(t, s, "initialization at another start time", "startTime 5 is not the case's start time 0",
                "EnterInitializationMode", False, 0.0, 5.0, False, 0.0)
    s.enterInitializationMode(0.0)
    s.exitInitializationMode()
    expectError(t, s, "leaving initialization twice", "leaving initialization is not allowed in step",
                "ExitInitializationMode")
    expectError(t, s, "an unknown value reference", "unknown value reference 999",
                "SetFloat64", (V*1)(999), 1, two(300.0), 1)
    expectError(t, s, "one temperature for two blocks", "2 values, nValues is 1",
                "SetFloat64", one("blocks.temperature"), 1, two(300.0), 1)
    expectError(t, s, "a NaN temperature", "not finite",
                "SetFloat64", one("blocks.temperature"), 1, two(300.0, math.nan), 2)
    expectError(t, s, "a negative temperature", "finite and positive",
                "SetFloat64", one("blocks.temperature"), 1, two(300.0, -5.0), 2)
    expectError(t, s, "setting an output", "is an output",
                "SetFloat64", one("blocks.stress"), 1, (C.c_double*8)(), 8)
    expectError(t, s, "setting a structural parameter", "cannot be set",
                "SetUInt64", one("blocks.nBlocks"), 1, (C.c_uint64*1)(3), 1)
    expectError(t, s, "a UInt64 read as Float64", "is a UInt64, not a Float64",
                "GetFloat64", one("blocks.nBlocks"), 1, out, 1)
    expectError(t, s, "a type without variables", "only Float64 and UInt64",
                "GetInt32", one("time"), 1, (C.c_int32*1)(), 1)
    expectError(t, s, "a step from the wrong time", "a step from 0.5, but the solid is at 0", *step(0.5, 1.0))
    expectError(t, s, "a step of zero length", "must be positive", *step(0.0, 0.0))
    expectError(t, s, "event mode", "not provided", "EnterEventMode")

    T = s.get("blocks.temperature")
    t.check(np.all(T == 293.15), "the rejected calls changed nothing: T = %s" % T)
    s.set("blocks.temperature", [343.15, 343.15])
    status, _ = s.doStep(0.0, 1.0)
    ux = s.get("freeRight.displacement")[0][0]
    eps = 1.25*8e-6*50
    t.close(1e-9, ux, eps, eps, "after the rejected calls the free block expands as it must")
    s.terminate()
    expectError(t, s, "an input after fmi3Terminate", "setting inputs is not allowed in terminated mode",
                "SetFloat64", one("blocks.temperature"), 1, two(300.0, 300.0), 2)
    expectError(t, s, "a step after fmi3Terminate", "a step is not allowed in terminated mode",
                *step(1.0, 1.0))
    s.check("Reset")
    s.enterInitializationMode(0.0)
    s.exitInitializationMode()
    t.check(s.get("time") == 0.0 and np.all(s.get("blocks.temperature") == 293.15)
            and s.get("freeRight.displacement")[0][0] == 0.0,
            "fmi3Reset: back at t = 0, at Tref and undeformed")
    s.set("blocks.temperature", [343.15, 343.15])
    status, last = s.doStep(0.0, 1.0)
    t.close(1e-9, s.get("freeRight.displacement")[0][0], eps, eps,
            "after fmi3Reset the free block expands again")
    s.free()


def solverLog(t, fmi3Master, fmu):
    """loggingOn sends the solver's log as logSolver messages;
    fmi3SetDebugLogging turns it off"""
    solid = fmu.instantiate("logged", loggingOn=True)
    solid.enterInitializationMode(0.0)
    solid.exitInitializationMode()
    solid.doStep(0.0, 1.0)
    lines = [m for s, c, m in solid.messages if c == "logSolver"]
    t.check(any("step from 0 by 1" in m for m in lines)
            and any("open-close" in m for m in lines),
            "loggingOn: %d logSolver messages, the step and its open-close iterations"
            % len(lines))
    solid.check("SetDebugLogging", False, 0, None)
    before = len(solid.messages)
    solid.doStep(1.0, 1.0)
    t.check(len(solid.messages) == before, "fmi3SetDebugLogging(false): no more messages")
    solid.free()


def twoInstances(t, fmi3Master, fmu):
    """Instances share nothing: each its own temperature and result; a state
    given to fmi3GetFMUState again is overwritten with the present one"""
    a, b = fmu.initialized("a"), fmu.initialized("b")
    state = a.getState()
    for s, dT in ((a, 10.0), (b, 40.0)):
        s.set("blocks.temperature", [293.15 + dT]*2)
    for s in (a, b):
        s.doStep(0.0, 1.0)
    ux = [s.get("freeRight.displacement")[0][0] for s in (a, b)]
    eps = 1.25*8e-6
    t.close(1e-9, ux[0], eps*10, eps*10, "instance a: its own expansion")
    t.close(1e-9, ux[1], eps*40, eps*40, "instance b: its own expansion")
    a.check("GetFMUState", C.byref(state))      # overwrite: the state at t = 1
    a.doStep(1.0, 1.0)
    a.setState(state)
    t.check(a.get("time") == 1.0, "fmi3GetFMUState on a given state overwrote it (t = 1)")
    a.freeState(state)
    for s in (a, b):
        s.free()


def freeFall(t, fmi3Master):
    """A dynamic case: tutorials/verification/freeFall with a patch on its
    bottom edge, packed with nmmFmuExport here; two communication steps of
    0.05 s, each the solid's own steps"""
    fmu = packed(t, "tutorials/verification/freeFall", [
        ("system/nmmMeshDict", "patches\n{\n}",
         "patches\n{\n    bottom { type box; min (-1 -1e-9); max (2 1e-9); }\n}"),
        ("0/D", "    // No patch: every edge is traction free\n", "    bottom { type"
         " tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }\n")],
        {"system/couplingDict": "FoamFile { version 2.0; format ascii; class dictionary;"
         " object couplingDict; }\nmodelName freeFall;\n"
         "regions { bottom { read (); write (displacement); } }\n"})
    solid = fmi3Master.fmu(fmu, t.work/"freeFallFmu").initialized("fall")
    for k in (1, 2):
        status, last = solid.doStep(0.05*(k - 1), 0.05)
        y = -9.81*(0.05*k)**2/2
        t.close(1e-10, solid.get("bottom.displacement")[0][1], y, abs(y),
                "free fall through the FMU at t = %g (-g t^2/2)" % last)
    solid.free()


def packed(t, tutorial, edits, files=None):
    """A copy of a tutorial with its files edited ((file, old, new) ...)
    and written ({file: text}), packed by nmmFmuExport; the path of its FMU"""
    case = t.work/Path(tutorial).name
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(t.project/tutorial, case,
                    ignore=shutil.ignore_patterns("VTK", "log.*", "[1-9]*", "0.*", "*.fmu",
                                                  "nmmMesh", "postProcessing", "driver"))
    for name, old, new in edits:
        text = (case/name).read_text()
        if old not in text:
            raise SystemExit("%s: no '%s' to replace" % (case/name, old))
        (case/name).write_text(text.replace(old, new))
    for name, text in (files or {}).items():
        (case/name).write_text(text)
    with open(case/"log.nmmFmuExport", "w") as log:
        subprocess.run([str(t.bin/"nmmFmuExport"), "-case", str(case)], stdout=log,
                       stderr=subprocess.STDOUT, check=True)
    return next(case.glob("*.fmu"))


def discard(t, fmi3Master):
    """A step the solid cannot complete: fractureFlow allowed one open-close
    iteration, its fracture opened by a pressure above the normal stress"""
    fmu = packed(t, "tutorials/coupling/fractureFlow", [("system/nmmSolution",
        "maxOpenCloseIterations  30;", "maxOpenCloseIterations  1;")])
    solid = fmi3Master.fmu(fmu, t.work/"discardFmu").initialized("discard")
    solid.doStep(0.0, 1.0)
    saved = solid.getState()
    n, capacity = int(solid.get("fractures.nFaces")), int(solid.get("fractures.capacity"))
    p = np.zeros(capacity)
    p[:n] = 2e7
    solid.set("fractures.pressure", p)
    status, last = solid.doStep(1.0, 1.0)
    category, message = solid.messages[-1][1:] if solid.messages else ("", "")
    t.check(status == fmi3Master.DISCARD and last == 1.0 and category == "logStatusDiscard"
            and "did not settle" in message,
            "a step that cannot converge: fmi3Discard at the last time reached (%g), logged:"
            " %s" % (last, message))
    solid.setState(saved)
    p[:n] = 1e6
    solid.set("fractures.pressure", p)
    status, last = solid.doStep(1.0, 1.0)
    t.check(status == fmi3Master.OK and last == 2.0,
            "restored, with a pressure below the normal stress it steps on (to t = %g)" % last)
    solid.freeState(saved)
    solid.free()


def pileRestored(t, fmi3Master):
    """States of a pile, restored and stepped on, repeat the run"""
    fmu = packed(t, "tutorials/contact/grainsInBox", [], {
        "system/couplingDict": "FoamFile { version 2.0; format ascii; class dictionary;"
        " object couplingDict; }\nmodelName grainsInBox;\n"
        "regions { fractures { read (); write (contactTraction slip); maxFaces 400; } }\n"})
    solid = fmi3Master.fmu(fmu, t.work/"grainsInBoxFmu").initialized("pile")
    h, steps = 0.01, 30
    saved = {}

    def outputs():
        return (solid.get("fractures.nFaces"), solid.get("fractures.bodies"),
                solid.get("fractures.contactTraction"), solid.get("fractures.slip"))

    def stepTo(k0):
        for k in range(k0, steps):
            status, _ = solid.doStep(k*h, h)
            if status != fmi3Master.OK:
                return False
            if k + 1 in (5, 15, 25) and k + 1 not in saved:
                saved[k + 1] = solid.getState()
        return True

    t.check(stepTo(0), "the pile steps to t = 0.3 through the FMU")
    reference = outputs()
    t.check(reference[0] > 20, "%d contacts at t = 0.3" % reference[0])
    for k, state in sorted(saved.items()):
        solid.setState(state)
        again = stepTo(k) and outputs()
        t.check(again and all(np.array_equal(a, b) for a, b in zip(reference, again)),
                "restored at t = %g and stepped to 0.3: the same contacts and"
                " tractions, bit for bit" % (k*h))
    for state in saved.values():
        solid.freeState(state)
    solid.free()


def main():
    t = fmuChecks.run(__doc__)
    import fmi3Master
    # The FMU writes its VTK frames relative to the working directory
    os.chdir(t.work)
    shutil.rmtree(t.work/"VTK", ignore_errors=True)
    fracture = fmi3Master.fmu(t.fmus/"fractureFlow.fmu", t.work/"fractureFlow")
    modelDescription(t, fmi3Master, fracture)
    sequence(t, fmi3Master, fracture)
    solverLog(t, fmi3Master, fracture)
    thermal = fmi3Master.fmu(t.fmus/"thermalBlocks.fmu", t.work/"thermalBlocks")
    wrongCalls(t, fmi3Master, thermal)
    twoInstances(t, fmi3Master, thermal)
    freeFall(t, fmi3Master)
    discard(t, fmi3Master)
    pileRestored(t, fmi3Master)
    return t.end()


if __name__ == "__main__":
    sys.exit(main())
