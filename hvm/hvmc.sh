#!/usr/bin/env bash
# Compiles a Java program into an icecap HVM executable with a tool chain built by build-hvm.sh.
#
#   hvm/hvmc.sh --toolchain DIR --classes CP --main pkg.Class [--natives FILE.c]...
#               [--mode interpreted|compiled|hot [--methods LIST]] [--heap BYTES] [--log FILE]
#               [--keep-c DIR] -o EXECUTABLE
#
# --mode: interpreted (the default) translates no method (the VM interprets the bytecode);
# compiled translates every method to C except those named main (icecap's -aot), and except
# methods that handle floats (patch 18; they stay interpreted). With patches 13-21 compiled code
# follows Java for int, long and double, array bounds included (issue 18). hot translates only the
# methods LIST names (patch 22: lines pkg.Class.method, pkg.Class.method(descriptor) or
# pkg.Class.*; '#' comments) and interprets the rest; an entry that names no method of the program
# is an error. The mission's default (build-mission.sh) is compiled; this script's stays
# interpreted, and its callers say which.
# CP: the program's class folders (':'-separated), compiled for Java 8 against DIR/rt.jar
# (-bootclasspath) and DIR/sdk. FILE.c: C natives of the program (functions named
# n_<package>_<Class>_<method>(int32 *sp)); they are compiled with the generated VM, with its
# headers on the include path. BYTES: the VM's Java heap (default 16000000); the SCJ memory
# areas are carved out of it.
# --keep-c DIR keeps the generated C (for reading or profiling).
# Steps (about 10 s): main.CompilationManager writes the program and the VM as C into a
# temporary folder; gcc links it with the flags below.
# Exit codes: 0 built; 1 the compiler or gcc failed (a line says which; --log keeps the log), or a
# tool is missing; 2 bad usage (an option, or a --methods LIST entry that names no method of the
# program).
set -euo pipefail
HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
. "$HERE/script-options.sh"

tc= classes= main= heap=16000000 out= log= mode=interpreted keep= methods=
natives=()
while [ $# -gt 0 ]; do
    case "$1" in
        --toolchain|--classes|--main|--natives|--heap|--log|--mode|--keep-c|--methods|-o)
            [ $# -ge 2 ] || bad "$1: needs a value" ;;
    esac
    case "$1" in
        --toolchain) tc=$2; shift 2 ;;
        --classes) classes=$2; shift 2 ;;
        --main) main=$2; shift 2 ;;
        --natives) [ -f "$2" ] || { echo "hvmc: --natives: no such file: $2" >&2; exit 2; }
                   natives+=("$(readlink -f "$2")"); shift 2 ;;
        --heap) heap=$2; shift 2 ;;
        --log) log=$2; shift 2 ;;
        --mode) mode=$2; shift 2 ;;
        --keep-c) keep=$2; shift 2 ;;
        --methods) methods=$2; shift 2 ;;
        -o) out=$2; shift 2 ;;
        -h|--help) header_help; exit 0 ;;
        *) echo "hvmc: unknown option: $1" >&2; exit 2 ;;
    esac
done
[ -n "$tc" ] && [ -n "$classes" ] && [ -n "$main" ] && [ -n "$out" ] \
    || { echo "hvmc: --toolchain, --classes, --main and -o are required" >&2; exit 2; }
# before the compiler runs: an output that cannot be written failed after it, with mkdir's or mv's words
writable_folder -o "$out" "$(dirname "$out")"
[ -z "$log" ] || writable_folder --log "$log" "$(dirname "$log")"
[ -z "$keep" ] || writable_folder --keep-c "$keep"
# Paths the script uses after it changes folder (realpath -m: readlink -f fails, and with it the
# script, silently, for a path two folders below what exists, which -o and --keep-c may name).
out=$(realpath -m "$out")
[ -z "$log" ] || log=$(realpath -m "$log")
[ -z "$keep" ] || keep=$(realpath -m "$keep")
[ -f "$tc/KEY" ] || { echo "hvmc: $tc is not a tool chain built by build-hvm.sh" >&2; exit 2; }
case "$heap" in ''|*[!0-9]*) echo "hvmc: --heap must be a number of bytes: $heap" >&2; exit 2 ;; esac
case "$mode" in
    compiled|interpreted) [ -z "$methods" ] || { echo "hvmc: --methods: only with --mode hot" >&2; exit 2; } ;;
    hot) [ -n "$methods" ] || { echo "hvmc: --mode hot needs --methods LIST" >&2; exit 2; }
         [ -f "$methods" ] || { echo "hvmc: --methods: no such file: $methods" >&2; exit 2; }
         methods=$(readlink -f "$methods") ;;
    *) echo "hvmc: --mode must be interpreted, compiled or hot: $mode" >&2; exit 2 ;;
