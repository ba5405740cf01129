#!/usr/bin/env bash
# kill -9 trials: is any run lost or doubled when the runner dies at a random point?
#
# Each trial starts a small command (native runs of match-quick at --time-scale 0.1) on a fresh
# store, sends it SIGKILL after a random delay between 0 and the length of an uninterrupted run of
# it, checks the store as the kill left it (SQLite integrity, the runs committed), then reruns the
# same command to the end and counts:
#   lost     a run committed before the kill that is gone or changed after the rerun, or a planned
#            run missing from the finished store, or an ok run whose folder has no summary.json
#   doubled  a configuration recorded twice, or a run folder without its row
#   corrupt  a store that fails PRAGMA integrity_check after the kill or after the rerun
# evaluate also needs its document after the rerun. verify (--only static,toy-: the seeded static
# checks and the toy JPF checks; JPF_CORE_SRC as for ./jmclbench verify) has no store: its results
# file must be absent or whole JSON after the kill (else corrupt) and after the rerun hold every
# check once (else lost or doubled); temporary files left by a killed writer are counted apart.
# Prints one line per trial and the totals; exit 1 when anything was lost, doubled or corrupt.
# Long (10-20 s a trial): not part of CI, whose short version is tooling's KillTrialsTest.
#
# usage: bench/kill-trials.sh [--trials N] [--command matrix|evaluate|verify] [--seed N] [--keep DIR]
#   --keep DIR   keep every trial's folder (store, logs) under DIR instead of a temporary folder
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
. "$home/bench/options.sh"
trials=100
command=matrix
seed=$RANDOM
keep=
while [ $# -gt 0 ]; do
    case "$1" in
        --trials) trials=$(value_of "$@"); shift 2 ;;
        --command) command=$(value_of "$@"); shift 2 ;;
        --seed) seed=$(value_of "$@"); shift 2 ;;
        --keep) keep=$(value_of "$@"); shift 2 ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
done
require_positive --trials "$trials"; require_count --seed "$seed"
[ -z "$keep" ] || require_creatable --keep "$keep"
case "$command" in matrix|evaluate|verify) ;; *) echo "kill-trials: --command: matrix, evaluate or verify, not $command" >&2; exit 2 ;; esac
command -v sqlite3 >/dev/null || { echo "kill-trials: needs the sqlite3 command (apt-get install sqlite3)" >&2; exit 2; }
if [ -n "$keep" ]; then
    work=$keep; mkdir -p "$work"
else
    work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fi
RANDOM=$seed
"$home/jmclbench" build

# the same six runs for matrix (a matrix file) and evaluate (its one section)
settings='runtimes   = native
policies   = skip, terminate
particles  = 50, 100, 200
datasets   = match-quick
time-scale = 0.1'
echo "$settings" > "$work/matrix.txt"
printf 'repeat = 1\n\n[native]\n%s\n' "$settings" > "$work/evaluation.txt"

# the command of trial folder $1, as an array in $args
command_in() {
    case "$command" in
        matrix) args=(matrix --matrix "$work/matrix.txt" --db "$1/results.db") ;;
        evaluate) args=(evaluate --matrix "$work/evaluation.txt" --db "$1/results.db" --out "$1/doc/evaluation"
                        --verification "$1/no-verification.json") ;;
        verify) args=(verify --only static,toy- --out "$1/verification.json" --logs "$1/logs") ;;
    esac
}

sql() { sqlite3 -batch -cmd '.timeout 10000' "$1" "$2"; }

# the check ids of a verification results file, one a line; fails when the file is not whole JSON
checks() { python3 -c 'import json, sys; [print(c["id"]) for c in json.load(open(sys.argv[1]))["checks"]]' "$1"; }

# the verify trial's counts after the kill ($1: trial folder): sets lost, doubled, corrupt, leftovers
verify_trial() {
    if [ -f "$1/verification.json" ] && ! checks "$1/verification.json" > /dev/null 2>&1; then corrupt=$((corrupt + 1)); fi
    committed=0
    [ -f "$1/verification.json" ] && committed=1
    leftovers=$((leftovers + $(find "$1" -maxdepth 1 -name '*.partial' | wc -l)))
    if ! "$home/jmclbench" "${args[@]}" > "$1/rerun.log" 2>&1; then
        echo "trial $i: the rerun failed (see $1/rerun.log)"; corrupt=$((corrupt + 1))
    fi
    if ! checks "$1/verification.json" > "$1/after" 2>/dev/null; then corrupt=$((corrupt + 1)); fi
    local n distinct
    n=$(wc -l < "$1/after"); distinct=$(sort -u "$1/after" | wc -l)
    [ "$distinct" -ge "$planned" ] || lost=$((lost + planned - distinct))
    doubled=$((doubled + n - distinct))
}

# every configuration once: what identifies a planned run
CONFIG="runtime || '|' || profile || '|' || engine || '|' || memory || '|' || policy || '|' || particles || '|' || dataset || '|' || load || '|' || repetition"

