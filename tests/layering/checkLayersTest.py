#!/usr/bin/env python3
"""
Description
    checkLayers.py on small libraries written to a scratch folder: that it
    passes a layered one and fails, naming the file, line and include, on
    each kind of break (an include of a later layer, a cycle, a folder
    missing from the list, a folder listed twice).

Usage
    checkLayersTest.py <scratch folder>
"""

import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CHECK = os.path.join(HERE, "checkLayers.py")

failures = []


def expect(condition, what, output):
    if not condition:
        failures.append(f"{what}\n--- output:\n{output}---")


def checkLibrary(scratch, name, layers, files):
    """checkLayers.py's exit code and output for a library folder
    <scratch>/<name>/src/nmmSolid with these files ({relative path: text})
    and a layers file listing these folders"""
    root = os.path.join(scratch, name, "src", "nmmSolid")
    shutil.rmtree(os.path.join(scratch, name), ignore_errors=True)
    os.makedirs(root)
    with open(os.path.join(root, "layers"), "w") as f:
        f.write("# comment\n" + "".join(n + "\n" for n in layers))
    for rel, text in files.items():
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    p = subprocess.run([sys.executable, CHECK, root],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    return p.returncode, p.stdout


def main(scratch):
    order = ["global", "io", "space", "model"]

    # Layered: includes of earlier folders, of the generated version.H
    # (absent from the source tree), of a listed folder that does not
    # exist yet, and violations that are only in comments or strings
    rc, out = checkLibrary(scratch, "layered", order, {
        "global/a/a.H": '#include "nmmSolid/global/version.H"\n',
        "io/b/b.H": '#include "nmmSolid/global/a/a.H"\n'
                    '#include "nmmSolid/global/version.H"\n'
                    '#include <vector>\n',
        "io/b/b.C": '#include "nmmSolid/io/b/b.H"\n'
                    '// #include "nmmSolid/model/m/m.H"\n'
                    '/*\n#include "nmmSolid/model/m/m.H"\n*/\n'
                    'const char* s = "/*";\n'
                    '#include "nmmSolid/global/a/a.H"\n',
        "model/m/m.H": '#  include "nmmSolid/io/b/b.H"\n'
                       '#include "nmmSolid/space/s/s.H"\n',
    })
    expect(rc == 0, "a layered library passes", out)

    # (a) an include of a later folder, at its file and line
    rc, out = checkLibrary(scratch, "upward", order, {
        "global/a/a.C": '#include "nmmSolid/global/a/a.H"\n\n'
                        '#include "nmmSolid/io/b/b.H"\n',
        "io/b/b.H": "\n",
    })
    expect(rc == 1, "an include of a later layer fails", out)
    expect('src/nmmSolid/global/a/a.C:3: #include "nmmSolid/io/b/b.H": '
           "global includes io, which comes after it in "
           "src/nmmSolid/layers" in out,
           "the message names the file, line and include", out)
    expect("cycle" not in out, "a one-way include is no cycle", out)

    # (b) a cycle, with an include for each of its steps
    rc, out = checkLibrary(scratch, "cycle", order, {
        "io/b/b.H": '#include "nmmSolid/model/m/m.H"\n',
        "model/m/m.H": '#include "nmmSolid/space/s/s.H"\n',
        "space/s/s.H": '#include "nmmSolid/io/b/b.H"\n',
    })
    expect(rc == 1, "a cycle fails", out)
    expect("cycle between folders io, model, space: "
           "io -> model -> space -> io" in out, "the cycle is named", out)
    for step in ['io -> model at src/nmmSolid/io/b/b.H:1: '
                 '#include "nmmSolid/model/m/m.H"',
                 'model -> space at src/nmmSolid/model/m/m.H:1:',
                 'space -> io at src/nmmSolid/space/s/s.H:1:']:
        expect(step in out, f"the cycle's step '{step}' is located", out)

    # (c) a folder that the order does not place, on disk or in an include;
    # two unlisted folders that include each other are still a cycle
    rc, out = checkLibrary(scratch, "unlisted", order, {
        "extra/e/e.H": '#include "nmmSolid/other/o/o.H"\n',
        "other/o/o.H": '#include "nmmSolid/extra/e/e.H"\n',
        "io/b/b.H": '#include "nmmSolid/ghost/g.H"\n',
    })
    expect(rc == 1, "a folder outside the order fails", out)
    expect("src/nmmSolid/extra: folder 'extra' is not in "
           "src/nmmSolid/layers" in out, "the unlisted folder is named", out)
    expect('src/nmmSolid/io/b/b.H:1: #include "nmmSolid/ghost/g.H": '
           "folder 'ghost' is not in src/nmmSolid/layers" in out,
           "an include of an unlisted folder is located", out)
    expect("cycle between folders extra, other" in out,
           "a cycle between unlisted folders is found", out)

    # A folder listed twice
    rc, out = checkLibrary(scratch, "twice", order + ["io"],
                           {"io/b/b.H": "\n"})
    expect(rc == 1 and "'io' is listed twice" in out,
           "a folder listed twice fails", out)

    for f in failures:
        print("FAILED: " + f)
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.stderr.write(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
