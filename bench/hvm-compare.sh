#!/usr/bin/env bash
# The SCJ mission on the icecap HVM against HotSpot (the same mission on rtsj-compat, and the
# Java SE engine) and the native C baseline: one run each at each particle count, same data and
# policy, all under SCHED_OTHER. Prints release jitter (mean, p99), task latency per particle
# (mean; p50 and min, which the machine's other work disturbs least) and misses per runtime.
# The HVM runs in each mode of --hvm-modes (JMCLBENCH_HVM_MODE: compiled, interpreted, hot; runtime
# names hvm-compiled, ...); --only-hvm skips HotSpot and C.
#
#   bench/hvm-compare.sh [--particles 100,400,1600] [--policy skip] [--dataset match-short] [-O DIR]
#                        [--hvm-modes compiled,interpreted,hot] [--only-hvm]
#
# Needs HVM_SRC (docs/HVM.md). A benchmark, not a test: figures depend on the machine and its load.
set -euo pipefail

ROOT=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
. "$ROOT/bench/options.sh"
particles=100,400,1600
policy=skip
dataset=match-short
out=
hvm_modes=compiled,interpreted,hot
only_hvm=0
while [ $# -gt 0 ]; do
    case "$1" in
        --hvm-modes) hvm_modes=$(value_of "$@"); shift 2 ;;
        --only-hvm) only_hvm=1; shift ;;
        --particles) particles=$(value_of "$@"); shift 2 ;;
        --policy) policy=$(value_of "$@"); shift 2 ;;
        --dataset) dataset=$(value_of "$@"); shift 2 ;;
        -O) out=$(value_of "$@"); shift 2 ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
done
# checked now: each run would refuse them only after a build, and the loop goes on past a failed run
require_counts --particles "$particles" ,
require_choice --policy "$policy" "$POLICY_CHOICES" ,
require_choice --hvm-modes "$hvm_modes" "compiled|interpreted|hot" ,
[ -d "$ROOT/data/$dataset" ] || { echo "hvm-compare: --dataset: $dataset: no such dataset under $ROOT/data" >&2; exit 2; }
[ -z "$out" ] || require_creatable -O "$out"
[ -n "$out" ] || out=$(mktemp -d "${TMPDIR:-/tmp}/hvm-compare.XXXXXX")
j=$ROOT/jmclbench
common=(--policy "$policy" --dataset "$ROOT/data/$dataset" -O "$out")

IFS=, read -ra counts <<< "$particles"
IFS=, read -ra modes <<< "$hvm_modes"
for p in "${counts[@]}"; do
    echo "hvm-compare: $p particles" >&2
    if [ $only_hvm = 0 ]; then
        "$j" run -p "$p" -j hotspot-javase "${common[@]}" > /dev/null || echo "hvm-compare: hotspot-javase $p failed" >&2
        "$j" run --engine scj -p "$p" -j hotspot-scj "${common[@]}" > /dev/null || echo "hvm-compare: hotspot-scj $p failed" >&2
        # --no-fifo: C under the scheduling of the others (it raises itself to SCHED_FIFO 80 when it may,
        # which on a loaded machine spares it the preemptions the HVM and HotSpot runs suffer)
        "$j" run-native -p "$p" -j c --no-fifo "${common[@]}" > /dev/null || echo "hvm-compare: c $p failed" >&2
    fi
    for m in "${modes[@]}"; do
        JMCLBENCH_HVM_MODE=$m "$j" run-hvm -p "$p" -j "hvm-$m" "${common[@]}" > /dev/null || echo "hvm-compare: hvm-$m $p failed" >&2
    done
done

python3 - "$out" "$particles" "$hvm_modes" <<'EOF'
import glob, json, os, sys
out, counts = sys.argv[1], sys.argv[2].split(',')
hvms = tuple('hvm-' + m for m in sys.argv[3].split(','))
print(f"{'runtime':16} {'particles':>9} {'jitter mean us':>15} {'jitter p99 us':>14} {'latency/particle us':>20} "
      f"{'p50':>7} {'min':>7} {'misses':>7} {'events':>7}")
for p in counts:
    for rt in hvms + ('hotspot-scj', 'hotspot-javase', 'c'):
        found = glob.glob(os.path.join(out, rt, '*', p, '*', '1', 'summary.json'))
        if not found:
            print(f"{rt:16} {p:>9} {'(failed)':>15}")
            continue
        a = json.load(open(found[0]))['tasks']['all']
        j, l = a['releaseJitterNs'], a['taskLatencyNs']
        print(f"{rt:16} {p:>9} {j['mean'] / 1e3:15.1f} {j['p99'] / 1e3:14.1f} {l['mean'] / 1e3 / int(p):20.3f} "
              f"{l['p50'] / 1e3 / int(p):7.3f} {l['min'] / 1e3 / int(p):7.3f} {a['missCount']:7d} {a['released']:7d}")
print(f"(run folders in {out})")
EOF
