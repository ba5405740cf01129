#!/usr/bin/env bash
# The cost of recording one job (SPEC section 11: "well under a microsecond"), run once: JMH
# (RecordCostBenchmark: the javase handlers' and the ideal run's JobRecorder) and the C loop
# (native/bench/record_cost.c: the C engines' record.h), with the per-job thread CPU clock (a
# run's default) and without it (--no-cpu-time), then one table: ns per job of the whole
# recording, of its share while the job holds the robot, and of one read of each clock. A
# benchmark, not a test: numbers depend on the machine and on what else it runs; the raw outputs
# are kept beside the table.
#
# usage: bench/record-cost.sh [--java PATH] [--out DIR] [--no-build] [-- JMH options]
# The JMH options default to a short run: -f 1 -wi 3 -i 5 -w 1s -r 1s; the C loop takes the
# same warm-up count, iteration count and iteration time from them.
set -euo pipefail
home=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
. "$home/bench/options.sh"

java_c_defaults record-cost
while [ $# -gt 0 ]; do
    case "$1" in
        *) java_c_option "$@"; shift "$taken" ;;
    esac
done
start_java_c_comparison build/record-cost

echo "record-cost: JMH ($java)..." >&2
"$java" -jar "$home/bench/target/benchmarks.jar" 'RecordCostBenchmark\.' "${jmh_opts[@]}" \
    -prof org.jmclbench.bench.CpuTimeProfiler -rf json -rff "$out/jmh.json" >"$out/jmh.txt" 2>&1 \
    || { tail -20 "$out/jmh.txt" >&2; echo "record-cost: JMH failed (log: $out/jmh.txt)" >&2; exit 1; }
echo "record-cost: C..." >&2
"$home/native/build/record-cost" --warmup "$c_warmup" --iterations "$c_iterations" --time "$c_time" >"$out/c.txt"
"$java" -version >"$out/java-version.txt" 2>&1 || true
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

python3 - "$out" "$load_before" "$load_after" "$(nproc)" <<'PY'
import json, os, sys
out, load_before, load_after, cpus = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
nan = float("nan")
java = {}  # (part, cpu) -> (wall ns, CPU ns) per operation
for r in json.load(open(os.path.join(out, "jmh.json"))):
    part = r["benchmark"].rsplit(".", 1)[1]
    cpu = r["params"]["cpuTime"]
    java[(part, cpu)] = (float(r["primaryMetric"]["score"]),
                         float(r.get("secondaryMetrics", {}).get("cpu.time.norm", {}).get("score", "nan")))
c = {}  # (part, cpu) -> (wall ns, CPU ns, cpu share)
for line in open(os.path.join(out, "c.txt")):
    if line.startswith("#") or not line.strip():
        continue
    part, cpu, ns, lo, hi, ops, share, cpu_ns = line.split()
    c[(part, cpu)] = (float(ns), float(cpu_ns), float(share))

rows = [("one read of the monotonic clock", ("nanoTime", "off")),
        ("one read of the thread CPU clock", ("cpuClock", "on")),
        ("recording a job, CPU time on (default)", ("record", "on")),
        ("  of which while the job holds the robot", ("held", "on")),
        ("recording a job, --no-cpu-time", ("record", "off")),
        ("  of which while the job holds the robot", ("held", "off"))]
print("ns per job (wall: JMH score, C loop mean; CPU: the measuring thread's CPU time per job)")
print("%-42s %10s %9s %9s %9s %9s" % ("", "Java wall", "Java CPU", "C wall", "C CPU", "C share"))
for label, key in rows:
    jw, jc = java.get(key, (nan, nan))
    cw, cc, share = c.get(key, (nan, nan, nan))
    print("%-42s %10.0f %9.0f %9.0f %9.0f %9.2f" % (label, jw, jc, cw, cc, share))
print()
print("load average before %s, after %s, on %d CPUs%s" % (load_before, load_after, cpus,
      "  (busy machine: wall times include preemption; the CPU columns do not)"
      if max(float(load_before.split()[0]), float(load_after.split()[0])) > cpus / 2 else ""))
def verdict(ns):
    return "well under" if ns < 500 else "under" if ns < 1000 else "OVER"
# the verdict on the CPU columns: what recording costs the thread, whatever else the machine runs
for side, table in (("Java", java), ("C", c)):
    on, off = table.get(("record", "on"), (nan, nan))[1], table.get(("record", "off"), (nan, nan))[1]
    print("SPEC 11, %-4s: recording a job costs %.0f CPU ns with the CPU clock (%s a microsecond), %.0f with "
          "--no-cpu-time (%s)" % (side, on, verdict(on), off, verdict(off)))
print("raw outputs: %s/{jmh.txt,jmh.json,c.txt}" % out)
PY
