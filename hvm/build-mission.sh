#!/usr/bin/env bash
# Builds the HVM executable of the jmclbench SCJ mission (the same core-immortal and
# scj-mission sources the JVM runs, compiled against icecap's SCJ library, with the entry point
# and natives of hvm/mission) and prints its path. Cached beside the tool chain, keyed by the
# sources, the natives, the heap size and the mode.
#
#   hvm/build-mission.sh [--heap BYTES] [--mode compiled|interpreted|hot]
#
# --heap: the VM's Java heap (default: the heap of hvm/hvm.properties, the size the hvm engine
# checks area sizes against).
# --mode (default: $JMCLBENCH_HVM_MODE, else compiled): compiled translates every method but main
# to C (icecap -aot, with our patches 13-21; a method that handles floats stays interpreted);
# interpreted runs every method in icecap's interpreter (the hvm runtime's profile int); hot
# compiles only the methods hvm/mission/hot-methods.txt lists and interprets the rest (patch 22;
# the profile hot). The mode (and hot's list) is part of the cache key and is written to MODE
# beside the executable (summary.json's engine.mode).
# Needs what build-hvm.sh needs (HVM_SRC, ...).
# Exit codes: 0 built (or cached); 1 the build failed (the tool chain's, javac's or hvmc.sh's, a
# line says which); 2 bad usage (an option, JMCLBENCH_HVM_MODE, a bad HVM_SRC).
set -euo pipefail

HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
ROOT=$(dirname "$HERE")
# The VM's Java heap holds the SCJ backing store (immortal, mission and private memories); its
# size is hvm/hvm.properties', which the hvm engine checks area sizes against before a run.
# (read with bash alone: a missing tool is need_tools' line below, not an empty heap)
heap=
while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in heap=*) heap=${line#heap=} ;; esac
done 2>/dev/null < "$HERE/hvm.properties" || true
mode=${JMCLBENCH_HVM_MODE:-compiled}
. "$HERE/script-options.sh"
[[ $heap =~ ^[1-9][0-9]{0,17}$ ]] || bad "hvm/hvm.properties: heap: '$heap' is not a positive number of bytes"
while [ $# -gt 0 ]; do
    case "$1" in
        --heap|--mode) [ $# -ge 2 ] || bad "$1: needs a value" ;;
    esac
    case "$1" in
        --heap) heap=$2; shift 2 ;;
        --mode) mode=$2; shift 2 ;;
        -h|--help) header_help; exit 0 ;;
        *) bad "unknown option: $1" ;;
    esac
done
# hvmc.sh would refuse it too, but after the tool chain's build, and as a failed build (exit 1)
[[ $heap =~ ^[1-9][0-9]{0,17}$ ]] || bad "--heap: '$heap' is not a positive number of bytes"
case "$mode" in
    interpreted|compiled|hot) ;;
    *) echo "build-mission: the mode (--mode or JMCLBENCH_HVM_MODE) must be interpreted, compiled or hot: $mode" >&2; exit 2 ;;
esac
hot_list=$HERE/mission/hot-methods.txt
list=()
[ "$mode" != hot ] || list=(--methods "$hot_list")

need_tools javac
tc=$("$HERE/build-hvm.sh")
srcs=("$ROOT/core-immortal/src/main/java" "$ROOT/scj-mission/src/main/java" "$HERE/mission/src")
key=$( { find "${srcs[@]}" -name '*.java' -print0 | sort -z | xargs -0 sha256sum | sed "s|$ROOT/||";
         sha256sum "$HERE/mission/natives.c" "$HERE/hvmc.sh" "$hot_list" | sed "s|$ROOT/||"; echo "heap $heap"; echo "mode $mode"; } \
       | sha256sum | cut -c1-16)
out=$tc/mission-$key
exe=$out/jmclbench-hvm
if [ -x "$exe" ]; then
    echo "$exe"
    exit 0
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/hvm-mission.XXXXXX")
trap 'rm -rf "$work"' EXIT
echo "build-mission: compiling the mission for the HVM, $mode (about 20 s)" >&2
find "${srcs[@]}" -name '*.java' -not -name 'package-info.java' > "$work/sources"
mkdir "$work/classes"
if ! javac -nowarn -source 8 -target 8 -encoding UTF-8 -bootclasspath "$tc/rt.jar" -cp "$tc/sdk" \
        -d "$work/classes" @"$work/sources" > "$work/javac.log" 2>&1; then
    grep -v '^warning\|^Note' "$work/javac.log" >&2
    echo "build-mission: the mission does not compile against icecap's SCJ library" >&2
    exit 1
fi
mkdir -p "$work/out"
"$HERE/hvmc.sh" --toolchain "$tc" --classes "$work/classes" --main org.jmclbench.hvm.HvmMain \
    --natives "$HERE/mission/natives.c" --heap "$heap" --mode "$mode" "${list[@]}" --log "$work/hvmc.log" -o "$work/out/jmclbench-hvm" \
    || { tail -20 "$work/hvmc.log" >&2; exit 1; }
cp "$work/hvmc.log" "$work/out/build.log"
echo "$mode" > "$work/out/MODE"
mkdir -p "$tc"
if ! mv -T "$work/out" "$out" 2>/dev/null; then
    [ -x "$exe" ] || { echo "build-mission: cannot write $out" >&2; exit 1; }
fi
echo "$exe"
