#!/usr/bin/env bash
# Fuzzes every parser (docs/RELIABILITY.md): libFuzzer with ASan/UBSan for the C readers
# (native/fuzz/), Jazzer for the Java ones (the @FuzzTest classes, differential against the C
# reader where one exists). Each target starts from its kept inputs (seeds and every past
# finding) and seeds derived from data/, and runs for a number of executions or seconds. A
# finding (crash, hang, leak, disagreement) is written under the work folder and the script
# exits 1: keep it as a regression input (the target's kept-inputs folder, printed) and fix.
#
# usage: bench/fuzz.sh [--runs N | --seconds S] [--work DIR] [--no-build] [TARGET...]
#   TARGET: c-dataset c-options java-events java-properties java-options java-matrix java-hvm-result (all)
#   bench/fuzz.sh --seconds 5          the short run of CI (scripts/test-all.sh)
#   bench/fuzz.sh --runs 1000000       the long run whose counts docs/RELIABILITY.md gives
set -euo pipefail
home=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
. "$home/bench/options.sh"

limit=(-max_total_time=60)
work=$home/results/fuzz
build=1
targets=()
while [ $# -gt 0 ]; do
    case "$1" in
        # libFuzzer reads a malformed number as 0, and -max_total_time=0 as "no limit"
        --runs) n=$(value_of "$@"); require_count --runs "$n"; limit=(-runs="$n"); shift 2 ;;
        --seconds) n=$(value_of "$@"); require_positive --seconds "$n"; limit=(-max_total_time="$n"); shift 2 ;;
        # -m: a folder that does not exist yet (readlink -f fails, silently, below a missing parent)
        --work) work=$(value_of "$@"); require_creatable --work "$work"; work=$(readlink -m "$work"); shift 2 ;;
        --no-build) build=0; shift ;;
        -h|--help) usage ;;
        c-dataset|c-options|java-events|java-properties|java-options|java-matrix|java-hvm-result) targets+=("$1"); shift ;;
        *) echo "fuzz: $1: unknown target or option (see --help)" >&2; exit 2 ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || targets=(c-dataset c-options java-events java-properties java-options java-matrix java-hvm-result)

java17=/usr/lib/jvm/java-17-openjdk-amd64
if [ -z "${JAVA_HOME:-}" ] && [ -d "$java17" ]; then export JAVA_HOME=$java17; fi
java=${JAVA_HOME:+$JAVA_HOME/bin/java}
java=${java:-java}

if [ "$build" = 1 ]; then
    command -v clang >/dev/null || { echo "fuzz: clang is needed (apt-get install clang; scripts/install-deps.sh)" >&2; exit 1; }
    make -s -C "$home/native" fuzz build/dataset_dump >&2
    # the test classes and their class path, for Jazzer's own driver (one JVM per target)
    (cd "$home" && mvn -q -B -ntp -pl workload,hvm/launcher,tooling -am test-compile dependency:build-classpath \
        -Dmdep.outputFile=target/fuzz-classpath.txt -Dmdep.includeScope=test >&2)
fi

