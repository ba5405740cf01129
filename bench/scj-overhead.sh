#!/usr/bin/env bash
# SCJ overhead: the same JVM, dataset and particles through the Java SE engine and the SCJ
# mission (on rtsj-compat), one after the other, and the ratios SCJ / Java SE of
#   - release jitter p99 (job start minus scheduled release, all jobs)
#   - mean task latency (job end minus job start)
# (goal: <= 1.2x), the bytes each SCJ release allocated in its private memory (goal: 0 in the
# preallocated style), and every memory area's size and peak for both SCJ memory styles.
#
# With --repeat N the three runs are repeated N times, interleaved (javase, scj preallocated,
# scj scoped, then again), so that drift of a shared machine does not favour one engine; every
# figure is then the median over the repetitions.
#
# usage: bench/scj-overhead.sh [--particles N] [--dataset DIR] [--policy P] [--repeat N] [--java PATH] [--out DIR]
#   --particles  particle count (default 1000)
#   --repeat     interleaved repetitions (default 3)
#   --dataset    dataset folder (default data/match-short)
#   --policy     skip|terminate|queue (default queue: every job runs, so both engines do the same work)
#   --java       the JVM to measure (default: JAVA_HOME's, else java on PATH)
#   --out        where the run folders go (default: a temporary folder, removed at the end)
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
. "$home/bench/options.sh"

particles=1000; dataset=$home/data/match-short; policy=queue; out=; repeat=3
java=${JAVA_HOME:+$JAVA_HOME/bin/java}; java=${java:-java}
while [ $# -gt 0 ]; do
    case "$1" in
        --particles) particles=$(value_of "$@"); shift 2 ;;
        --dataset) dataset=$(value_of "$@"); shift 2 ;;
        --policy) policy=$(value_of "$@"); shift 2 ;;
        --repeat) repeat=$(value_of "$@"); shift 2 ;;
        --java) java=$(value_of "$@"); shift 2 ;;
        --out) out=$(value_of "$@"); shift 2 ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
done
require_positive --particles "$particles"
require_choice --policy "$policy" "$POLICY_CHOICES" ,
require_positive --repeat "$repeat"
[ -d "$dataset" ] || { echo "scj-overhead: --dataset: $dataset: no such folder" >&2; exit 2; }
[ -z "$out" ] || require_creatable --out "$out"
command -v python3 >/dev/null || { echo "scj-overhead: python3 is needed to read summary.json" >&2; exit 1; }

"$home/jmclbench" build
if [ -z "$out" ]; then out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; fi

run() { # engine memory n -> prints the run folder
    JMCLBENCH_JAVA=$java "$home/jmclbench" run --engine "$1" --memory "$2" -p "$particles" --policy "$policy" \
        --dataset "$dataset" -O "$out" -j "bench-$1-$2" -n "$3" --force
}
se=(); pre=(); scoped=()
for n in $(seq 1 "$repeat"); do
    se+=("$(run javase preallocated "$n")")
    pre+=("$(run scj preallocated "$n")")
    scoped+=("$(run scj scoped "$n")")
done

python3 - "$particles" "$policy" "$java" "$repeat" "${se[@]}" "${pre[@]}" "${scoped[@]}" <<'PY'
import json, statistics, sys
particles, policy, java, repeat = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
dirs = sys.argv[5:]
runs = [[json.load(open(d + "/summary.json")) for d in dirs[i * repeat:(i + 1) * repeat]] for i in range(3)]

def med(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None

def merge(rs):
    """One summary-like dict whose numbers are the medians over the repetitions."""
    m = {"tasks": {"all": {}}, "missCount": med([r["missCount"] for r in rs]),
         "deviation": {"xy": {"mean": med([r["deviation"]["xy"]["mean"] for r in rs])}},
         "parameters": rs[0]["parameters"], "environment": rs[0]["environment"], "memory": {"areas": []}}
    for key in ("releaseJitterNs", "taskLatencyNs"):
        m["tasks"]["all"][key] = {s: med([r["tasks"]["all"][key][s] for r in rs]) for s in ("mean", "p99")}
    for i, a in enumerate(rs[0]["memory"]["areas"]):
        m["memory"]["areas"].append({"name": a["name"], "size": a["size"],
                                     "peakBytes": max(r["memory"]["areas"][i]["peakBytes"] for r in rs),
                                     "bytesPerRelease": a["bytesPerRelease"] if a["bytesPerRelease"] is None else
                                     max(r["memory"]["areas"][i]["bytesPerRelease"] for r in rs)})
    return m
se, pre, scoped = (merge(rs) for rs in runs)
def task(s, key, stat):
    return s["tasks"]["all"][key][stat]
def ratio(a, b):
    return float("nan") if not b else a / b
print(f"jmclbench scj-overhead: medians of {repeat} interleaved runs; {particles} particles, policy {policy}, dataset {se['parameters']['dataset']['name']}, "
      f"JVM {se['environment'].get('runtime', {}).get('version', java) if isinstance(se['environment'].get('runtime'), dict) else java}")
print(f"{'':28}{'javase':>14}{'scj prealloc':>14}{'scj scoped':>14}{'ratio(pre)':>12}{'ratio(scoped)':>14}")
for label, key, stat in [("release jitter p99 (us)", "releaseJitterNs", "p99"),
                         ("release jitter mean (us)", "releaseJitterNs", "mean"),
                         ("task latency mean (us)", "taskLatencyNs", "mean"),
                         ("task latency p99 (us)", "taskLatencyNs", "p99")]:
    a, b, c = (task(s, key, stat) / 1e3 for s in (se, pre, scoped))
    print(f"{label:28}{a:14.1f}{b:14.1f}{c:14.1f}{ratio(b, a):12.2f}{ratio(c, a):14.2f}")
print(f"{'misses':28}{se['missCount']:14.0f}{pre['missCount']:14.0f}{scoped['missCount']:14.0f}")
print(f"{'deviation xy mean (m)':28}{se['deviation']['xy']['mean']:14.4f}{pre['deviation']['xy']['mean']:14.4f}{scoped['deviation']['xy']['mean']:14.4f}")
goal = "met" if ratio(task(pre, 'releaseJitterNs', 'p99'), task(se, 'releaseJitterNs', 'p99')) <= 1.2 and \
    ratio(task(pre, 'taskLatencyNs', 'mean'), task(se, 'taskLatencyNs', 'mean')) <= 1.2 else "NOT met"
print(f"goal <= 1.2x (preallocated): {goal}")
for name, s in (("javase", se), ("scj preallocated", pre), ("scj scoped", scoped)):
    print(f"memory areas, {name} (peak and bytes/release: the largest of the runs):")
    for a in s["memory"]["areas"]:
        per = "-" if a["bytesPerRelease"] is None else str(a["bytesPerRelease"])
        print(f"  {a['name']:12} size {a['size']:>12}  peak {a['peakBytes']:>12}  bytes/release {per:>8}")
PY
