#!/usr/bin/python3
"""Read nmmSolid's VTK output back with VTK's own readers.

Usage:
    checkVtkOutput.py --samples <vtkSamples> --work <dir>
        run vtkSamples into <dir>, then check everything it wrote
    checkVtkOutput.py --check <dir>
        check a folder that vtkSamples wrote earlier
    checkVtkOutput.py --selftest --samples <vtkSamples> --work <dir>
        prove that the check fails on corrupted output

Run it with /usr/bin/python3: VTK's Python bindings come from the Debian
package python3-vtk9 (listed in etc/debianPackages), which installs them
for Debian's /usr/bin/python3 only, and that interpreter is not first on
PATH here (pyenv's python3 is). The test (tests/vtk/CMakeLists.txt) calls
it by that full path. Without the package the check fails with a message
naming it.

vtkSamples leaves manifest.json next to the output: every file with the
points, polygons and arrays it must hold, and every series with its
entries. For each .vtu and .vtp file the check

  - parses the XML with Python's ElementTree: root VTKFile attributes
    (type, version 1.0, byte_order, header_type UInt64) and the format of
    every DataArray (binary, or ascii in an ascii file except the arrays
    holding a NaN or an infinity, which must be binary);
  - reads it with vtkXMLUnstructuredGridReader / vtkXMLPolyDataReader,
    with every VTK message captured (a vtkStringOutputWindow installed as
    the output window, and ErrorEvent/WarningEvent observers on the
    reader): any error or warning fails the file;
  - compares the number of points and cells, the points (bit for bit),
    the cell types (VTK_POLYGON = 7, or VTK_VERTEX = 1 as Verts with no
    Lines, Strips or Polys), the connectivity and offsets, and for every
    point-data and cell-data array: the names (same set, same order), the
    value type (Float64, Int32, Int64), the number of components, the
    component names, and every value (doubles bit for bit, so -0 and
    denormals count; NaN matches NaN); the field-data TimeValue.

Each .series file must be strict JSON with "file-series-version" "1.0",
strictly increasing times, the expected names and times, and name only
files that exist and were read back. Every .vtu, .vtp and .series file
under the folder must be in the manifest, and no temporary file
('.<name>.tmp') may be left.

Exit code 0 when everything matches, 1 otherwise (each mismatch listed).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import json
import math
import re
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]/"bin"/"tools"))
import nmmVtk  # noqa: E402


def import_modules():
    """numpy and VTK, or exit naming the missing Debian packages."""
    missing = nmmVtk.missingPackages()
    if missing:
        packages = " ".join(p for p, _ in missing)
        sys.exit(
            "checkVtkOutput: %s cannot import %s.\n"
            "Install the Debian package%s %s (listed in etc/debianPackages):\n"
            "    apt-get install %s\n"
            "and run this script with /usr/bin/python3, the interpreter "
            "Debian's python3-* packages are installed for."
            % (sys.executable, "; ".join("%s (%s)" % (p, e) for p, e in missing),
               "s" if len(missing) > 1 else "", packages, packages))


# --------------------------------------------------------------------------
# VTK messages

class vtkMessages:
    """Every error and warning VTK reports, from any object.

    VTK objects without an observer print through the one output window;
    replacing it with a string window keeps their text. Observers on the
    reader see its own errors and warnings (which then skip the window).
    """

    def __init__(self):
        self.observed = []
        self.window = None
        self.take()

    def watch(self, obj):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.util.vtkConstants import VTK_STRING
        from vtkmodules.vtkCommonCore import vtkCommand

        @calldata_type(VTK_STRING)      # VTK passes the message text
        def keep(caller, event, message):
            self.observed.append("%s: %s" % (event, message))
        for event in (vtkCommand.ErrorEvent, vtkCommand.WarningEvent):
            obj.AddObserver(event, keep)

    def take(self):
        """Messages since the last call; starts a fresh window."""
        from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow
        # VTK 9 also logs each message to stderr; the window has them all
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
        text = self.window.GetOutput().strip() if self.window else ""
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        messages = self.observed + ([text] if text else [])
        self.observed = []
        return messages


# --------------------------------------------------------------------------
# Comparisons

def as_numpy(vtk_array):
    return nmmVtk.toNumpy(vtk_array).reshape(-1)


NUMPY_TYPES = {"Float64": "float64", "Int32": "int32", "Int64": "int64"}


def same_values(actual, expected, type_name):
    """Bit-for-bit for doubles (NaN matches NaN), exact for integers."""
    import numpy as np
    e = np.array(expected, dtype=NUMPY_TYPES[type_name]).reshape(-1)
    a = np.asarray(actual).reshape(-1)
    if a.shape != e.shape:
        return False
    if type_name != "Float64":
        return bool(np.array_equal(a, e))
    nan_a, nan_e = np.isnan(a), np.isnan(e)
    return bool(np.array_equal(nan_a, nan_e)
                and np.array_equal(a[~nan_a].view(np.uint64),
                                   e[~nan_e].view(np.uint64)))


def first_difference(actual, expected):
    """The first value that differs, in words."""
    def same(a, e):
        if isinstance(e, float):
            return (math.isnan(a) and math.isnan(e)) \
                or struct.pack("<d", float(a)) == struct.pack("<d", e)
        return a == e
    for i, (a, e) in enumerate(zip(list(actual), expected)):
        if not same(a, e):
            return "value %d is %r, expected %r" % (i, a, e)
    return "%d values, expected %d" % (len(actual), len(expected))


class fileCheck:
    """The checks of one file; failures are collected, not raised."""

    def __init__(self, root, entry, messages):
        self.root = root
        self.entry = entry
        self.path = root / entry["path"]
        self.messages = messages
        self.failures = []

    def fail(self, text):
        self.failures.append("%s: %s" % (self.entry["path"], text))

    def expect(self, condition, text):
        if not condition:
            self.fail(text)
        return condition

    # XML, independent of VTK
    def check_xml(self):
        kind = self.entry["kind"]
        try:
            root = ET.parse(self.path).getroot()
        except ET.ParseError as e:
            self.fail("not well-formed XML: %s" % e)
            return
        want = {"type": "UnstructuredGrid" if kind == "vtu" else "PolyData",
                "version": "1.0",
                "byte_order": "LittleEndian" if sys.byteorder == "little" else "BigEndian",
                "header_type": "UInt64"}
        for key, value in want.items():
            self.expect(root.get(key) == value, "VTKFile %s=%r, expected %r"
                        % (key, root.get(key), value))

        nonfinite = {a["name"] for a in self.entry["pointData"] + self.entry["cellData"]
                     if any(isinstance(v, float) and not math.isfinite(v)
                            for v in a["values"])}
        for da in root.iter("DataArray"):
            name = da.get("Name")
            fmt = da.get("format")
            expected = self.entry["format"]
            if name in nonfinite:
                expected = "binary"
            self.expect(fmt == expected, "DataArray %r has format=%r, expected %r"
                        % (name, fmt, expected))

    # VTK's reader
    def read(self):
        reader = nmmVtk.newReader(self.entry["kind"])
        self.messages.watch(reader)
        self.messages.take()
        if not self.expect(reader.CanReadFile(str(self.path)) == 1,
                           "%s cannot read the file" % reader.GetClassName()):
            return None
        reader.SetFileName(str(self.path))
        reader.Update()
        for m in self.messages.take():
            self.fail("VTK reported: %s" % m.replace("\n", " | "))
        self.expect(reader.GetErrorCode() == 0,
                    "reader error code %d" % reader.GetErrorCode())
        return reader.GetOutput()

    def check_arrays(self, where, vtk_data, expected):
        names = [vtk_data.GetArrayName(i) for i in range(vtk_data.GetNumberOfArrays())]
        self.expect(names == [a["name"] for a in expected],
                    "%s arrays %r, expected %r" % (where, names, [a["name"] for a in expected]))
        for a in expected:
            arr = vtk_data.GetArray(a["name"])
            if not self.expect(arr is not None, "%s array %r missing" % (where, a["name"])):
                continue
            label = "%s array %r" % (where, a["name"])
            self.expect(arr.GetNumberOfComponents() == a["nComponents"],
                        "%s has %d components, expected %d"
                        % (label, arr.GetNumberOfComponents(), a["nComponents"]))
            values = as_numpy(arr)
            if not self.expect(str(values.dtype) == NUMPY_TYPES[a["type"]],
                               "%s is %s, expected %s" % (label, values.dtype, a["type"])):
                continue
            for i, cname in enumerate(a["componentNames"]):
                got = arr.GetComponentName(i)
                self.expect(got == cname, "%s component %d is named %r, expected %r"
                            % (label, i, got, cname))
            if not same_values(values, a["values"], a["type"]):
                self.fail("%s: %s" % (label, first_difference(values.tolist(), a["values"])))

    def check_cells(self, out):
        e = self.entry
        n_cells = out.GetNumberOfCells()
        types = [out.GetCellType(i) for i in range(n_cells)]
        self.expect(types == [e["cellType"]] * e["nCells"],
                    "cell types %r, expected all %d" % (sorted(set(types)), e["cellType"]))
        if e["kind"] == "vtu":
            cells = out.GetCells()
            connectivity = as_numpy(cells.GetConnectivityArray()).tolist()
            offsets = as_numpy(cells.GetOffsetsArray()).tolist()
            self.expect(connectivity == e["connectivity"], "connectivity differs: %s"
                        % first_difference(connectivity, e["connectivity"]))
            self.expect(offsets == [0] + e["offsets"], "offsets differ: %s"
                        % first_difference(offsets, [0] + e["offsets"]))
        else:
            n = e["nPoints"]
            self.expect(out.GetNumberOfVerts() == n, "%d verts, expected %d"
                        % (out.GetNumberOfVerts(), n))
            for what, count in (("lines", out.GetNumberOfLines()),
                                ("strips", out.GetNumberOfStrips()),
                                ("polys", out.GetNumberOfPolys())):
                self.expect(count == 0, "%d %s, expected none" % (count, what))
            verts = out.GetVerts()
            self.expect(as_numpy(verts.GetConnectivityArray()).tolist() == list(range(n)),
                        "verts are not one per point")
            self.expect(as_numpy(verts.GetOffsetsArray()).tolist() == list(range(n + 1)),
                        "verts offsets are not 0..n")

    def check_time(self, out):
        field = out.GetFieldData()
        arr = field.GetArray("TimeValue") if field else None
        t = self.entry["time"]
        if t is None:
            self.expect(arr is None, "has a TimeValue, expected none")
        elif self.expect(arr is not None, "no TimeValue field data"):
            self.expect(arr.GetNumberOfTuples() == 1 and same_values(as_numpy(arr), [t], "Float64"),
                        "TimeValue %r, expected %r" % (as_numpy(arr).tolist(), t))

    def run(self):
        if not self.expect(self.path.is_file(), "missing"):
            return self.failures
        self.check_xml()
        out = self.read()
        if out is None:
            return self.failures
        e = self.entry
        try:
            self.expect(out.GetNumberOfPoints() == e["nPoints"], "%d points, expected %d"
                        % (out.GetNumberOfPoints(), e["nPoints"]))
            self.expect(out.GetNumberOfCells() == e["nCells"], "%d cells, expected %d"
                        % (out.GetNumberOfCells(), e["nCells"]))
            points = out.GetPoints()
            if self.expect(points is not None, "no points"):
                xyz = as_numpy(points.GetData())
                self.expect(str(xyz.dtype) == "float64", "points are %s" % xyz.dtype)
                self.expect(same_values(xyz, e["points"], "Float64"), "points differ: %s"
                            % first_difference(xyz.tolist(), e["points"]))
            self.check_cells(out)
            self.check_arrays("point data", out.GetPointData(), e["pointData"])
            self.check_arrays("cell data", out.GetCellData(), e["cellData"])
            self.check_time(out)
        except Exception as ex:    # a broken file may leave half a data set
            self.fail("%s: %s" % (type(ex).__name__, ex))
        return self.failures


# --------------------------------------------------------------------------
# Series

def reject_constant(name):
    raise ValueError("%s is not JSON" % name)


def check_series(root, s, read_files):
    failures = []
    path = root / s["path"]

    def fail(text):
        failures.append("%s: %s" % (s["path"], text))

    try:
        data = json.loads(path.read_text(encoding="utf-8"), parse_constant=reject_constant)
    except (OSError, ValueError) as e:
        fail("does not load as JSON: %s" % e)
        return failures
    if data.get("file-series-version") != "1.0":
        fail("file-series-version %r, expected '1.0'" % data.get("file-series-version"))
    files = data.get("files")
    if not isinstance(files, list):
        fail("no 'files' list")
        return failures
    names = [f.get("name") for f in files]
    times = [f.get("time") for f in files]
    if not all(isinstance(t, (int, float)) and not isinstance(t, bool) for t in times):
        fail("times %r are not all numbers" % times)
        return failures
    if any(b <= a for a, b in zip(times, times[1:])):
        fail("times %r are not strictly increasing" % times)
    if names != s["names"]:
        fail("names %r, expected %r" % (names, s["names"]))
    if [float(t) for t in times] != [float(t) for t in s["times"]]:
        fail("times %r, expected %r" % (times, s["times"]))
    for name in names:
        target = (path.parent / name).resolve()
        if not target.is_file():
            fail("lists %r, which does not exist" % name)
        elif target not in read_files:
            fail("lists %r, which was not read back" % name)
    return failures


# --------------------------------------------------------------------------
# A whole output folder

def check_folder(root):
    """All failures for the folder vtkSamples wrote (empty: all good)."""
    root = Path(root).resolve()
    try:
        manifest = json.loads((root / "manifest.json").read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        return ["manifest.json: %s" % e], (0, 0)

    messages = vtkMessages()
    failures = []
    read_files = set()
    for entry in manifest["files"]:
        failures += fileCheck(root, entry, messages).run()
        read_files.add((root / entry["path"]).resolve())
    for s in manifest["series"]:
        failures += check_series(root, s, read_files)

    known = read_files | {(root / s["path"]).resolve() for s in manifest["series"]}
    for p in sorted(root.rglob("*")):
        if not p.is_file():
            continue
        if re.fullmatch(r"\..+\.tmp", p.name):
            failures.append("%s: temporary file left behind" % p.relative_to(root))
        elif p.suffix in (".vtu", ".vtp", ".series") and p.resolve() not in known:
            failures.append("%s: not in the manifest, so not checked" % p.relative_to(root))

    counts = (len(manifest["files"]), len(manifest["series"]))
    return failures, counts


def report(failures, counts, root):
    if failures:
        print("FAILED: %d mismatches in %s" % (len(failures), root))
        for f in failures:
            print("  " + f)
        return 1
    print("OK: %d VTK files read back by VTK and %d series checked in %s"
          % (counts[0], counts[1], root))
    return 0


def run_samples(samples, work):
    work = Path(work)
    if work.exists():
        shutil.rmtree(work)
    result = subprocess.run([samples, str(work)], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("checkVtkOutput: %s failed (exit %d):\n%s%s"
                 % (samples, result.returncode, result.stdout, result.stderr))
    return work


# --------------------------------------------------------------------------
# Self-test: corrupted output must fail, for the right reason

def edit_array(path, name, change, occurrence=0):
    """Replace the content (or, change=None, the whole element) of a
    DataArray of that name."""
    text = path.read_text(encoding="utf-8")
    pattern = re.compile(r'(<DataArray[^>]*Name="%s"[^>]*>)(.*?)(</DataArray>\s*)'
                         % re.escape(name), re.S)
    matches = list(pattern.finditer(text))
    m = matches[occurrence]
    if change is None:
        new = ""
    else:
        new = m.group(1) + change(m.group(2)) + m.group(3)
    path.write_text(text[:m.start()] + new + text[m.end():], encoding="utf-8")


def bump_first_number(text):
    m = re.search(r"-?\d[\d.e+-]*", text)
    value = float(m.group(0))
    return text[:m.start()] + repr(value * (1 + 1e-15) + 1e-300) + text[m.end():]


def swap_series_times(path):
    data = json.loads(path.read_text())
    data["files"][0]["time"], data["files"][1]["time"] = \
        data["files"][1]["time"], data["files"][0]["time"]
    path.write_text(json.dumps(data))


CORRUPTIONS = [
    # (what, change of the tree, text expected among the failures)
    ("an ascii value one ulp off",
     lambda r: edit_array(r / "ascii/sampleCase/VTK/sampleCase_100.vtu", "sigmaEq",
                          bump_first_number),
     "cell data array 'sigmaEq': value 0"),
    # VTK 9.1 reads a base64 block shorter than its byte count without a
    # word (the rest is whatever memory held): only the values tell
    ("a binary block cut short",
     lambda r: edit_array(r / "binary/sampleCase/VTK/sampleCase_0.vtu", "D",
                          lambda s: s.strip()[:-12] + "\n"),
     "point data array 'D': value"),
    ("an ascii array cut short",
     lambda r: edit_array(r / "ascii/sampleCase/VTK/sampleCase_200.vtu", "sigmaEq",
                          lambda s: s[:len(s) // 2] + "\n"),
     "VTK reported"),
    ("XML that is not well-formed",
     lambda r: (r / "binary/sampleCase/VTK/contacts_100.vtp").write_text(
         (r / "binary/sampleCase/VTK/contacts_100.vtp").read_text().replace("</Points>", "", 1)),
     "VTK reported"),
    ("a missing array",
     lambda r: edit_array(r / "ascii/sampleCase/VTK/sampleCase_150.vtu", "blockId", None),
     "point data arrays"),
    ("a wrong cell type",
     lambda r: edit_array(r / "ascii/sampleCase/VTK/mesh.vtu", "types",
                          lambda s: s.replace("7", "9", 1)),
     "cell types"),
    ("wrong component names",
     lambda r: (r / "ascii/sampleCase/VTK/sampleCase_0.vtu").write_text(
         (r / "ascii/sampleCase/VTK/sampleCase_0.vtu").read_text().replace(
             'ComponentName1="YY"', 'ComponentName1="ZZ"', 1)),
     "component 1 is named 'ZZ'"),
    ("series times not increasing",
     lambda r: swap_series_times(r / "binary/sampleCase/VTK/sampleCase.vtu.series"),
     "not strictly increasing"),
    ("series that is not JSON",
     lambda r: (r / "ascii/sampleCase/VTK/contacts.vtp.series").write_text('{ "files" : [ '),
     "does not load as JSON"),
    ("an unchecked frame",
     lambda r: shutil.copy(r / "binary/sampleCase/VTK/sampleCase_0.vtu",
                           r / "binary/sampleCase/VTK/sampleCase_7.vtu"),
     "not in the manifest"),
    ("a temporary file left",
     lambda r: (r / "binary/sampleCase/VTK/.sampleCase_300.vtu.tmp").write_text("half"),
     "temporary file left behind"),
]


def selftest(samples, work):
    work = Path(work)
    if work.exists():
        shutil.rmtree(work)
    good = run_samples(samples, work / "good")
    failures, counts = check_folder(good)
    if failures:
        print("selftest: the unmodified output does not pass:")
        return report(failures, counts, good)

    bad = 0
    for i, (what, corrupt, expected) in enumerate(CORRUPTIONS):
        tree = work / ("corrupt%d" % i)
        shutil.copytree(good, tree)
        corrupt(tree)
        failures, _ = check_folder(tree)
        found = any(expected in f for f in failures)
        print("%s %s: %s" % ("ok  " if found else "FAIL", what,
                             failures[0] if failures else "not detected"))
        if not found:
            bad += 1
            for f in failures:
                print("      " + f)
    if bad:
        print("selftest: %d corruptions not detected as expected" % bad)
        return 1
    print("selftest: all %d corruptions detected" % len(CORRUPTIONS))
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--samples", help="the vtkSamples executable")
    parser.add_argument("--work", help="folder for the output (emptied first)")
    parser.add_argument("--check", help="check this folder only")
    parser.add_argument("--selftest", action="store_true")
    args = parser.parse_args()

    import_modules()
    if args.check:
        failures, counts = check_folder(args.check)
        return report(failures, counts, args.check)
    if not args.samples or not args.work:
        parser.error("--samples and --work are needed")
    if args.selftest:
        return selftest(args.samples, args.work)
    root = run_samples(args.samples, args.work)
    failures, counts = check_folder(root)
    return report(failures, counts, root)


if __name__ == "__main__":
    sys.exit(main())