# Seeds from the shipped datasets: the first lines of every file, behind the byte that picks
# the kind of file (C: 0 odometry, 1 laser, 2 dataset.properties; Java: even 4, odd 2 columns).
seeds=$work/seeds
rm -rf "$seeds"
mkdir -p "$seeds/c-dataset" "$seeds/java-events" "$seeds/java-properties"
for d in "$home"/data/*/; do
    n=$(basename "$d")
    for f in odometry:0 laser:1 real:0; do
        file=${f%:*} kind=${f#*:}
        { printf "\\x0$kind"; head -n 20 "$d/$file.txt"; } > "$seeds/c-dataset/$n-$file"
        { printf "\\x0$kind"; head -n 20 "$d/$file.txt"; } > "$seeds/java-events/$n-$file"
    done
    if [ -f "$d/dataset.properties" ]; then
        { printf '\x02'; cat "$d/dataset.properties"; } > "$seeds/c-dataset/$n-properties"
        cp "$d/dataset.properties" "$seeds/java-properties/$n"
    fi
done

wres=$home/workload/src/test/resources/org/jmclbench/workload
tres=$home/tooling/src/test/resources/org/jmclbench/tooling/runner
kept_of() {
    case "$1" in
        c-dataset) echo "$home/native/fuzz/corpus/dataset" ;;
        c-options) echo "$home/native/fuzz/corpus/options" ;;
        java-events) echo "$wres/data/DatasetFuzzTestInputs/eventFiles" ;;
        java-properties) echo "$wres/data/DatasetFuzzTestInputs/properties" ;;
        java-options) echo "$wres/RunOptionsFuzzTestInputs/commandLine" ;;
        java-matrix) echo "$tres/MatrixFileFuzzTestInputs/matrixFile" ;;
        java-hvm-result) echo "$home/hvm/launcher/src/test/resources/org/jmclbench/hvm/launcher/HvmResultFileFuzzTestInputs/resultFile" ;;
    esac
}

# jazzer MODULE CLASS METHOD ARGS...: Jazzer's driver on a @FuzzTest method of MODULE's tests.
jazzer() {
    local module=$1 class=$2 method=$3
    shift 3
    local m=$home/$module
    (cd "$m" && "$java" -Xmx1g -cp "$m/target/test-classes:$m/target/classes:$(cat "$m/target/fuzz-classpath.txt")" \
        com.code_intelligence.jazzer.Jazzer --target_class="$class" --target_method="$method" \
        --instrumentation_includes='org.jmclbench.**' "$@")
}

status=0
printf '%-16s %12s %8s %9s  %s\n' target executions seconds exec/s result
for t in "${targets[@]}"; do
    kept=$(kept_of "$t")
    corpus=$work/corpus/$t
    art=$work/findings/$t/
    log=$work/$t.log
    mkdir -p "$corpus" "$art"
    extra=()
    [ -d "$seeds/$t" ] && extra=("$seeds/$t")
    flags=("${limit[@]}" -timeout=10 -rss_limit_mb=3072 -artifact_prefix="$art" -print_final_stats=1)
    start=$(date +%s.%N)
    set +e
    case "$t" in
        c-dataset) "$home/native/build/fuzz/fuzz_dataset" "${flags[@]}" "$corpus" "$kept" "${extra[@]}" >"$log" 2>&1 ;;
        c-options) "$home/native/build/fuzz/fuzz_options" "${flags[@]}" "$corpus" "$kept" "${extra[@]}" >"$log" 2>&1 ;;
        java-events) jazzer workload org.jmclbench.workload.data.DatasetFuzzTest eventFiles "${flags[@]}" "$corpus" "$kept" "${extra[@]}" >"$log" 2>&1 ;;
        java-properties) jazzer workload org.jmclbench.workload.data.DatasetFuzzTest properties "${flags[@]}" "$corpus" "$kept" "${extra[@]}" >"$log" 2>&1 ;;
        java-options) jazzer workload org.jmclbench.workload.RunOptionsFuzzTest commandLine "${flags[@]}" "$corpus" "$kept" >"$log" 2>&1 ;;
        java-matrix) jazzer tooling org.jmclbench.tooling.runner.MatrixFileFuzzTest matrixFile "${flags[@]}" "$corpus" "$kept" >"$log" 2>&1 ;;
        java-hvm-result) jazzer hvm/launcher org.jmclbench.hvm.launcher.HvmResultFileFuzzTest resultFile "${flags[@]}" "$corpus" "$kept" >"$log" 2>&1 ;;
    esac
    code=$?
    set -e
    secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
    runs=$(sed -n 's/^Done \([0-9]*\) runs in.*/\1/p' "$log" | tail -1)
    result=ok
    if [ -n "$(ls -A "$art")" ]; then
        result="FINDING (exit $code): $log; keep the input from $art in $kept"
        status=1
    elif [ "$code" != 0 ] || [ -z "$runs" ]; then
        if grep -q '^INFO: Seed:' "$log"; then # it fuzzed, then died keeping no input (a crash of the JVM)
            result="FINDING (exit $code, no input kept): $log"
        else # it never started (not built, a bad class path): the harness, not the parser
            result="DID NOT RUN (exit $code): $log"
        fi
        status=1
    fi
    printf '%-16s %12s %8.1f %9.0f  %s\n' "$t" "${runs:-?}" "$secs" \
        "$(awk -v r="${runs:-0}" -v s="$secs" 'BEGIN { print (s > 0 ? r / s : 0) }')" "$result"
done
exit $status
