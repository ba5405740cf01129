#!/usr/bin/env bash
# Runs icecap's own SCJ tests (icecaptoolstest/src/test/TestSCJSingle*.java, single core) on
# our patched VM, in each mode: each is compiled to an HVM executable and run; it passes when it
# exits 0 (the tests call vm.VMTest.markResult(false) on success). Prints one line a test and mode
# and a total.
#
#   hvm/upstream-scj-tests.sh [--timeout SECONDS] [--modes interpreted,compiled] [TestName...]
#
# Known failures (listed below, not counted): TestSCJSingleRawMemory_MemoryMapped1 maps raw
# device memory at a fixed address, which a Linux process cannot do (both modes). Takes about
# 10 s a test and mode.
# Exit codes: 0 every other test passes and only known failures fail; 1 an unexpected failure, or
# the tool chain failed to build; 2 bad usage (an option, a bad HVM_SRC).
set -euo pipefail

HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
timeout_s=60
modes=interpreted,compiled
names=()
. "$HERE/script-options.sh"
while [ $# -gt 0 ]; do
    case "$1" in
        --timeout|--modes) [ $# -ge 2 ] || bad "$1: needs a value" ;;
    esac
    case "$1" in
        --timeout) timeout_s=$2; shift 2 ;;
        --modes) modes=$2; shift 2 ;;
        -h|--help) header_help; exit 0 ;;
        -*) bad "unknown option: $1" ;;
        *) names+=("$1"); shift ;;
    esac
done
# A bad value failed every run (timeout refused it, hvmc.sh refused the mode) as the VM's failure.
[[ $timeout_s =~ ^[1-9][0-9]{0,5}$ ]] || bad "--timeout: '$timeout_s' is not a positive number of seconds"
[[ $modes =~ ^(interpreted|compiled)(,(interpreted|compiled))*$ ]] \
    || bad "--modes: '$modes' is not a list of interpreted and compiled"
# test or test/mode -> why it fails here
declare -A known_failure=(
    [TestSCJSingleRawMemory_MemoryMapped1]="maps raw device memory at a fixed address"
)

need_tools javac timeout
tc=$("$HERE/build-hvm.sh")
tests_src=$tc/src/icecaptoolstest/src
if [ ${#names[@]} -eq 0 ]; then
    for f in "$tests_src"/test/TestSCJSingle*.java; do names+=("$(basename "$f" .java)"); done
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/hvm-upstream.XXXXXX")
trap 'rm -rf "$work"' EXIT

passed=0 failed=0 known=0 runs=0
for name in "${names[@]}"; do
    mkdir -p "$work/$name/classes"
    javac_ok=1
    javac -nowarn -source 8 -target 8 -encoding ISO-8859-1 -bootclasspath "$tc/rt.jar" -cp "$tc/sdk" \
        -sourcepath "$tests_src" -d "$work/$name/classes" "$tests_src/test/$name.java" > "$work/$name/javac.log" 2>&1 \
        || javac_ok=0
    for mode in ${modes//,/ }; do
        start=$(date +%s)
        runs=$((runs + 1))
        if [ $javac_ok = 0 ]; then
            result="fail (javac)"; rc=1
        elif ! "$HERE/hvmc.sh" --toolchain "$tc" --classes "$work/$name/classes" --main "test.$name" --mode "$mode" \
                --log "$work/$name/hvmc-$mode.log" -o "$work/$name/exe-$mode" 2>/dev/null; then
            result="fail (HVM build)"; rc=1
        else
            rc=0
            timeout "$timeout_s" "$work/$name/exe-$mode" > "$work/$name/out-$mode.log" 2>&1 || rc=$?
            case $rc in 0) result=pass ;; 124) result="fail (hung, stopped after ${timeout_s}s)" ;; *) result="fail (exit $rc)" ;; esac
        fi
        note=
        why=${known_failure[$name/$mode]:-${known_failure[$name]:-}}
        if [ $rc = 0 ]; then
            passed=$((passed + 1))
        elif [ -n "$why" ]; then
            known=$((known + 1)); note="known: $why"
        else
            failed=$((failed + 1))
        fi
        printf '%-45s %-12s %-34s %4ss %s\n' "$name" "$mode" "$result" "$(( $(date +%s) - start ))" "$note"
        if [ $rc != 0 ] && [ -z "$note" ] && [ -f "$work/$name/out-$mode.log" ]; then
            tail -3 "$work/$name/out-$mode.log" | sed 's/^/    | /'
        fi
    done
done
echo "upstream SCJ tests: ${#names[@]} tests, $runs runs ($modes), $passed passed, $known known failure(s), $failed unexpected failure(s)"
[ $failed = 0 ]
