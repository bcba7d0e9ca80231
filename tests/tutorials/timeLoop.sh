#!/bin/bash
#------------------------------------------------------------------------------
# nmmSolid: Numerical Manifold Method solver for deformable geomaterials
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Script
#     tests/tutorials/timeLoop.sh
#
# Description
#     Runs tutorials/basic/timeLoop from a scratch copy and checks what
#     nmmSolidFoam leaves behind (time directories, uniform/time, the log,
#     exit codes).
#
#         timeLoop.sh <check> <binDir> <projectDir> <workDir>
#
#     check:
#         allrun       Allrun writes the four write times, Allclean removes them
#         restart      startFrom latestTime continues the time index
#         signal       SIGTERM writes the current time and exits with 0
#         writeNow     "stopAt writeNow" written into the running case stops it
#         errors       FOAM-style fatal errors with exit code 1; -dry-run, -help
#------------------------------------------------------------------------------

check="$1"
binDir="$2"
projectDir="$3"
workDir="$4"

failures=0

fail()
{
    echo "FAILED: $*" 1>&2
    failures=$((failures + 1))
}

expectEqual()   # what actual expected
{
    if [ "$2" != "$3" ]
    then
        fail "$1: expected '$3', got '$2'"
    fi
}

expectInFile()  # file text
{
    if ! grep -qF -- "$2" "$1"
    then
        fail "'$2' not in $1"
        sed -n '1,40p' "$1" 1>&2
    fi
}

# Time directory names in time order
timeDirs()
{
    local d
    for d in */
    do
        d="${d%/}"
        # The initial conditions (0/) are input, not written times
        [ "$d" = 0 ] && continue
        [[ "$d" =~ ^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$ ]] && echo "$d"
    done | sort -g | tr '\n' ' ' | sed 's/ $//'
}

# Value of a keyword in a dictionary file
entry()         # file keyword
{
    sed -n "s/^$2[[:space:]]*\\([^;]*\\);.*/\\1/p" "$1" | tr -d '"'
}

# Wait (at most $2 s) until file $1 contains text $3
waitFor()
{
    local i
    for ((i = 0; i < $2 * 10; i++))
    do
        grep -qF -- "$3" "$1" 2>/dev/null && return 0
        sleep 0.1
    done
    return 1
}

setEntry()      # keyword value (in system/controlDict)
{
    sed -i "s/^$1 .*/$1 $2;/" system/controlDict
}

[ -x "$binDir/nmmSolidFoam" ] || { echo "no $binDir/nmmSolidFoam" 1>&2; exit 1; }
export PATH="$binDir:$PATH"
export NMM_PROJECT_DIR="$projectDir"

rm -rf "$workDir"
mkdir -p "$workDir"
cp -r "$projectDir/tutorials/basic/timeLoop" "$workDir/timeLoop"
cd "$workDir/timeLoop" || exit 1

case "$check" in
allrun)
    ./Allrun || fail "Allrun returned $?"
    expectEqual "time directories" "$(timeDirs)" "0.00025 0.0005 0.00075 0.001"
    for t in 0.00025 0.0005 0.00075 0.001
    do
        [ -f "$t/uniform/time" ] || fail "no $t/uniform/time"
        expectEqual "$t name" "$(entry "$t/uniform/time" name)" "$t"
    done
    expectEqual "index of 0.001" "$(entry 0.001/uniform/time index)" "12"
    expectInFile log.nmmSolidFoam "Time = 8.33333e-05"
    expectInFile log.nmmSolidFoam "Time = 0.001"
    expectInFile log.nmmSolidFoam "ExecutionTime = "
    expectInFile log.nmmSolidFoam "  ClockTime = "
    expectInFile log.nmmSolidFoam "Exec   : nmmSolidFoam"
    expectEqual "last line" "$(grep -v '^$' log.nmmSolidFoam | tail -n 1)" "End"
    expectEqual "hidden entries" "$(ls -A | grep '^\.' | tr '\n' ' ')" ""
    # Function objects: '#' header, the start row and one row per step
    for f in motion balance
    do
        file="postProcessing/$f/0/$f.dat"
        [ -f "$file" ] || fail "no $file"
        expectEqual "$file header" "$(head -c 7 "$file")" "# time "
        expectEqual "$file rows" "$(grep -vc '^#' "$file")" "13"
    done

    ./Allclean || fail "Allclean returned $?"
    expectEqual "time directories after Allclean" "$(timeDirs)" ""
    [ -f log.nmmSolidFoam ] && fail "Allclean left log.nmmSolidFoam"
    [ -d postProcessing ] && fail "Allclean left postProcessing"
    ;;

restart)
    ./Allrun || fail "Allrun returned $?"
    setEntry startFrom latestTime
    setEntry endTime 2e-3
    nmmSolidFoam > log.restart 2>&1 || fail "restart returned $?"
    expectEqual "time directories" "$(timeDirs)" \
        "0.00025 0.0005 0.00075 0.001 0.00125 0.0015 0.00175 0.002"
    expectInFile log.restart "Start time = 0.001, time index 12"
    expectEqual "index of 0.002" "$(entry 0.002/uniform/time index)" "24"
    # The restarted run's rows go to a folder of its start time, as in
    # OpenFOAM; the first run's file stays
    expectEqual "rows of the first run" \
        "$(grep -vc '^#' postProcessing/motion/0/motion.dat)" "13"
    expectEqual "rows of the restarted run" \
        "$(grep -vc '^#' postProcessing/motion/0.001/motion.dat)" "13"
    expectEqual "first row of the restart" \
        "$(grep -v '^#' postProcessing/motion/0.001/motion.dat | head -n 1 | cut -d' ' -f2-)" \
        "$(grep -v '^#' postProcessing/motion/0/motion.dat | tail -n 1 | cut -d' ' -f2-)"

    # The restarted run reproduces an uninterrupted one (state from
    # 0.001/nmmState.h5): the displacements of the last frames agree
    cp -r "$projectDir/tutorials/basic/timeLoop" ../straight
    (cd ../straight && setEntry endTime 2e-3 && ./Allrun) \
        || fail "uninterrupted run failed"
    python=/usr/bin/python3     # Debian's, which sees python3-vtk9
    [ -x "$python" ] || python=python3
    "$python" - VTK/timeLoop_24.vtu ../straight/VTK/straight_24.vtu <<'PYTHON' \
        || fail "restarted and uninterrupted runs differ"
