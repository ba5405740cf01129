#!/usr/bin/env bash
# ATC delivery latency: how long rtsj-compat's asynchronous transfer of control takes to stop a
# computation (AIE fired to interruptAction), beside a volatile flag polled at the same points (the
# javase and scj engines' cooperative abort), apart from any job (AtcDeliveryLatency).
#
# usage: bench/atc-latency.sh [--fifo] [--aborts N] [--warmup N] [--work N] [--java PATH] [--no-build]
#   --fifo      run under SCHED_FIFO 80 (chrt -f 80)
#   --aborts    aborts measured per mode (default 2000)
#   --warmup    unrecorded aborts before them (default 200; 0 measures a run's first aborts)
#   --work      arithmetic steps between two delivery points (default 200, about 0.3 us)
#   --java      the JVM to measure (default: JAVA_HOME's, else java on PATH)
#   --no-build  use bench/target/benchmarks.jar as it is
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
. "$home/bench/options.sh"

fifo=0; aborts=2000; warmup=200; work=200; build=1
java=${JAVA_HOME:+$JAVA_HOME/bin/java}; java=${java:-java}
while [ $# -gt 0 ]; do
    case "$1" in
        --fifo) fifo=1; shift ;;
        --aborts) aborts=$(value_of "$@"); shift 2 ;;
        --warmup) warmup=$(value_of "$@"); shift 2 ;;
        --work) work=$(value_of "$@"); shift 2 ;;
        --java) java=$(value_of "$@"); shift 2 ;;
        --no-build) build=0; shift ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
done
require_positive --aborts "$aborts"; require_count --warmup "$warmup"; require_count --work "$work"
require_java "$java"
if [ $build = 1 ]; then
    build_benchmarks
fi
prefix=()
if [ $fifo = 1 ]; then
    command -v chrt >/dev/null || { echo "atc-latency: --fifo: chrt not found" >&2; exit 2; }
    prefix=(chrt -f 80)
fi
echo "# $("$java" -XshowSettings:properties -version 2>&1 | sed -n 's/^ *java.vm.version = //p'), $([ $fifo = 1 ] && echo 'SCHED_FIFO 80' || echo 'default scheduler'), load $(cut -d' ' -f1-3 /proc/loadavg)"
for mode in flag atc; do
    "${prefix[@]}" "$java" -cp "$home/bench/target/benchmarks.jar" org.jmclbench.bench.AtcDeliveryLatency "$mode" "$aborts" "$warmup" "$work"
done
