#!/usr/bin/env bash
# The Java/C kernel comparison of SPEC section 11, run once: JMH (bench/, with -prof gc) and
# the C timing loop (native/bench/kernel_jobs.c) on the same dataset, particle counts and
# jobs, then one table: ns per job in Java and C, the Java/C ratio and the bytes Java
# allocates per job, for both memory styles. A benchmark, not a test: numbers depend on the
# machine and on what else it runs; the raw outputs are kept beside the table.
#
# usage: bench/kernel-ratio.sh [--java PATH] [--dataset DIR] [--particles N,N] [--out DIR]
#                              [--no-build] [-- JMH options]
# The JMH options default to a short run: -f 1 -wi 3 -i 5 -w 1s -r 1s; the C loop takes the
# same warm-up count, iteration count and iteration time from them.
set -euo pipefail
home=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)

java=${JAVA_HOME:+$JAVA_HOME/bin/java}
java=${java:-java}
dataset=$home/datasets/match-short
particles=1000,4000
out=$home/results/kernel-ratio/$(date -u +%Y%m%dT%H%M%SZ)
build=1
jmh_opts=(-f 1 -wi 3 -i 5 -w 1s -r 1s)
while [ $# -gt 0 ]; do
    case "$1" in
        --java) java=$2; shift 2 ;;
        --dataset) dataset=$(readlink -f "$2"); shift 2 ;;
        --particles) particles=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --no-build) build=0; shift ;;
        --) shift; jmh_opts=("$@"); break ;;
        -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "kernel-ratio: $1: unknown option (see --help)" >&2; exit 2 ;;
    esac
done
[ -f "$dataset/odometry.txt" ] || { echo "kernel-ratio: --dataset: $dataset: not a dataset folder" >&2; exit 2; }
command -v "$java" >/dev/null || { echo "kernel-ratio: --java: $java: not found" >&2; exit 2; }

if [ $build = 1 ]; then
    echo "kernel-ratio: building the benchmarks..." >&2
    (cd "$home" && mvn -q -B -ntp -pl bench -am package -DskipTests >&2)
    make -s -C "$home/native" build/kernel-jobs >&2
fi
mkdir -p "$out"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

# The C loop takes the iteration shape from the JMH options (-wi, -i, -r in seconds).
c_warmup=3 c_iterations=5 c_time=1
for ((k = 0; k < ${#jmh_opts[@]} - 1; k++)); do
    v=${jmh_opts[k+1]}
    case "${jmh_opts[k]}" in
        -wi) c_warmup=$v ;;
        -i) c_iterations=$v ;;
        -r) case "$v" in *ms) c_time=$(awk "BEGIN{print ${v%ms}/1000}") ;; *s) c_time=${v%s} ;; *) c_time=$v ;; esac ;;
    esac
done

# The same counts and iteration shape for both; C runs after Java so neither warms the other.
echo "kernel-ratio: JMH ($java)..." >&2
"$java" -jar "$home/bench/target/benchmarks.jar" KernelBenchmark "${jmh_opts[@]}" -prof gc \
    -p "particles=$particles" -p "dataset=$dataset" -rf json -rff "$out/jmh.json" >"$out/jmh.txt" 2>&1 \
    || { tail -20 "$out/jmh.txt" >&2; echo "kernel-ratio: JMH failed (log: $out/jmh.txt)" >&2; exit 1; }
echo "kernel-ratio: exact allocation count..." >&2
"$java" -cp "$home/bench/target/benchmarks.jar" org.jmclbench.bench.AllocationCheck "$dataset" "$particles" \
    >"$out/alloc.txt"
echo "kernel-ratio: C timing loop..." >&2
"$home/native/build/kernel-jobs" --dataset "$dataset" --particles "$particles" \
    --warmup "$c_warmup" --iterations "$c_iterations" --time "$c_time" >"$out/c.txt"
"$java" -version >"$out/java-version.txt" 2>&1 || true

load_after=$(cut -d' ' -f1-3 /proc/loadavg)
python3 - "$out" "$load_before" "$load_after" "$(nproc)" <<'PY'
import json, os, sys
out, load_before, load_after, cpus = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
java = {}  # (job, n, memory) -> (ns, error, bytes per job)
for r in json.load(open(os.path.join(out, "jmh.json"))):
    job = r["benchmark"].rsplit(".", 1)[1]
    key = (job, int(r["params"]["particles"]), r["params"]["memory"])
    alloc = r.get("secondaryMetrics", {}).get("gc.alloc.rate.norm", {}).get("score")
    java[key] = (float(r["primaryMetric"]["score"]), float(r["primaryMetric"]["scoreError"]),  # "NaN" for 1 iteration
                 None if alloc is None else float(alloc))
exact = {}  # (job, n, memory) -> bytes per job counted by the thread's allocation counter
for line in open(os.path.join(out, "alloc.txt")):
    if not line.startswith("#") and line.strip():
        job, n, memory, b = line.split()
        exact[(job, int(n), memory)] = None if b == "n/a" else float(b)
c = {}  # (job, n, memory) -> (ns, min, max, cpu share)
for line in open(os.path.join(out, "c.txt")):
    if line.startswith("#") or not line.strip():
        continue
    job, n, memory, ns, lo, hi, jobs, share = line.split()
    c[(job, int(n), memory)] = (float(ns), float(lo), float(hi), float(share))

nan = float("nan")
print("%-8s %6s %-13s %20s %28s %7s %22s" % ("job", "N", "memory", "Java ns/job (+-99.9%)",
                                              "C ns/job [min..max] cpu", "Java/C", "Java B/job JMH, exact"))
rows = []
for key in sorted(java, key=lambda k: (k[0], k[1], k[2] != "preallocated")):
    j_ns, j_err, alloc = java[key]
    c_ns, c_lo, c_hi, share = c.get(key, (nan, nan, nan, nan))
    ratio = j_ns / c_ns
    ex = exact.get(key)
    print("%-8s %6d %-13s %11.0f +-%7.0f %9.0f [%6.0f..%6.0f] %4.2f %7.2f %12s %9s"
          % (key[0], key[1], key[2], j_ns, j_err, c_ns, c_lo, c_hi, share, ratio,
             "n/a" if alloc is None else "%.1f" % alloc, "n/a" if ex is None else "%.0f" % ex))
    rows.append((key, ratio, ex))
print()
print("load average before %s, after %s, on %d CPUs%s" % (load_before, load_after, cpus,
      "  (busy machine: times include preemption; rerun when idle)"
      if max(float(load_before.split()[0]), float(load_after.split()[0])) > cpus / 2 else ""))
pre = [(k, r, a) for k, r, a in rows if k[2] == "preallocated"]
worst = max(pre, key=lambda x: x[1])
print("SPEC 11, preallocated style: worst Java/C ratio %.2f (%s, %d particles): %s the 1.25 target"
      % (worst[1], worst[0][0], worst[0][1], "meets" if worst[1] <= 1.25 else "MISSES"))
# JMH's gc.alloc.rate.norm includes its own per-iteration bookkeeping (a few KB) spread over
# the iteration's jobs; the exact column counts the thread's allocations over warm jobs only.
known = [a for _, _, a in pre if a is not None]
if known:
    most = max(known)
    print("SPEC 11, preallocated style: at most %.1f B allocated per warm job (exact count): %s"
          % (most, "zero" if most == 0 else "NOT zero"))
else:
    print("SPEC 11, preallocated style: this JVM has no per-thread allocation counter; see JMH's column")
print("raw outputs: %s/{jmh.txt,jmh.json,alloc.txt,c.txt}" % out)
PY
