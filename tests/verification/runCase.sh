#!/bin/bash
#------------------------------------------------------------------------------
# nmmSolid: Numerical Manifold Method solver for deformable geomaterials
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Script
#     tests/verification/runCase.sh
#
# Description
#     Runs verification tutorials from scratch copies and compares them with
#     their closed form.
#
#         runCase.sh <binDir> <projectDir> <workDir> <python> <checker> \
#             <tutorial>[@cellSize] ... [-- <checker arguments>]
#
#     Each tutorial (a path under tutorials/, e.g. verification/lame) is
#     copied to <workDir>/<name> (<name>_h<cellSize> when a cellSize is
#     given, which then replaces the cellSize of system/nmmMeshDict), its
#     Allrun is run with <binDir> first on PATH, and the run must end with
#     exit code 0 and 'End' in log.nmmSolidFoam. Then
#         <python> <checker> <case> ... <checker arguments>
#     runs on all the copies (coarse first, in the order given) and its exit
#     code is the script's.
#------------------------------------------------------------------------------

[ "$#" -ge 6 ] || { sed -n '/^# Description/,/^#---/p' "$0"; exit 1; }
binDir="$1"
projectDir="$2"
workDir="$3"
python="$4"
checker="$5"
shift 5

specs=()
while [ "$#" -gt 0 ] && [ "$1" != "--" ]
do
    specs+=("$1")
    shift
done
[ "${1:-}" = "--" ] && shift

for app in nmmMesh nmmSolidFoam
do
    [ -x "$binDir/$app" ] || { echo "no $binDir/$app" 1>&2; exit 1; }
done
export PATH="$binDir:$PATH"
export NMM_PROJECT_DIR="$projectDir"

mkdir -p "$workDir"
cases=()
for spec in "${specs[@]}"
do
    tutorial="${spec%@*}"
    name="$(basename "$tutorial")"
    cellSize=""
    if [ "$spec" != "$tutorial" ]
    then
        cellSize="${spec##*@}"
        name="${name}_h${cellSize}"
    fi
    src="$projectDir/tutorials/$tutorial"
    [ -d "$src" ] || { echo "no tutorial $src" 1>&2; exit 1; }
    dst="$workDir/$name"
    rm -rf "$dst"
    cp -r "$src" "$dst"
    if [ -n "$cellSize" ]
    then
        sed -i "s/^\([[:space:]]*cellSize[[:space:]]\+\)[^;]*;/\1$cellSize;/" \
            "$dst/system/nmmMeshDict"
        grep -q "cellSize[[:space:]]*$cellSize;" "$dst/system/nmmMeshDict" \
            || { echo "could not set cellSize $cellSize in $dst" 1>&2; exit 1; }
    fi
    echo "== $tutorial -> $dst"
    start=$SECONDS
    if ! "$dst/Allrun"
    then
        echo "Allrun of $dst failed" 1>&2
        for log in "$dst"/log.*
        do
            [ -f "$log" ] && { echo "--- $log (last lines)"; tail -n 30 "$log"; } 1>&2
        done
        exit 1
    fi
    if [ "$(grep -v '^$' "$dst/log.nmmSolidFoam" | tail -n 1)" != "End" ]
    then
        echo "log.nmmSolidFoam of $dst does not end with End" 1>&2
        tail -n 30 "$dst/log.nmmSolidFoam" 1>&2
        exit 1
    fi
    echo "   ran in $((SECONDS - start)) s"
    cases+=("$dst")
done

exec "$python" "$checker" "${cases[@]}" "$@"
