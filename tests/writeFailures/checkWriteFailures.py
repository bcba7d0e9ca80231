#!/usr/bin/python3
"""nmmMesh and nmmSolidFoam in a case folder they cannot write.

Usage:
    checkWriteFailures.py <scenario> <binDir> <case> <workDir>

<case> is a small case (tests/vtk/pointDataCase). It is copied to
<workDir>, meshed, and run to time 2 with a function object, so that
times 0, 1, 2, VTK/ frames and a postProcessing table exist; endTime is
then raised to 3 (startFrom latestTime) and the scenario makes the next
write fail. Every scenario expects exit code 1 (never a signal), a FOAM
FATAL message naming the folder or file and the reason, and every file
of times 0 to 2, of VTK/ and of postProcessing/ as it was (checksums),
with no hidden temporary ('.3.tmp') left; a time 3 that exists must be
complete (its state file readable: the run restarts from it).

  readOnly      the case and everything in it without write permission
                (chmod a-w); as root, which writes regardless, the runs
                are made in a user namespace ('unshare --user'), where
                root's override does not reach the files. nmmMesh, and
                nmmSolidFoam from time 2, must say "Permission denied".
  fullDisk      the case on a small tmpfs (mounted directly as root, or
                in 'unshare -rm'), filled up to a few kB: several sizes
                so that the state file, the frame and the series each
                meet the full disk; "No space left on device".
  fileSizeLimit 'ulimit -f' (RLIMIT_FSIZE) of 8 kB, SIGXFSZ left at its
                default: the programs must ignore it themselves and
                report "File too large" (EFBIG).
  pathIsFile    VTK and postProcessing replaced by plain files: the
                error names the folder (works as any user).

Each precondition is checked before the run (a probe write must fail the
same way); when it cannot be set up here (no user or mount namespaces in
a container, say), the scenario says why and exits with 77, which ctest
reports as skipped: never passed without having tested anything.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import hashlib
import os
import resource
import shutil
import signal
import subprocess
import sys
from pathlib import Path

failures = []


def check(ok, what):
    print("%s: %s" % ("ok  " if ok else "FAIL", what))
    if not ok:
        failures.append(what)
    return ok


def fatal(what):
    print("FAIL: " + what)
    sys.exit(1)


def cannotSetUp(what):
    """ctest's SKIP_RETURN_CODE: the scenario did not run here"""
    print("SKIPPED: " + what)
    sys.exit(77)


def run(cmd, prefix=(), preexec=None):
    p = subprocess.run([*prefix, *map(str, cmd)], capture_output=True, text=True,
                       timeout=300, preexec_fn=preexec)
    return p.returncode, p.stdout, p.stderr


def setEntry(dictFile, key, value):
    lines = dictFile.read_text().splitlines()
    out = [l if not l.startswith(key + " ") else "%s %s;" % (key, value) for l in lines]
    dictFile.write_text("\n".join(out) + "\n")


def prepare(binDir, source, case):
    """The case run to time 2; endTime then 3, from the latest time"""
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(source, case)
    control = case/"system"/"controlDict"
    setEntry(control, "endTime", "2")
    setEntry(control, "startFrom", "latestTime")
    control.write_text(control.read_text() + "functions\n{\n    e { type energy; }\n}\n")
    for app in ("nmmMesh", "nmmSolidFoam"):
        rc, out, err = run([binDir/app, "-case", case])
        if rc != 0:
            fatal("preparing %s: %s exit code %d\n%s" % (case, app, rc, err))
    setEntry(control, "endTime", "3")


def snapshot(case):
    """Checksums of every file of the times, VTK/ and postProcessing/"""
    sums = {}
    for top in ("0", "1", "2", "VTK", "postProcessing", "constant"):
        for f in sorted((case/top).rglob("*")):
            if f.is_file():
                sums[str(f.relative_to(case))] = hashlib.sha256(f.read_bytes()).hexdigest()
    return sums


