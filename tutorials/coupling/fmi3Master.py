#!/usr/bin/python3
# Needs Debian's /usr/bin/python3 (python3-numpy).
"""A minimal FMI 3.0 co-simulation importer, in Python's standard library
(zipfile, xml.etree, ctypes) and numpy: how a coupled solver or a
co-simulation master drives the nmmSolid FMU that nmmFmuExport packs.

    fmu = fmi3Master.fmu("sneddonCrack.fmu")    # unzip, read the model
    solid = fmu.instantiate("solid")            # description, load the binary
    solid.enterInitializationMode(0.0)          # (or both at once:
    solid.exitInitializationMode()              #  fmu.initialized("solid"))
    solid.set("crack.pressure", p)              # arrays by variable name
    saved = solid.getState()                    # for an implicit loop
    status, t = solid.doStep(0.0, 1.0)          # OK, or DISCARD and the time reached
    d = solid.get("crack.displacement")         # numpy array [n, 2]
    solid.setState(saved)                       # repeat the step
    solid.terminate(); solid.free()

Every call checks the status; a status other than fmi3OK raises fmiError
with the FMU's logged message. call() gives the bare status instead.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import ctypes as C
import shutil
import tempfile
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np

OK, WARNING, DISCARD, ERROR, FATAL = range(5)
STATUS = ("fmi3OK", "fmi3Warning", "fmi3Discard", "fmi3Error", "fmi3Fatal")

LOGGER = C.CFUNCTYPE(None, C.c_void_p, C.c_int, C.c_char_p, C.c_char_p)
VR = C.c_uint32


class fmiError(RuntimeError):
    def __init__(self, function, status, message):
        super().__init__("%s returned %s: %s" % (function, STATUS[status], message))
        self.status = status


class variable:
    def __init__(self, e):
        self.name = e.get("name")
        self.vr = int(e.get("valueReference"))
        self.type = e.tag
        self.causality = e.get("causality")
        self.unit = e.get("unit")
        self.start = e.get("start")
        # Each dimension: a fixed size, or the value reference of the
        # structural parameter holding it
        self.dimensions = [("fixed", int(d.get("start"))) if d.get("start") is not None
                           else ("ref", int(d.get("valueReference")))
                           for d in e.findall("Dimension")]


class fmu:
    """An extracted FMU: its model description and its binary"""

    def __init__(self, path, extractTo=None):
        self.dir = Path(extractTo or tempfile.mkdtemp(prefix="fmu."))
        with zipfile.ZipFile(path) as z:
            z.extractall(self.dir)
        root = ET.parse(self.dir / "modelDescription.xml").getroot()
        if root.get("fmiVersion") != "3.0":
            raise RuntimeError("%s is not an FMI 3.0 FMU" % path)
        self.token = root.get("instantiationToken")
        cs = root.find("CoSimulation")
        if cs is None:
            raise RuntimeError("%s has no co-simulation interface" % path)
        self.modelIdentifier = cs.get("modelIdentifier")
        self.variables = {}
        for e in root.find("ModelVariables"):
            v = variable(e)
            self.variables[v.name] = v
        self.byVr = {v.vr: v for v in self.variables.values()}
        self.lib = C.CDLL(str(self.dir / "binaries" / "x86_64-linux"
                              / (self.modelIdentifier + ".so")))
        self._declare()

    def _declare(self):
        L = self.lib
        arr = C.POINTER
        L.fmi3GetVersion.restype = C.c_char_p
        L.fmi3InstantiateCoSimulation.restype = C.c_void_p
        L.fmi3InstantiateCoSimulation.argtypes = [
            C.c_char_p, C.c_char_p, C.c_char_p, C.c_bool, C.c_bool, C.c_bool, C.c_bool,
            arr(VR), C.c_size_t, C.c_void_p, LOGGER, C.c_void_p]
        L.fmi3FreeInstance.argtypes = [C.c_void_p]
        L.fmi3FreeInstance.restype = None
        L.fmi3EnterInitializationMode.argtypes = [
            C.c_void_p, C.c_bool, C.c_double, C.c_double, C.c_bool, C.c_double]
        for f in ("ExitInitializationMode", "Terminate", "Reset"):
            getattr(L, "fmi3" + f).argtypes = [C.c_void_p]
        L.fmi3GetFloat64.argtypes = [C.c_void_p, arr(VR), C.c_size_t, arr(C.c_double),
                                     C.c_size_t]
        L.fmi3SetFloat64.argtypes = L.fmi3GetFloat64.argtypes
        L.fmi3GetUInt64.argtypes = [C.c_void_p, arr(VR), C.c_size_t, arr(C.c_uint64),
                                    C.c_size_t]
        L.fmi3SetUInt64.argtypes = L.fmi3GetUInt64.argtypes
        L.fmi3SetDebugLogging.argtypes = [C.c_void_p, C.c_bool, C.c_size_t,
                                           C.POINTER(C.c_char_p)]
        L.fmi3GetFMUState.argtypes = [C.c_void_p, arr(C.c_void_p)]
        L.fmi3SetFMUState.argtypes = [C.c_void_p, C.c_void_p]
        L.fmi3FreeFMUState.argtypes = [C.c_void_p, arr(C.c_void_p)]
        L.fmi3DoStep.argtypes = [C.c_void_p, C.c_double, C.c_double, C.c_bool,
                                 arr(C.c_bool), arr(C.c_bool), arr(C.c_bool),
                                 arr(C.c_double)]

    def instantiate(self, name="solid", token=None, resources=None, loggingOn=False):
        """loggingOn: the solver's log comes as messages of category logSolver"""
        return instance(self, name, self.token if token is None else token,
                        str(self.dir / "resources") + "/" if resources is None
                        else resources, loggingOn)

    def initialized(self, name="solid", startTime=0.0):
        """An instance through initialization, ready for its first step"""
        solid = self.instantiate(name)
        solid.enterInitializationMode(startTime)
        solid.exitInitializationMode()
        return solid

    def remove(self):
        shutil.rmtree(self.dir, ignore_errors=True)


