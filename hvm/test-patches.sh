#!/usr/bin/env bash
# Runs the program that tests each of our VM patches (hvm/tests/hvmtest) on the patched VM,
# where it must pass, and with --unpatched also on the upstream VM, where it must fail (exit
# status not 0, or a hang stopped by the timeout): the proof that each test can fail.
# Each program runs in the modes its row names: interpreted (every method interpreted) and/or
# compiled (hvmc.sh --mode compiled: icecap -aot translates every method but main to C, so these
# programs keep their logic outside main) and/or hot (--mode hot: only the methods NAME.methods
# lists are compiled; the compiler's log must name exactly those). Upstream, a compiled program
# may also fail by not compiling (the code generator refuses a bytecode it lacks, or crashes), and
# a hot one by the compiler ignoring its list: that counts as failing there; any other build
# failure is a broken test.
#
#   hvm/test-patches.sh [--unpatched] [--only=NAME]
#
# Needs what build-hvm.sh needs (HVM_SRC, ...).
# Exit codes: 0 every expectation holds; 1 one does not, or the tool chain failed to build; 2 bad
# usage (an option, a bad HVM_SRC).
set -euo pipefail

HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
TIMEOUT=15
variants=(patched)
only=
. "$HERE/script-options.sh"
for a in "$@"; do
    case "$a" in
        --unpatched) variants+=(unpatched) ;;
        --only=*) only=${a#--only=}; [ -n "$only" ] || bad "--only: needs a test name (--only=NAME)" ;;
        --only) bad "--only: needs a test name (--only=NAME)" ;;
        -h|--help) header_help; exit 0 ;;
        *) bad "unknown option: $a" ;;
    esac
done

# test program -> the patch(es) it checks -> the modes it runs in
tests=(
    "DoubleSubDiv 01-double-sub-div-operands+13 interpreted,compiled"
    "DoubleOpcodes 02-dneg-drem-l2d-d2l+13 interpreted,compiled"
    "LongDivRem 03-long-div-rem interpreted,compiled"
    "StrictMathLog 04-strictmath-log interpreted"
    "ClockTick 05-clock-tick-absolute interpreted"
    "DoubleLongBits 06-double-long-bits interpreted,compiled"
    "AotDoubles 13-aot-double-opcodes compiled"
    "AotStackOps 14-aot-stack-opcodes compiled"
    "IntSemantics 15-int-semantics interpreted,compiled"
    "LongArithmetic 16-long-arithmetic interpreted,compiled"
    "NaNCompare 17-nan-compare-saturation interpreted,compiled"
    "FloatOps 18-float-interpreted interpreted,compiled"
    "ArrayBounds 19-array-bounds interpreted,compiled"
    "FloorCeil 21-strictmath-floor-ceil interpreted,compiled"
    "HotMethods 22-aot-listed-methods hot"
    "SyncReturn 23-aot-synchronized-return compiled"
)

# A name no row has ran nothing and passed.
if [ -n "$only" ]; then
    names=()
    for t in "${tests[@]}"; do names+=("${t%% *}"); done
    [[ " ${names[*]} " == *" $only "* ]] || bad "--only: no test named '$only' (one of: ${names[*]})"
fi

need_tools javac timeout
work=$(mktemp -d "${TMPDIR:-/tmp}/hvm-patches.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
for variant in "${variants[@]}"; do
    if [ "$variant" = patched ]; then tc=$("$HERE/build-hvm.sh"); else tc=$("$HERE/build-hvm.sh" --unpatched); fi
    mkdir -p "$work/$variant/classes"
    javac -nowarn -source 8 -target 8 -bootclasspath "$tc/rt.jar" -cp "$tc/sdk" -d "$work/$variant/classes" \
        "$HERE"/tests/hvmtest/*.java 2>&1 | grep -v '^warning\|^Note\|^1 warning' >&2 || true
    for t in "${tests[@]}"; do
        read -r name patch modes <<< "$t"
        [ -z "$only" ] || [ "$only" = "$name" ] || continue
        nat=()
        [ -f "$HERE/tests/hvmtest/$name.c" ] && nat=(--natives "$HERE/tests/hvmtest/$name.c")
        for mode in ${modes//,/ }; do
            exe=$work/$variant/$name-$mode
            rc=0
            list=()
            [ "$mode" != hot ] || list=(--methods "$HERE/tests/hvmtest/$name.methods")
            if ! "$HERE/hvmc.sh" --toolchain "$tc" --classes "$work/$variant/classes" --main "hvmtest.$name" \
                    "${nat[@]}" --mode "$mode" "${list[@]}" --heap 4000000 --log "$exe.log" -o "$exe" 2>/dev/null; then
                if [ "$mode" = hot ] && grep -q "the compiler did not read the list" "$exe.log"; then
                    result="fail (the compiler ignores the list)"; rc=-2
                elif [ "$mode" = compiled ] && grep -q "unsupported byte code" "$exe.log"; then
                    result="fail (the compiler refuses a bytecode)"; rc=-2
                elif [ "$mode" = compiled ] && grep -q "^Exception in thread \"main\"" "$exe.log"; then
                    result="fail (the compiler crashes)"; rc=-2
                else
                    result="BUILD-FAILED"; rc=-1
                    tail -5 "$exe.log" | sed 's/^/    | /' >&2
                fi
            else
                timeout "$TIMEOUT" "$exe" > "$exe.out" 2>&1 || rc=$?
                case $rc in 0) result=pass ;; 124) result="fail (hung, stopped after ${TIMEOUT}s)" ;; *) result="fail (exit $rc)" ;; esac
                if [ "$mode" = hot ] && [ $rc = 0 ]; then
                    # each entry of the list matched one method (no overloads here), and nothing else was compiled
                    entries=$(sed 's/#.*//' "$HERE/tests/hvmtest/$name.methods" | awk 'NF' | wc -l)
                    if [ "$(grep -c '^aot list: ' "$exe.log")" != "$entries" ]; then
                        result="fail (the log does not name the $entries listed methods)"; rc=-3
                    fi
                fi
            fi
            if [ "$variant" = patched ]; then expect=pass; else expect=fail; fi
            verdict=ok
            if [ "$expect" = pass ] && [ "$rc" != 0 ]; then verdict=WRONG; fi
            if [ "$expect" = fail ] && { [ "$rc" = 0 ] || [ "$rc" = -1 ]; }; then verdict=WRONG; fi
            [ $verdict = ok ] || failures=$((failures + 1))
            printf '%-10s %-15s %-12s %-32s %-42s %s\n' "$variant" "$name" "$mode" "$patch" "$result" "$verdict"
        done
    done
done
if [ $failures -gt 0 ]; then
    echo "test-patches: $failures expectation(s) not met" >&2
    exit 1
fi