esac

pkg=${main%.*}
cls=${main##*.}
[ "$pkg" != "$main" ] || { echo "hvmc: --main needs a package: $main" >&2; exit 2; }
abs_cp=
IFS=: read -ra parts <<< "$classes"
for p in "${parts[@]}"; do
    [ -e "$p" ] || { echo "hvmc: --classes: no such folder or jar: $p" >&2; exit 2; }
    abs_cp+=$(readlink -f "$p"):
done
need_tools java gcc

work=$(mktemp -d "${TMPDIR:-/tmp}/hvmc.XXXXXX")
trap 'rm -rf "$work"' EXIT
# the failure lines name the log only when it outlives the script (the temporary one is removed)
where="log: $log"
[ -n "$log" ] || { log=$work/compile.log; where="no log kept: --log FILE keeps it"; }
mkdir -p "$(dirname "$log")"
: > "$log"

# The compiler reads hvm.properties from its working folder for the VM sources to copy.
echo "vmSourceFolder=$tc/src/icecapvm/src" > "$work/hvm.properties"
aot=()
case "$mode" in
    compiled) aot=(-aot) ;;
    hot) aot=("-aot=$methods") ;;
esac
mkdir "$work/c"
if ! (cd "$work" && java -cp "$tc/tools:$tc/lib/bcel-6.0.jar" main.CompilationManager \
        "$abs_cp$tc/sdk:$tc/rt.jar" "$pkg" "$cls" "$work/c/" "${aot[@]}") >> "$log" 2>&1 \
        || grep -q "Couldn't find" "$log" || [ ! -f "$work/c/classes.c" ]; then
    echo "hvmc: the icecap compiler failed for $main ($where):" >&2
    grep -m1 -A4 "Couldn't find\|Exception in thread" "$log" >&2 || tail -5 "$log" >&2
    exit 1
fi

# A hot build: the compiler names each listed method it met ("aot list: ..."), and each entry no
# method matched; a tool chain without patch 22 names none (it ignored the list).
if [ "$mode" = hot ]; then
    if ! grep -q "^aot list: " "$log"; then
        echo "hvmc: --methods $methods: the compiler did not read the list (a tool chain without patch 22?)" | tee -a "$log" >&2
        exit 1
    fi
    if grep -q "^aot list: not in the program: " "$log"; then
        echo "hvmc: --methods $methods: $(grep -m1 "^aot list: not in the program: " "$log" | sed 's/^aot list: not in the program: //')" \
            "names no method of $main" | tee -a "$log" >&2
        exit 2
    fi
fi

# -mincoming-stack-boundary=3 -mstackrealign: the VM's threads start on stacks it allocates
# itself, 8-byte aligned; without realignment SSE code in pthread_create can crash.
# -fno-strict-aliasing: the VM and the generated C write int32 stack words and read them as
# doubles (without it gcc reorders the two at -O2 and the mission hangs); -fwrapv: Java's int and
# long arithmetic wraps, C's signed overflow is undefined; -ffp-contract=off: no fused multiply-add
# (Java rounds each operation). -O3, not the C baseline's -O2: measured, the compiled mission's
# jobs are 10% faster (docs/HVM.md).
cd "$work/c"
if ! gcc -O3 -w -fno-strict-aliasing -fwrapv -ffp-contract=off -DPC64 -DPRINTFSUPPORT -DREF_OFFSET -DSUPPORTGC -DJAVA_HEAP_SIZE="$heap" \
        -mincoming-stack-boundary=3 -mstackrealign -I. -o "$work/a.out" \
        classes.c icecapvm.c methodinterpreter.c methods.c gc.c natives_allOS.c natives_i86.c \
        rom_heap.c allocation_point.c rom_access.c print.c x86_64_interrupt.s "${natives[@]}" \
        -Wl,-z,noexecstack -lpthread -lrt -lm >> "$log" 2>&1; then
    echo "hvmc: gcc failed for $main ($where):" >&2
    grep -m10 "error" "$log" >&2 || tail -10 "$log" >&2
    exit 1
fi
if [ -n "$keep" ]; then
    rm -rf "$keep" && mkdir -p "$keep" && cp -r "$work/c/." "$keep/"
fi
mkdir -p "$(dirname "$out")"
mv "$work/a.out" "$out"
