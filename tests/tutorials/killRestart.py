#!/usr/bin/python3
# Debian's /usr/bin/python3: it sees python3-vtk9 and numpy, which other
# interpreters first on PATH (pyenv) may not.
"""A run killed with SIGKILL and restarted, again and again, reproduces the
uninterrupted run:

    killRestart.py <binDir> <projectDir> <workDir> [seed]

The case is tutorials/contact/grainsInBox, shortened and written often:
grains falling into a box, contacts opening, sticking and sliding, steps
cut and grown. It is run once without interruption, and once killed with
SIGKILL at least 10 times (after one or two new write times and a drawn
fraction of the wall time one write interval takes, both from a seeded
generator, or while a time directory is being written: at least three
times) and
restarted with startFrom latestTime after each kill, until it ends.

  - after every kill, every completed write time is intact: each time
    directory reads back (nmmSolidFoam -dry-run from it reads its
    uniform/time and restart state), and every frame the VTK series
    files list reads with VTK's XML readers;
  - the restarted run ends at the same time index as the uninterrupted
    one (the same steps), and its last frames (points, displacement,
    velocity and stress at the points, every contact's state and forces)
    equal the uninterrupted run's to 1e-12 of each field's largest value.
Exit 1 when a check fails.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader

endTime = 0.3
writeInterval = 0.01
minKills = 10
minKillsWhileWriting = 3


def setEntry(case, keyword, value):
    control = case/"system/controlDict"
    text, n = re.subn(r"(?m)^(%s\s+)[^;]*;" % keyword, r"\g<1>%s;" % value,
                      control.read_text())
    if n != 1:
        raise SystemExit("FAIL: no %s in %s" % (keyword, control))
    control.write_text(text)


def timeDirs(case):
    dirs = []
    for d in case.iterdir():
        try:
            dirs.append((float(d.name), d))
        except ValueError:
            pass
    return [d for _, d in sorted(dirs)]


def entry(file, keyword):
    m = re.search(r"(?m)^%s\s+([^;]*);" % keyword, file.read_text())
    return m.group(1).strip() if m else None


def readVtk(path):
    reader = (vtkXMLPolyDataReader() if path.suffix == ".vtp"
              else vtkXMLUnstructuredGridReader())
    reader.SetFileName(str(path))
    reader.Update()
    if reader.GetErrorCode() != 0:
        return None
    return reader.GetOutput()


def seriesFrames(case):
    frames = []
    for series in (case/"VTK").glob("*.series"):
        for f in json.loads(series.read_text())["files"]:
            frames.append(case/"VTK"/f["name"])
    return frames


def readsBack(case, timeDir, env):
    """nmmSolidFoam -dry-run from timeDir: the log, or None if it fails."""
    check = case.parent/"readBack"
    if check.exists():
        shutil.rmtree(check)
    check.mkdir()
    shutil.copytree(case/"system", check/"system")
    for name in ("constant", "0", timeDir.name):
        (check/name).symlink_to(case/name)
    setEntry(check, "startFrom", "startTime")
    setEntry(check, "startTime", timeDir.name)
    run = subprocess.run(["nmmSolidFoam", "-dry-run", "-noFunctionObjects"],
                         cwd=check, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    ok = run.returncode == 0 and "Restart from" in run.stdout
    return None if ok else run.stdout


def intactWrites(case, env, checked, failures, after):
    """Every time written since the last check, and the latest, reads
    back (a kill can only touch the time being written or purged); every
    frame the series list reads."""
    dirs = [d for d in timeDirs(case) if d.name != "0"]
    for d in dirs:
        if d.name in checked and d != dirs[-1]:
            continue
        checked.add(d.name)
        log = readsBack(case, d, env)
        if log is not None:
            failures.append("%s: time %s does not read back:\n%s"
                            % (after, d.name, log[-2000:]))
    for frame in seriesFrames(case):
        data = readVtk(frame) if frame.exists() else None
        if data is None or data.GetNumberOfPoints() == 0 and frame.suffix == ".vtu":
            failures.append("%s: %s is listed but does not read" % (after, frame.name))


def writing(case, since):
    """A time directory is being written (atomicDirectory's hidden name),
    made after since: not one a killed run left behind"""
    for p in case.iterdir():
        try:
            if p.name.startswith(".") and p.name.endswith(".tmp") \
                    and p.stat().st_mtime >= since:
                return True
        except FileNotFoundError:
            pass
    return False


def runKilled(case, env, rng, failures):
    """Restart after SIGKILL until the run ends by itself; the kills."""
    kills, whileWriting = 0, 0
    checked = set()
    interval = 0.01  # until two new write times have been seen
    for attempt in range(200):
        log = open(case/("log.nmmSolidFoam.%d" % attempt), "w")
        started = time.time()
        proc = subprocess.Popen(["nmmSolidFoam"], cwd=case, env=env,
                                stdout=log, stderr=subprocess.STDOUT)
        # Kills are placed by the run's progress, not by the clock, so
        # that a fast machine is killed as often as a slow one: after one
        # or two new write times and a drawn fraction of the wall time
        # the last write interval took (a moment of up to 0.05 s let a
        # fast run end before its tenth kill), or as soon as a time
        # directory is being written
        atWrite = kills < minKills and kills % 3 == 2
        seen = len(timeDirs(case))
        target = seen + rng.randint(1, 2)
        fraction = rng.uniform(0.0, 1.0)
        newWrites = []
        deadline = None
        killed = False
        while proc.poll() is None:
            count = len(timeDirs(case))
            if count > seen:
                seen = count
                newWrites.append(time.monotonic())
                if len(newWrites) >= 2:
                    interval = newWrites[-1] - newWrites[-2]
            if kills < minKills and not atWrite and deadline is None \
                    and count >= target:
                deadline = time.monotonic() + fraction*interval
            due = writing(case, started) if atWrite else \
                deadline is not None and time.monotonic() >= deadline
            if kills < minKills and due:
                hit = writing(case, started)
                proc.send_signal(signal.SIGKILL)
                proc.wait()
                kills += 1
                whileWriting += hit
                killed = True
                break
            time.sleep(0.0005 if atWrite else 0.005)
        log.close()
        if killed:
            intactWrites(case, env, checked, failures, "after kill %d" % kills)
            continue
        if proc.returncode != 0:
            failures.append("restarted run %d returned %d" % (attempt, proc.returncode))
        intactWrites(case, env, set(), failures, "at the end")
        return kills, whileWriting
    failures.append("the killed run did not end after 200 restarts")
    return kills, whileWriting


def lastFrame(case, pattern):
    frames = sorted((case/"VTK").glob(pattern),
                    key=lambda p: int(p.stem.rsplit("_", 1)[1]))
    return frames[-1]


def compareFrames(straight, killed, failures):
    for pattern, names in (("*[0-9].vtu", ("D", "U", "sigma")),
                           ("contacts_*.vtp", ("contactState", "bondIntact",
                                               "normalForce", "shearForce",
                                               "slip", "blockA", "blockB"))):
        a, b = readVtk(lastFrame(straight, pattern)), readVtk(lastFrame(killed, pattern))
        fields = [("points", vtk_to_numpy(a.GetPoints().GetData()),
                   vtk_to_numpy(b.GetPoints().GetData()))]
        for n in names:
            arrays = [f.GetPointData().GetArray(n) for f in (a, b)]
            if None in arrays:
                failures.append("%s: no point data %s" % (pattern, n))
                continue
            fields.append((n, vtk_to_numpy(arrays[0]), vtk_to_numpy(arrays[1])))
        for name, x, y in fields:
            if x.shape != y.shape:
                failures.append("%s: %s has shape %s, restarted %s"
                                % (pattern, name, x.shape, y.shape))
                continue
            scale = max(np.abs(x).max(), 1e-300)
            diff = np.abs(x.astype(float) - y.astype(float)).max()
            print("  %-16s %-12s largest %.6g, difference %.3g"
                  % (pattern, name, scale, diff))
            if not diff <= 1e-12*scale:
                failures.append("%s: %s differs by %.3g (largest value %.3g)"
                                % (pattern, name, diff, scale))


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__)
        return 1
    binDir, project, work = Path(argv[0]), Path(argv[1]), Path(argv[2])
    rng = random.Random(int(argv[3]) if len(argv) == 4 else 20261202)
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    env = dict(os.environ, PATH=str(binDir) + os.pathsep + os.environ.get("PATH", ""))

    base = work/"base"
    shutil.copytree(project/"tutorials/contact/grainsInBox", base)
    for keyword, value in (("endTime", endTime), ("writeInterval", writeInterval),
                           ("startFrom", "latestTime")):
        setEntry(base, keyword, value)
    subprocess.run(["nmmMesh"], cwd=base, env=env, check=True,
                   stdout=subprocess.DEVNULL)
    straight, killed = work/"straight", work/"killed"
    shutil.copytree(base, straight)
    shutil.copytree(base, killed)

    failures = []
    with open(straight/"log.nmmSolidFoam", "w") as log:
        if subprocess.run(["nmmSolidFoam"], cwd=straight, env=env,
                          stdout=log, stderr=subprocess.STDOUT).returncode != 0:
            failures.append("the uninterrupted run failed")
    kills, whileWriting = runKilled(killed, env, rng, failures)
    print("%d kills, %d while a time directory was being written" % (kills, whileWriting))
    if kills < minKills or whileWriting < minKillsWhileWriting:
        failures.append("only %d kills (%d while writing): the run ended first"
                        % (kills, whileWriting))

    ends = [timeDirs(c)[-1] for c in (straight, killed)]
    indices = [entry(d/"uniform/time", "index") for d in ends]
    print("last time %s, index %s uninterrupted; %s, index %s restarted"
          % (ends[0].name, indices[0], ends[1].name, indices[1]))
    if ends[0].name != ends[1].name or indices[0] != indices[1]:
        failures.append("the restarted run ends at time %s index %s, the"
                        " uninterrupted one at %s index %s"
                        % (ends[1].name, indices[1], ends[0].name, indices[0]))
    compareFrames(straight, killed, failures)

    for f in failures:
        print("FAIL: " + f)
    print("killRestart: %s" % ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
