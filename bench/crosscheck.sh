#!/usr/bin/env bash
# Randomized differential check of whole ideal runs, long (conformance/README.md): Java in every
# memory style against the C baseline in each of its own, random filter options, many cases.
# Runs workload's RandomizedCrossCheckTest with more cases than CI's six. With --generate N it
# first writes N datasets with `jmclbench generate` (random scenario, seed, 1-6 s (kidnap 30-32 s), noise or
# --no-noise) and the cases take them in turn instead of the test's synthetic circle. Prints
# the counts and every disagreement; exits 1 when there is one.
#
# usage: bench/crosscheck.sh [--cases N] [--first K] [--generate N] [--work DIR]
#   bench/crosscheck.sh --cases 400                  cases 1..400 on synthetic datasets
#   bench/crosscheck.sh --cases 200 --generate 40    on 40 generated datasets
set -euo pipefail
home=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
. "$home/bench/options.sh"

cases=100
first=1
generate=0
work=$home/results/crosscheck
while [ $# -gt 0 ]; do
    case "$1" in
        --cases) cases=$(value_of "$@"); require_positive --cases "$cases"; shift 2 ;;
        --first) first=$(value_of "$@"); require_count --first "$first"; shift 2 ;;
        --generate) generate=$(value_of "$@"); require_count --generate "$generate"; shift 2 ;;
        --work) work=$(value_of "$@"); require_creatable --work "$work"; work=$(readlink -m "$work"); shift 2 ;;
        -h|--help) usage ;;
        *) echo "$me: $1: unknown option (see --help)" >&2; exit 2 ;;
    esac
done

datasets=()
if [ "$generate" -gt 0 ]; then
    rm -rf "$work/datasets"
    mkdir -p "$work/datasets"
    # built once here: the launcher rebuilds on every call in a git worktree
    "$home/jmclbench" build
    java17=/usr/lib/jvm/java-17-openjdk-amd64/bin/java
    [ -x "$java17" ] || java17=java
    scenarios=(match match-short match-quick stay figure8 kidnap)
    RANDOM=$first # the same datasets for the same --first
    for ((i = 0; i < generate; i++)); do
        s=${scenarios[RANDOM % ${#scenarios[@]}]}
        # 1 to 6 s in steps of 0.05 s; a kidnap needs its 30 s mark to show
        periods=$((20 + RANDOM % 101))
        [ "$s" = kidnap ] && periods=$((600 + RANDOM % 41))
        duration=$(printf '%d.%02d' $((periods / 20)) $((periods % 20 * 5)))
        noise=()
        [ $((RANDOM % 4)) = 0 ] && noise=(--no-noise)
        name=$(printf '%03d-%s' "$i" "$s")
        # a short one may hold no laser event: the generator refuses it (exit 2), take the next
        if ! "$java17" -jar "$home/tooling/target/jmclbench-tooling.jar" generate --scenario "$s" \
                --seed $((RANDOM * 32768 + RANDOM)) --duration "$duration" "${noise[@]}" \
                --out "$work/datasets/$name" >/dev/null; then
            echo "$me: $name: not generated, skipped" >&2
        fi
    done
    datasets=(-Djmclbench.crosscheck.datasets="$work/datasets")
fi

mkdir -p "$work"
log=$work/crosscheck.log
set +e
(cd "$home" && mvn -q -B -pl workload -am test -Dtest=RandomizedCrossCheckTest -Dsurefire.failIfNoSpecifiedTests=false \
    -Djmclbench.crosscheck.cases="$cases" -Djmclbench.crosscheck.first="$first" "${datasets[@]}" >"$log" 2>&1)
status=$?
set -e
grep '^crosscheck:' "$log" || { tail -n 40 "$log"; exit 1; }
[ "$status" = 0 ] || { echo "$me: disagreements or a failed run; the log: $log" >&2; exit 1; }
