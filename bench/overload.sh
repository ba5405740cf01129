#!/usr/bin/env bash
# Overload sweep: at which particle count does this machine start missing deadlines?
#
# Runs the workload (real time, one fresh JVM per run) for each particle count and policy and
# prints one line per run from its summary.json: misses, late/skipped/terminated jobs, and
# the job latency, response time and CPU time per task.
#
# usage: bench/overload.sh [--particles "400 1000 ..."] [--policies "skip queue"]
#                          [--dataset DIR] [--warmup S] [--out DIR] [--fifo] [-- extra run options]
#   --fifo   run the workload under SCHED_FIFO 80 (chrt -f 80): the machine's capacity rather
#            than its share of a machine that other processes also load
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
. "$home/bench/options.sh"
particles="400 1000 2000 5000 10000 20000 50000"
policies="skip"
warmup=2
dataset=
out=
prefix=()
while [ $# -gt 0 ]; do
    case "$1" in
        --particles) particles=$(value_of "$@"); shift 2 ;;
        --policies) policies=$(value_of "$@"); shift 2 ;;
        --dataset) dataset=$(value_of "$@"); shift 2 ;;
        --warmup) warmup=$(value_of "$@"); shift 2 ;;
        --out) out=$(value_of "$@"); shift 2 ;;
        --fifo) prefix=(chrt -f 80); shift ;;
        --) shift; break ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
done
extra=("$@")
# checked now: the first run would refuse them only after the build and the table's header
require_counts --particles "$particles" " "
require_choice --policies "$policies" "$POLICY_CHOICES" " "
require_number --warmup "$warmup"
[ -z "$dataset" ] || [ -d "$dataset" ] || { echo "overload: --dataset: $dataset: no such folder" >&2; exit 2; }
[ -z "$out" ] || require_creatable --out "$out"
[ -n "$out" ] || { out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; }
ds=(); [ -n "$dataset" ] && ds=(--dataset "$dataset")

printf '%-9s %-6s %5s %5s %5s %5s %5s | %9s %9s | %9s %9s | %9s %9s | %9s\n' \
    policy N jobs miss late skip term "lat.p50" "lat.p99" "cpuP.p50" "cpuU.p50" "resp.p99" "resp.max" "disp.p99"
echo "# times in ms; lat = job end - start, resp = end - scheduled release, cpuP/cpuU = CPU per predict/update job, disp = dispatcher lateness"
for policy in $policies; do
    for n in $particles; do
        "$home/jmclbench" build
        "${prefix[@]}" "$home/jmclbench" run -p "$n" -n 1 -j sweep -O "$out" --policy "$policy" --warmup "$warmup" --force \
            "${ds[@]}" "${extra[@]}" >/dev/null
        summary=$(find "$out/sweep" -path "*/$n/*/1/summary.json" -newer "$0" | head -1)
        python3 - "$summary" "$policy" "$n" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
a, p, u = d["tasks"]["all"], d["tasks"]["predict"], d["tasks"]["update"]
ms = lambda s, q: float("nan") if s[q] is None else s[q] / 1e6
print("%-9s %-6s %5d %5d %5d %5d %5d | %9.3f %9.3f | %9.3f %9.3f | %9.3f %9.3f | %9.3f" % (
    sys.argv[2], sys.argv[3], a["released"], d["missCount"], a["late"], a["skipped"], a["terminated"],
    ms(a["taskLatencyNs"], "p50"), ms(a["taskLatencyNs"], "p99"), ms(p["cpuNs"], "p50"), ms(u["cpuNs"], "p50"),
    ms(a["responseTimeNs"], "p99"), ms(a["responseTimeNs"], "max"), ms(d["dispatcherLatenessNs"], "p99")))
PY
        rm -rf "$out/sweep"
    done
done