def withoutMesh(sums):
    """nmmMesh's own output, which it rewrites (atomically, each file)"""
    return {k: v for k, v in sums.items()
            if not k.startswith("constant/nmmMesh") and k != "VTK/mesh.vtu"}


def expectFailure(name, result, reason, names, case, before):
    rc, out, err = result
    missing = [s for s in ("FOAM FATAL", reason, names) if s not in err]
    check(rc == 1 and not missing, "%s: exit code 1 naming %s and '%s'%s" % (
        name, names, reason, "" if rc == 1 and not missing else
        " (exit code %d, missing %s)\n%s\n%s" % (rc, missing, out[-1500:], err)))
    if before is not None:
        after = snapshot(case)
        changed = [f for f in before if after.get(f) != before[f]]
        check(not changed, "%s: the earlier times, frames and tables are as they were%s"
              % (name, "" if not changed else ": changed " + ", ".join(changed)))
    leftovers = [p.name for p in case.iterdir() if p.name.startswith(".") and
                 p.name.endswith((".tmp", ".old"))]
    check(not leftovers, "%s: no temporary left behind %s" % (name, leftovers))
    mesh = case/"constant"/"nmmMesh"/"nmmMesh.h5"
    if mesh.parent.exists():
        check(mesh.is_file() and mesh.read_bytes()[:8] == b"\x89HDF\r\n\x1a\n",
              "%s: the mesh file is whole" % name)
    if (case/"3").exists():
        # A time that exists is complete
        state = case/"3"/"nmmState.h5"
        check(state.is_file() and state.read_bytes()[:8] == b"\x89HDF\r\n\x1a\n"
              and (case/"3"/"uniform"/"time").is_file(),
              "%s: time 3 exists and is complete" % name)


# --------------------------------------------------------------- scenarios

def readOnly(binDir, source, work):
    case = work/"case"
    prepare(binDir, source, case)
    meshOnly = work/"meshOnly"
    shutil.rmtree(meshOnly, ignore_errors=True)
    shutil.copytree(source, meshOnly)
    before = snapshot(case)
    prefix = ()
    if os.geteuid() == 0:
        if not shutil.which("unshare"):
            cannotSetUp("running as root, where chmod does not stop writes, and without "
                  "'unshare' to drop that: the read-only case cannot be set up")
        prefix = ("unshare", "--user")
    for folder in (case, meshOnly):
        for d, dirs, files in os.walk(folder):
            for n in dirs + files:
                p = Path(d)/n
                p.chmod(p.stat().st_mode & ~0o222)
        folder.chmod(folder.stat().st_mode & ~0o222)
    try:
        rc, out, err = run(["touch", case/"probe"], prefix)
        if rc == 0 or "Permission denied" not in err:
            cannotSetUp("the read-only case cannot be set up here: a probe write %s (%s)"
                  % ("succeeded" if rc == 0 else "failed otherwise", err.strip()))
        expectFailure("nmmSolidFoam, read-only case",
                      run([binDir/"nmmSolidFoam", "-case", case], prefix),
                      "Permission denied", str(case), case, before)
        expectFailure("nmmMesh, read-only case",
                      run([binDir/"nmmMesh", "-case", meshOnly], prefix),
                      "Permission denied", str(meshOnly), meshOnly, None)
    finally:
        for folder in (case, meshOnly):
            folder.chmod(0o755)
            for d, dirs, files in os.walk(folder):
                for n in dirs + files:
                    p = Path(d)/n
                    p.chmod(p.stat().st_mode | 0o200)


FULL_DISK_SCRIPT = r'''
set -u
mnt="$1"; case="$2"; free="$3"; shift 3
mount -t tmpfs -o size=4m tmpfs "$mnt" || exit 90
cp -a "$case" "$mnt/case" || exit 91
dd if=/dev/zero of="$mnt/filler" bs=4k 2>/dev/null
truncate -s "-${free}k" "$mnt/filler" || exit 92
if dd if=/dev/zero of="$mnt/probe" bs=1k count=$((free + 8)) 2>/dev/null; then exit 93; fi
rm -f "$mnt/probe"
# The output goes beside the case, off the full disk
"$@" -case "$mnt/case" > "$case.out" 2> "$case.err"
echo $? > "$case.rc"
rm -rf "$case.full"; cp -a "$mnt/case" "$case.full"
umount "$mnt"
'''


