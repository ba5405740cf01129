#!/usr/bin/env bash
# Differential tester of the icecap HVM (issue 18): generated programs of int, long and double
# arithmetic, conversions, comparisons, shifts, arrays and calls between compiled and interpreted
# methods (hvm/difftest/gen.py), run on HotSpot, the HVM interpreter and the HVM compiled (icecap
# -aot), every value compared bit for bit with HotSpot's (NaNs equal). A few seeds are CI; many
# seeds are a benchmark run.
#
#   hvm/difftest.sh [--seeds 1-5|1,7,9] [--count 100] [--modes interpreted,compiled] [--keep DIR]
#                   [--toolchain DIR]
#
# --count: values (methods) per program. --keep DIR: copy each program that disagreed there
# (with the indices) to keep as a regression program. --toolchain: another tool chain than
# build-hvm.sh's (e.g. one built without some patches).
# Needs what build-hvm.sh needs (HVM_SRC, ...).
# Exit codes: 0 every value agreed; 1 a value disagreed or a program did not build or run, or the
# tool chain failed to build; 2 bad usage (an option, a bad HVM_SRC).
set -euo pipefail

HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
TIMEOUT=60
seeds=1-3
count=100
modes=interpreted,compiled
keep=
tc=
. "$HERE/script-options.sh"
while [ $# -gt 0 ]; do
    case "$1" in
        --toolchain|--seeds|--count|--modes|--keep) [ $# -ge 2 ] || bad "$1: needs a value" ;;
    esac
    case "$1" in
        --toolchain) [ -f "$2/KEY" ] || bad "--toolchain: $2 is not a tool chain built by build-hvm.sh"
                     tc=$(readlink -f "$2"); shift 2 ;;
        --seeds) seeds=$2; shift 2 ;;
        --count) count=$2; shift 2 ;;
        --modes) modes=$2; shift 2 ;;
        --keep) writable_folder --keep "$2"; keep=$(realpath -m "$2"); shift 2 ;;
        -h|--help) header_help; exit 0 ;;
        *) bad "unknown option: $1" ;;
    esac
done
# Every value is checked before anything is built: a bad one ran nothing, or compared no value, and passed.
if [[ $seeds =~ ^([0-9]{1,9})-([0-9]{1,9})$ ]]; then
    [ $((10#${BASH_REMATCH[1]})) -le $((10#${BASH_REMATCH[2]})) ] || bad "--seeds: $seeds is an empty range"
    seed_list=$(seq "$((10#${BASH_REMATCH[1]}))" "$((10#${BASH_REMATCH[2]}))")
elif [[ $seeds =~ ^[0-9]{1,9}(,[0-9]{1,9})*$ ]]; then
    seed_list=
    for s in ${seeds//,/ }; do seed_list+="$((10#$s)) "; done
else
    bad "--seeds: '$seeds' is not a range (1-5) or a list (1,7,9) of seeds"
fi
[[ $count =~ ^[1-9][0-9]{0,8}$ ]] || bad "--count: '$count' is not a positive number of values"
[[ $modes =~ ^(interpreted|compiled)(,(interpreted|compiled))*$ ]] \
    || bad "--modes: '$modes' is not a list of interpreted and compiled"
need_tools python3 java javac timeout

[ -n "$tc" ] || tc=$("$HERE/build-hvm.sh")
work=$(mktemp -d "${TMPDIR:-/tmp}/hvm-difftest.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/runner"
cat > "$work/runner/Runner.java" <<'JAVA'
public class Runner {
    public static void main(String[] a) throws Exception {
        Class<?> c = Class.forName(a[0]);
        int n = Integer.parseInt(a[1]);
        StringBuilder b = new StringBuilder();
        for (int k = 0; k < n; k++) {
            java.lang.reflect.Method m = c.getDeclaredMethod("v" + k);
            m.setAccessible(true);
            b.append((long) (Long) m.invoke(null)).append('\n');
        }
        System.out.print(b);
    }
}
JAVA
javac -d "$work/runner" "$work/runner/Runner.java"
jc() {
    if ! javac -nowarn -source 8 -target 8 -bootclasspath "$tc/rt.jar" -cp "$tc/sdk" -d "$1" "$2" > "$1.log" 2>&1; then
        grep -v '^warning\|^Note' "$1.log" >&2
        # a bug of gen.py or a broken tool chain, not the user's input
        echo "difftest: the generated program $2 does not compile against $tc (gen.py's bug, or the tool chain's)" >&2
        exit 1
    fi
}

values=0 disagreements=0
for seed in $seed_list; do
    d=$work/$seed
    mkdir -p "$d/src/difftest" "$d/hs" "$d/hvm"
    src=$d/src/difftest/G$seed.java
    python3 "$HERE/difftest/gen.py" "$seed" "$count" "$src"
    jc "$d/hs" "$src"
    timeout "$TIMEOUT" java -cp "$d/hs:$work/runner" Runner "difftest.G$seed" "$count" > "$d/expected.txt"
    python3 "$HERE/difftest/gen.py" "$seed" "$count" "$src" "$d/expected.txt"
    jc "$d/hvm" "$src"
    for mode in ${modes//,/ }; do
        exe=$d/G$seed-$mode
        if ! "$HERE/hvmc.sh" --toolchain "$tc" --classes "$d/hvm" --main "difftest.G$seed" --mode "$mode" \
                --heap 4000000 --log "$exe.log" -o "$exe" 2>/dev/null; then
            echo "difftest: seed $seed $mode: does not build ($(grep -m1 'Exception in\|unsupported\|error' "$exe.log" | cut -c1-120))"
            disagreements=$((disagreements + 1))
            continue
        fi
        rc=0
        timeout "$TIMEOUT" "$exe" > "$exe.out" 2>&1 || rc=$?
        values=$((values + count))
        if [ $rc = 0 ] && [ ! -s "$exe.out" ]; then
            echo "difftest: seed $seed $mode: $count values agree"
        else
            bad=$(tr '\n' ' ' < "$exe.out" | cut -c1-200)
            echo "difftest: seed $seed $mode: DISAGREES (exit $rc; values $bad)"
            disagreements=$((disagreements + 1))
            if [ -n "$keep" ]; then
                mkdir -p "$keep"
                cp "$src" "$keep/G$seed.java"
                echo "$mode: exit $rc; values $bad" >> "$keep/G$seed.txt"
            fi
        fi
    done
done
echo "difftest: $values values compared, $disagreements program run(s) disagreeing"
[ $disagreements = 0 ]