class instance:
    """One instance of an FMU, with the messages it logged"""

    def __init__(self, fmu, name, token, resources, loggingOn=False):
        self.fmu = fmu
        self.messages = []

        def log(env, status, category, message):
            self.messages.append((status, category.decode(), message.decode()))
        self._logger = LOGGER(log)      # kept alive as long as the instance
        self.handle = fmu.lib.fmi3InstantiateCoSimulation(
            name.encode(), token.encode(), resources.encode(), False, loggingOn, False,
            False, None, 0, None, self._logger, None)
        if not self.handle:
            raise fmiError("fmi3InstantiateCoSimulation", ERROR, self.lastMessage())

    def lastMessage(self):
        return self.messages[-1][2] if self.messages else "(nothing logged)"

    def call(self, function, *args):
        """The status of fmi3<function>(instance, *args)"""
        return getattr(self.fmu.lib, "fmi3" + function)(self.handle, *args)

    def check(self, function, *args):
        s = self.call(function, *args)
        if s != OK:
            raise fmiError("fmi3" + function, s, self.lastMessage())

    def enterInitializationMode(self, startTime):
        self.check("EnterInitializationMode", False, 0.0, startTime, False, 0.0)

    def exitInitializationMode(self):
        self.check("ExitInitializationMode")

    def terminate(self):
        self.check("Terminate")

    def free(self):
        self.fmu.lib.fmi3FreeInstance(self.handle)
        self.handle = None

    def shape(self, name):
        v = self.fmu.variables[name]
        dims = []
        for kind, n in v.dimensions:
            if kind == "ref":
                out = (C.c_uint64*1)()
                self.check("GetUInt64", (VR*1)(n), 1, out, 1)
                n = int(out[0])
            dims.append(n)
        return tuple(dims)

    def get(self, name):
        v = self.fmu.variables[name]
        shape = self.shape(name)
        n = int(np.prod(shape)) if shape else 1
        if v.type == "UInt64":
            out = (C.c_uint64*n)()
            self.check("GetUInt64", (VR*1)(v.vr), 1, out, n)
        else:
            out = (C.c_double*n)()
            self.check("GetFloat64", (VR*1)(v.vr), 1, out, n)
        values = np.array(out[:])
        return values.reshape(shape) if shape else values[0]

    def set(self, name, values):
        v = self.fmu.variables[name]
        x = np.ascontiguousarray(np.broadcast_to(np.asarray(values, dtype=float),
                                                 self.shape(name) or (1,))).ravel()
        self.check("SetFloat64", (VR*1)(v.vr), 1, (C.c_double*len(x))(*x), len(x))

    def doStep(self, t, h):
        """The status (OK or DISCARD) and the last time reached"""
        flags = [C.c_bool() for _ in range(3)]
        last = C.c_double()
        s = self.call("DoStep", t, h, False, *(C.byref(f) for f in flags), C.byref(last))
        if s not in (OK, DISCARD):
            raise fmiError("fmi3DoStep", s, self.lastMessage())
        return s, last.value

    def getState(self):
        state = C.c_void_p()
        self.check("GetFMUState", C.byref(state))
        return state

    def setState(self, state):
        self.check("SetFMUState", state)

    def freeState(self, state):
        self.check("FreeFMUState", C.byref(state))