def fullDisk(binDir, source, work):
    case = work/"case"
    prepare(binDir, source, case)
    before = snapshot(case)
    mnt = work/"mnt"
    mnt.mkdir(exist_ok=True)
    script = work/"fullDisk.sh"
    script.write_text(FULL_DISK_SCRIPT)
    # A mount namespace of its own: the tmpfs goes with the process
    prefix = ("unshare", "-m" if os.geteuid() == 0 else "-rm", "bash")
    if not shutil.which("unshare"):
        if os.geteuid() != 0:
            cannotSetUp("the full disk cannot be set up here: no 'unshare' to mount a tmpfs "
                  "without root")
        prefix = ("bash",)
    # nmmMesh writes about 100 kB: at 240 kB free it succeeds
    for free in (4, 12, 48, 240):
        for app in ("nmmSolidFoam", "nmmMesh") if free < 240 else ("nmmSolidFoam",):
            rc, out, err = run([script, mnt, case, free, binDir/app], prefix)
            if rc != 0:
                cannotSetUp("the full disk cannot be set up here (%s, step %d): %s; mounting a "
                      "tmpfs needs root or user namespaces" % (" ".join(prefix), rc,
                                                                err.strip()))
            full = Path(str(case) + ".full")
            result = tuple(conv(Path(str(case) + ext).read_text()) for conv, ext in
                           ((int, ".rc"), (str, ".out"), (str, ".err")))
            if app == "nmmSolidFoam":
                expectFailure("nmmSolidFoam, %d kB free" % free, result,
                              "No space left on device", str(mnt/"case"), full, before)
            else:
                expectFailure("nmmMesh, %d kB free" % free, result,
                              "No space left on device", str(mnt/"case"), full,
                              withoutMesh(before))


def fileSizeLimit(binDir, source, work):
    case = work/"case"
    prepare(binDir, source, case)
    before = snapshot(case)
    limit = 8 << 10

    def limited():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    def limitedQuiet():
        limited()
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    rc, out, err = run(["dd", "if=/dev/zero", "of=%s" % (work/"probe"), "bs=1k", "count=16"],
                       preexec=limitedQuiet)
    (work/"probe").unlink(missing_ok=True)
    if rc == 0:
        fatal("RLIMIT_FSIZE does not limit writes here: a 16 kB probe was written")
    expectFailure("nmmSolidFoam, files limited to 8 kB",
                  run([binDir/"nmmSolidFoam", "-case", case], preexec=limited),
                  "File too large", str(case), case, before)
    expectFailure("nmmMesh, files limited to 8 kB",
                  run([binDir/"nmmMesh", "-case", case], preexec=limited),
                  "File too large", str(case), case, withoutMesh(before))


def pathIsFile(binDir, source, work):
    for folder, writer in (("VTK", "nmmSolidFoam"), ("postProcessing", "nmmSolidFoam"),
                           ("VTK", "nmmMesh")):
        case = work/(folder + writer)
        prepare(binDir, source, case)
        shutil.rmtree(case/folder)
        (case/folder).write_text("not a folder\n")
        before = {k: v for k, v in snapshot(case).items() if not k.startswith(folder)}
        if writer == "nmmMesh":
            before = withoutMesh(before)
        expectFailure("%s, %s is a file" % (writer, folder),
                      run([binDir/writer, "-case", case]), "",
                      str(case/folder), case, before)


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    scenario = sys.argv[1]
    binDir, source, work = (Path(a).resolve() for a in sys.argv[2:])
    work.mkdir(parents=True, exist_ok=True)
    {"readOnly": readOnly, "fullDisk": fullDisk, "fileSizeLimit": fileSizeLimit,
     "pathIsFile": pathIsFile}[scenario](binDir, source, work)
    print("\n%d failure%s" % (len(failures), "" if len(failures) == 1 else "s"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
