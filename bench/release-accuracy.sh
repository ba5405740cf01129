#!/usr/bin/env bash
# Release accuracy: the workload's dispatcher beside cyclictest, same machine, same policy.
#
# Both sleep to an absolute time on CLOCK_MONOTONIC and measure wake-up minus requested time
# (Java: LockSupport.parkNanos in the jmclbench dispatcher; C: clock_nanosleep TIMER_ABSTIME),
# one after the other at a 1 ms and a 50 ms period, and the script prints both distributions
# (min, p50, p99, max in microseconds) and the ratios Java / cyclictest of p99 and max.
# cyclictest holds /dev/cpu_dma_latency at 0 while it runs; the script does the same for the
# Java run so that both see the same power management.
#
# usage: bench/release-accuracy.sh [--fifo] [--loops-1ms N] [--loops-50ms N] [--spin-us N]
#                                  [--java PATH]
#   --fifo         run both under SCHED_FIFO 80 (chrt -f 80; cyclictest also gets -p 80)
#   --loops-1ms    releases at the 1 ms period (default 10000, 10 s)
#   --loops-50ms   releases at the 50 ms period (default 400, 20 s)
#   --spin-us      the dispatcher's --spin-us (default 0: park only)
#   --java         the JVM to measure (default: JAVA_HOME's, else java on PATH)
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
. "$home/bench/options.sh"

fifo=0; loops_1ms=10000; loops_50ms=400; spin_us=0
java=${JAVA_HOME:+$JAVA_HOME/bin/java}; java=${java:-java}
while [ $# -gt 0 ]; do
    case "$1" in
        --fifo) fifo=1; shift ;;
        --loops-1ms) loops_1ms=$(value_of "$@"); shift 2 ;;
        --loops-50ms) loops_50ms=$(value_of "$@"); shift 2 ;;
        --spin-us) spin_us=$(value_of "$@"); shift 2 ;;
        --java) java=$(value_of "$@"); shift 2 ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
done
require_positive --loops-1ms "$loops_1ms"; require_positive --loops-50ms "$loops_50ms"; require_count --spin-us "$spin_us"
command -v cyclictest >/dev/null || { echo "release-accuracy: cyclictest not found (apt-get install rt-tests)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "release-accuracy: python3 is needed to read cyclictest's JSON" >&2; exit 1; }

jar=$home/workload/target/jmclbench-workload.jar
"$home/jmclbench" build
[ -f "$jar" ] || { echo "release-accuracy: $jar missing after the build" >&2; exit 1; }

prefix=(); ct_prio=()
policy=SCHED_OTHER
if [ "$fifo" = 1 ]; then prefix=(chrt -f 80); ct_prio=(-p 80); policy="SCHED_FIFO 80"; fi

tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# Java side, holding /dev/cpu_dma_latency at 0 like cyclictest does (when we may).
java_run() { # period_us loops
    (
        if [ -w /dev/cpu_dma_latency ]; then exec 3>/dev/cpu_dma_latency; printf '\0\0\0\0' >&3; fi
        "${prefix[@]}" "$java" -cp "$jar" org.jmclbench.workload.release.ReleaseAccuracyMain \
            --period-us "$1" --loops "$2" --spin-us "$spin_us"
    )
}

# cyclictest's histogram (1 us buckets up to hmax, overflows counted apart) to the same line.
cyclictest_run() { # period_us loops
    local hmax=$(( $1 * 20 < 100000 ? 100000 : $1 * 20 ))
    "${prefix[@]}" cyclictest -m -i "$1" -l "$2" -h "$hmax" -q "${ct_prio[@]}" --json="$tmp/ct.json" >/dev/null
    python3 - "$tmp/ct.json" <<'PY'
import json, math, sys
t = json.load(open(sys.argv[1]))["thread"]["0"]
hist = sorted((int(k), v) for k, v in t["histogram"].items())
n = t["cycles"]
def q(p):
    rank = max(1, math.ceil(p * n)); seen = 0
    for us, c in hist:
        seen += c
        if seen >= rank:
            return float(us)
    return float(t["max"])  # the rank falls among the overflows: report the maximum
print("cyclictest count=%d min=%.1f p50=%.1f p90=%.1f p99=%.1f p999=%.1f max=%.1f"
      % (n, t["min"], q(0.5), q(0.9), q(0.99), q(0.999), t["max"]))
PY
}

echo "# release accuracy on $(uname -n), $(uname -r), policy $policy, $("$java" -version 2>&1 | head -1)"
echo "# values in us: lateness = wake-up minus requested absolute release time"
printf '%-8s %-11s %8s %9s %9s %9s %9s\n' period tool count min p50 p99 max
for period in 1000 50000; do
    loops=$loops_1ms; [ "$period" = 50000 ] && loops=$loops_50ms
    j=$(java_run "$period" "$loops" | grep '^dispatcher')
    c=$(cyclictest_run "$period" "$loops")
    python3 - "$period" "$j" "$c" <<'PY'
import sys
period = int(sys.argv[1])
def parse(line):
    name, *kv = line.split()
    return name, dict((k, float(v)) for k, v in (x.split("=") for x in kv))
(jn, j), (cn, c) = parse(sys.argv[2]), parse(sys.argv[3])
label = "%dms" % (period // 1000)
for name, d in (("java", j), ("cyclictest", c)):
    print("%-8s %-11s %8d %9.1f %9.1f %9.1f %9.1f" % (label, name, d["count"], d["min"], d["p50"], d["p99"], d["max"]))
ratio = lambda a, b: ("%.2f" % (a / b)) if b > 0 else "n/a"
print("%-8s ratio java/cyclictest: p99 %s, max %s" % (label, ratio(j["p99"], c["p99"]), ratio(j["max"], c["max"])))
PY
done
