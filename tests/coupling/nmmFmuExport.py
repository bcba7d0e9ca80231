#!/usr/bin/python3
"""nmmFmuExport on a copy of tutorials/coupling/thermalBlocks:

    nmmFmuExport.py <fmuDir> <projectDir> <binDir> <workDir>

  - the FMU it writes holds modelDescription.xml, the binary as
    binaries/x86_64-linux/<modelIdentifier>.so and the case as resources/
    (0, constant, system), without nmmMesh's output (the FMU meshes from
    nmmMeshDict) or the case's results;
  - broken input stops it with exit code 1 and a message naming what is
    wrong: no system/couplingDict, a misspelt field (with the file, its
    line and a "did you mean"), an unknown region, no FMU binary.
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fmuChecks  # noqa: E402


def export(t, case, *options):
    r = subprocess.run([str(t.bin/"nmmFmuExport"), "-case", str(case), *options],
                       capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def main():
    t = fmuChecks.run(__doc__)
    case = t.work/"thermalBlocks"
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(t.project/"tutorials/coupling/thermalBlocks", case,
                    ignore=shutil.ignore_patterns("log.*", "*.fmu", "VTK", "postProcessing",
                                                  "nmmMesh"))
    # What a run leaves in a case, which must stay out of the FMU
    (case/"constant/nmmMesh").mkdir()
    (case/"constant/nmmMesh/nmmMesh.h5").write_bytes(b"mesh")
    (case/"VTK").mkdir()

    rc, out = export(t, case)
    t.check(rc == 0, "nmmFmuExport on the tutorial case (exit %d)" % rc)
    with zipfile.ZipFile(case/"thermalBlocks.fmu") as z:
        names = set(z.namelist())
        root = ET.fromstring(z.read("modelDescription.xml"))
    identifier = root.find("CoSimulation").get("modelIdentifier")
    t.check({"modelDescription.xml", "binaries/x86_64-linux/%s.so" % identifier,
             "resources/system/couplingDict", "resources/system/nmmMeshDict",
             "resources/0/D", "resources/constant/mechanicalProperties"} <= names,
            "the FMU holds the description, the binary and the case")
    t.check(not any("nmmMesh/" in n or n.startswith("VTK") or "/VTK" in n for n in names),
            "and neither nmmMesh's output nor the case's results")

    dict_ = case/"system/couplingDict"
    good = dict_.read_text()
    broken = [
        ("no system/couplingDict", None, ["cannot open file", "system/couplingDict"]),
        ("a misspelt field", good.replace("(temperature)", "(temprature)"),
         ["did you mean 'temperature'?", "couplingDict at line 23"]),
        ("an unknown region", good.replace("    freeTop\n", "    freeTpo\n"),
         ["unknown coupling region 'freeTpo'; did you mean 'freeTop'?"]),
    ]
    for what, text, phrases in broken:
        if text is None:
            dict_.unlink()
        else:
            dict_.write_text(text)
        rc, out = export(t, case)
        t.check(rc == 1 and all(p in out for p in phrases),
                "%s: exit %d, %s" % (what, rc, " / ".join(p for p in phrases if p in out)))
        dict_.write_text(good)
    rc, out = export(t, case, "-binary", str(t.work/"none.so"))
    t.check(rc == 1 and "no FMU binary" in out, "no FMU binary: exit %d" % rc)
    return t.end()


if __name__ == "__main__":
    sys.exit(main())