# the store trial's counts after the kill ($1: trial folder): sets committed, lost, doubled, corrupt
store_trial() {
    local rows configs folders dir
    if [ -f "$1/results.db" ]; then
        # the folder may hold a store the kill cut before its tables: that is an empty store, not a corrupt one
        [ "$(sql "$1/results.db" "PRAGMA integrity_check" 2>&1)" = ok ] || corrupt=$((corrupt + 1))
        sql "$1/results.db" "SELECT run_key || ' ' || started_at FROM runs" 2>/dev/null | sort > "$1/before" || : > "$1/before"
    else
        : > "$1/before"
    fi
    committed=$(wc -l < "$1/before")
    if ! "$home/jmclbench" "${args[@]}" > "$1/rerun.log" 2>&1; then
        echo "trial $i: the rerun failed (see $1/rerun.log)"; corrupt=$((corrupt + 1))
    fi
    [ "$(sql "$1/results.db" "PRAGMA integrity_check" 2>&1)" = ok ] || corrupt=$((corrupt + 1))
    sql "$1/results.db" "SELECT run_key || ' ' || started_at FROM runs" | sort > "$1/after"
    lost=$((lost + $(comm -23 "$1/before" "$1/after" | wc -l)))
    rows=$(sql "$1/results.db" "SELECT count(*) FROM runs")
    configs=$(sql "$1/results.db" "SELECT count(DISTINCT $CONFIG) FROM runs")
    [ "$configs" -ge "$planned" ] || lost=$((lost + planned - configs))
    doubled=$((doubled + rows - configs))
    folders=$(find "$1/runs" -mindepth 1 -maxdepth 1 -type d | wc -l)
    [ "$folders" -le "$rows" ] || doubled=$((doubled + folders - rows))
    while read -r dir; do
        [ -f "$1/$dir/summary.json" ] || lost=$((lost + 1))
    done < <(sql "$1/results.db" "SELECT run_dir FROM runs WHERE status = 'ok'")
    if [ "$command" = evaluate ] && ! grep -q . "$1/doc/EVALUATION.md" 2>/dev/null; then
        lost=$((lost + 1))
    fi
}

# a full run first: how many runs the command plans and how long it takes
first=$work/full
rm -rf "$first"; mkdir -p "$first"
command_in "$first"
t0=$(date +%s.%N)
"$home/jmclbench" "${args[@]}" > "$first/log" 2>&1 || { echo "kill-trials: the uninterrupted $command failed:" >&2; cat "$first/log" >&2; exit 1; }
full_s=$(echo "$(date +%s.%N) - $t0" | bc)
if [ "$command" = verify ]; then
    planned=$(checks "$first/verification.json" | wc -l)
else
    planned=$(sql "$first/results.db" "SELECT count(*) FROM runs")
fi
echo "kill-trials: $command of $planned $([ "$command" = verify ] && echo checks || echo runs) takes ${full_s} s uninterrupted; $trials trials, seed $seed"

lost_total=0 doubled_total=0 corrupt_total=0 killed_total=0 leftovers=0
for i in $(seq 1 "$trials"); do
    t=$work/t$i
    rm -rf "$t"; mkdir -p "$t"
    command_in "$t"
    delay=$(echo "scale=3; $full_s * $RANDOM / 32767" | bc)
    # verify builds first (Maven, then the JVM): its whole process group is killed, so that no orphaned
    # build races the rerun's; matrix and evaluate lose only the runner, their runs go on as orphans
    setsid "$home/jmclbench" "${args[@]}" > "$t/killed.log" 2>&1 &
    pid=$!
    sleep "$delay"
    killed=0
    target=$pid
    [ "$command" = verify ] && target=-$pid
    if kill -9 -- "$target" 2>/dev/null; then killed=1; fi
    wait "$pid" 2>/dev/null || true
    killed_total=$((killed_total + killed))
    lost=0 doubled=0 corrupt=0 committed=0
    if [ "$command" = verify ]; then
        verify_trial "$t"
    else
        store_trial "$t"
    fi
    printf 'trial %3d: kill after %6.3f s (%s), %d %s at the kill; lost %d, doubled %d, corrupt %d\n' \
        "$i" "$delay" "$([ $killed = 1 ] && echo killed || echo 'had ended')" "$committed" \
        "$([ "$command" = verify ] && echo 'results files' || echo 'runs committed')" "$lost" "$doubled" "$corrupt"
    lost_total=$((lost_total + lost)); doubled_total=$((doubled_total + doubled)); corrupt_total=$((corrupt_total + corrupt))
    [ -n "$keep" ] || rm -rf "$t"
done
echo "kill-trials: $command, $trials trials ($killed_total killed mid-way), $planned $([ "$command" = verify ] && echo checks || echo runs) each:" \
    "lost $lost_total, doubled $doubled_total, corrupt $corrupt_total$([ "$command" = verify ] && echo ", $leftovers temporary files left by killed writers")"
[ $((lost_total + doubled_total + corrupt_total)) = 0 ]
