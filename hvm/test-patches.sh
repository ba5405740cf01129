#!/usr/bin/env bash
# Runs the program that tests each of our VM patches (hvm/tests/hvmtest) on the patched VM,
# where it must pass, and with --unpatched also on the upstream VM, where it must fail (exit
# status not 0, or a hang stopped by the timeout): the proof that each test can fail.
#
#   hvm/test-patches.sh [--unpatched]
#
# Needs what build-hvm.sh needs (HVM_SRC, ...). Exit 0 when every expectation holds.
set -euo pipefail

HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
TIMEOUT=15
variants=(patched)
for a in "$@"; do
    case "$a" in
        --unpatched) variants+=(unpatched) ;;
        -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "test-patches: unknown option: $a" >&2; exit 2 ;;
    esac
done

# test program -> the patch it checks
tests=(
    "DoubleSubDiv 01-double-sub-div-operands"
    "DoubleOpcodes 02-dneg-drem-l2d-d2l"
    "LongDivRem 03-long-div-rem"
    "StrictMathLog 04-strictmath-log"
    "ClockTick 05-clock-tick-absolute"
    "DoubleLongBits 06-double-long-bits"
)

work=$(mktemp -d "${TMPDIR:-/tmp}/hvm-patches.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
for variant in "${variants[@]}"; do
    if [ "$variant" = patched ]; then tc=$("$HERE/build-hvm.sh"); else tc=$("$HERE/build-hvm.sh" --unpatched); fi
    mkdir -p "$work/$variant/classes"
    javac -nowarn -source 8 -target 8 -bootclasspath "$tc/rt.jar" -cp "$tc/sdk" -d "$work/$variant/classes" \
        "$HERE"/tests/hvmtest/*.java 2>&1 | grep -v '^warning\|^Note\|^1 warning' >&2 || true
    for t in "${tests[@]}"; do
        read -r name patch <<< "$t"
        nat=()
        [ -f "$HERE/tests/hvmtest/$name.c" ] && nat=(--natives "$HERE/tests/hvmtest/$name.c")
        exe=$work/$variant/$name
        rc=0
        if ! "$HERE/hvmc.sh" --toolchain "$tc" --classes "$work/$variant/classes" --main "hvmtest.$name" \
                "${nat[@]}" --heap 4000000 -o "$exe"; then
            result="BUILD-FAILED"; rc=-1
        else
            timeout "$TIMEOUT" "$exe" > "$work/$variant/$name.out" 2>&1 || rc=$?
            case $rc in 0) result=pass ;; 124) result="fail (hung, stopped after ${TIMEOUT}s)" ;; *) result="fail (exit $rc)" ;; esac
        fi
        if [ "$variant" = patched ]; then expect=pass; else expect=fail; fi
        verdict=ok
        if [ "$expect" = pass ] && [ "$rc" != 0 ]; then verdict=WRONG; fi
        if [ "$expect" = fail ] && { [ "$rc" = 0 ] || [ "$rc" = -1 ]; }; then verdict=WRONG; fi
        [ $verdict = ok ] || failures=$((failures + 1))
        printf '%-10s %-15s %-28s %-40s %s\n' "$variant" "$name" "$patch" "$result" "$verdict"
    done
done
if [ $failures -gt 0 ]; then
    echo "test-patches: $failures expectation(s) not met" >&2
    exit 1
fi
