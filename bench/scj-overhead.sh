#!/usr/bin/env bash
# SCJ overhead: the same JVM, dataset and particles through the Java SE engine and the SCJ
# mission (on rtsj-compat), one after the other, and the ratios SCJ / Java SE of
#   - release jitter p99 (job start minus scheduled release, all jobs)
#   - mean task latency (job end minus job start)
# (goal: <= 1.2x), the bytes each SCJ release allocated in its private memory (goal: 0 in the
# preallocated style), and every memory area's size and peak for both SCJ memory styles.
#
# usage: bench/scj-overhead.sh [--particles N] [--dataset DIR] [--policy P] [--java PATH] [--out DIR]
#   --particles  particle count (default 1000)
#   --dataset    dataset folder (default data/match-short)
#   --policy     skip|terminate|queue (default queue: every job runs, so both engines do the same work)
#   --java       the JVM to measure (default: JAVA_HOME's, else java on PATH)
#   --out        where the run folders go (default: a temporary folder, removed at the end)
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)

particles=1000; dataset=$home/data/match-short; policy=queue; out=
java=${JAVA_HOME:+$JAVA_HOME/bin/java}; java=${java:-java}
while [ $# -gt 0 ]; do
    case "$1" in
        --particles) particles=${2:?--particles: needs a value}; shift 2 ;;
        --dataset) dataset=${2:?--dataset: needs a folder}; shift 2 ;;
        --policy) policy=${2:?--policy: needs a value}; shift 2 ;;
        --java) java=${2:?--java: needs a path}; shift 2 ;;
        --out) out=${2:?--out: needs a folder}; shift 2 ;;
        -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "jmclbench: $1: unknown option" >&2; exit 2 ;;
    esac
done
[[ "$particles" =~ ^[0-9]+$ ]] || { echo "jmclbench: --particles: $particles: not a count" >&2; exit 2; }
[ -d "$dataset" ] || { echo "jmclbench: --dataset: $dataset: no such folder" >&2; exit 2; }
command -v python3 >/dev/null || { echo "jmclbench: python3 is needed to read summary.json" >&2; exit 1; }

"$home/jmclbench" build
if [ -z "$out" ]; then out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; fi

run() { # engine memory -> prints the run folder
    JMCLBENCH_JAVA=$java "$home/jmclbench" run --engine "$1" --memory "$2" -p "$particles" --policy "$policy" \
        --dataset "$dataset" -O "$out" -j "bench-$1-$2" --force
}
se=$(run javase preallocated)
pre=$(run scj preallocated)
scoped=$(run scj scoped)

python3 - "$se" "$pre" "$scoped" "$particles" "$policy" "$java" <<'PY'
import json, sys
se, pre, scoped = (json.load(open(d + "/summary.json")) for d in sys.argv[1:4])
particles, policy, java = sys.argv[4:7]
def task(s, key, stat):
    return s["tasks"]["all"][key][stat]
def ratio(a, b):
    return float("nan") if not b else a / b
print(f"jmclbench scj-overhead: {particles} particles, policy {policy}, dataset {se['parameters']['dataset']['name']}, "
      f"JVM {se['environment'].get('runtime', {}).get('version', java) if isinstance(se['environment'].get('runtime'), dict) else java}")
print(f"{'':28}{'javase':>14}{'scj prealloc':>14}{'scj scoped':>14}{'ratio(pre)':>12}{'ratio(scoped)':>14}")
for label, key, stat in [("release jitter p99 (us)", "releaseJitterNs", "p99"),
                         ("release jitter mean (us)", "releaseJitterNs", "mean"),
                         ("task latency mean (us)", "taskLatencyNs", "mean"),
                         ("task latency p99 (us)", "taskLatencyNs", "p99")]:
    a, b, c = (task(s, key, stat) / 1e3 for s in (se, pre, scoped))
    print(f"{label:28}{a:14.1f}{b:14.1f}{c:14.1f}{ratio(b, a):12.2f}{ratio(c, a):14.2f}")
print(f"{'misses':28}{se['missCount']:14d}{pre['missCount']:14d}{scoped['missCount']:14d}")
print(f"{'deviation xy mean (m)':28}{se['deviation']['xy']['mean']:14.4f}{pre['deviation']['xy']['mean']:14.4f}{scoped['deviation']['xy']['mean']:14.4f}")
goal = "met" if ratio(task(pre, 'releaseJitterNs', 'p99'), task(se, 'releaseJitterNs', 'p99')) <= 1.2 and \
    ratio(task(pre, 'taskLatencyNs', 'mean'), task(se, 'taskLatencyNs', 'mean')) <= 1.2 else "NOT met"
print(f"goal <= 1.2x (preallocated): {goal}")
for name, s in (("javase", se), ("scj preallocated", pre), ("scj scoped", scoped)):
    print(f"memory areas, {name}:")
    for a in s["memory"]["areas"]:
        per = "-" if a["bytesPerRelease"] is None else str(a["bytesPerRelease"])
        print(f"  {a['name']:12} size {a['size']:>12}  peak {a['peakBytes']:>12}  bytes/release {per:>8}")
PY