import sys
import numpy as np
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

def pointD(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return vtk_to_numpy(r.GetOutput().GetPointData().GetArray("D"))

a, b = pointD(sys.argv[1]), pointD(sys.argv[2])
difference = np.abs(a - b).max()/np.abs(b).max()
print("restart vs uninterrupted: largest difference of D %.3g (relative)" % difference)
sys.exit(0 if a.shape == b.shape and np.abs(b).max() > 0 and difference < 1e-12 else 1)
PYTHON
    ;;

signal)
    setEntry endTime 1e9
    setEntry writeInterval 1e6
    nmmSolidFoam > log.nmmSolidFoam 2>&1 &
    pid=$!
    waitFor log.nmmSolidFoam 20 "Starting time loop" || fail "run did not start"
    kill -TERM "$pid"
    wait "$pid"
    expectEqual "exit code" "$?" "0"
    expectInFile log.nmmSolidFoam "Stopped by SIGTERM at time = "
    expectEqual "last line" "$(grep -v '^$' log.nmmSolidFoam | tail -n 1)" "End"
    dirs="$(timeDirs)"
    expectEqual "number of time directories" "$(echo "$dirs" | wc -w)" "1"
    [ -f "$dirs/uniform/time" ] || fail "no uniform/time in '$dirs'"
    expectEqual "hidden entries" "$(ls -A | grep '^\.' | tr '\n' ' ')" ""
    # The stopped run's tables have the start row and one per step
    index="$(entry "$dirs/uniform/time" index)"
    for f in motion balance
    do
        expectEqual "$f rows" "$(grep -vc '^#' "postProcessing/$f/0/$f.dat")" \
            "$((index + 1))"
    done
    ;;

writeNow)
    setEntry endTime 1e9
    setEntry writeInterval 1e6
    nmmSolidFoam > log.nmmSolidFoam 2>&1 &
    pid=$!
    waitFor log.nmmSolidFoam 20 "Starting time loop" || fail "run did not start"
    setEntry stopAt writeNow
    for ((i = 0; i < 200; i++))
    do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    if kill -0 "$pid" 2>/dev/null
    then
        fail "stopAt writeNow did not stop the run"
        kill -KILL "$pid"
    fi
    wait "$pid"
    expectEqual "exit code" "$?" "0"
    expectInFile log.nmmSolidFoam "Re-reading object controlDict from file"
    dirs="$(timeDirs)"
    expectEqual "number of time directories" "$(echo "$dirs" | wc -w)" "1"
    ;;

errors)
    # -dry-run reads and validates, writes nothing
    nmmSolidFoam -dry-run > log.dryRun 2>&1 || fail "-dry-run returned $?"
    expectInFile log.dryRun "Dry run"
    expectEqual "time directories after -dry-run" "$(timeDirs)" ""
    [ -d postProcessing ] && fail "-dry-run wrote postProcessing"

    nmmSolidFoam -help > log.help 2>&1 || fail "-help returned $?"
    expectInFile log.help "Keywords of system/controlDict"
    expectInFile log.help "adjustableRunTime"
    expectInFile log.help "type patchDisplacement"

    # -noFunctionObjects does not even read the entries
    cp system/controlDict controlDict.orig
    sed -i 's/type energy;/type energi;/' system/controlDict
    nmmSolidFoam -dry-run -noFunctionObjects > /dev/null 2>&1 \
        || fail "-noFunctionObjects read the function objects"
    nmmSolidFoam -dry-run > /dev/null 2> err.functionObject
    expectEqual "bad function object exit code" "$?" "1"
    expectInFile err.functionObject "did you mean 'energy'?"
    cp controlDict.orig system/controlDict

    nmmSolidFoam -cse . > /dev/null 2> err.option
    expectEqual "unknown option exit code" "$?" "1"
    expectInFile err.option "--> FOAM FATAL ERROR:"
    expectInFile err.option "Invalid option: -cse; did you mean '-case'?"

    sed -i 's/^writeControl .*/writeControl    adjustableRuntime;/' system/controlDict
    nmmSolidFoam > /dev/null 2> err.keyword
    expectEqual "bad keyword exit code" "$?" "1"
    expectInFile err.keyword "--> FOAM FATAL IO ERROR:"
    expectInFile err.keyword "did you mean 'adjustableRunTime'?"
    expectInFile err.keyword "file: $PWD/system/controlDict at line"
    expectInFile err.keyword "keyword: writeControl"

    rm system/controlDict
    nmmSolidFoam > /dev/null 2> err.missing
    expectEqual "missing controlDict exit code" "$?" "1"
    expectInFile err.missing "cannot find file \"$PWD/system/controlDict\""
    ;;

*)
    echo "unknown check '$check'" 1>&2
    exit 1
    ;;
esac

if [ "$failures" -gt 0 ]
then
    echo "$check: $failures check(s) failed in $PWD" 1>&2
    exit 1
fi
echo "$check: passed"
