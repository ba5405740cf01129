#!/usr/bin/env bash
# Times `jmclbench report` on a generated results store of N runs (default 1000), the speed
# target of SPEC section 11 ("building the report for 1,000 runs takes seconds, not minutes").
# The store comes from the test-scope FixtureDb (the schema of docs/FORMATS.md section 5, 90 s
# runs: 5 runtimes x 2 policies x 4 particle counts x repetitions, with histograms and series).
#   bench/report-build.sh [RUNS]
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
. "$home/bench/options.sh"
runs=
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) usage ;;
        -*) unknown_option "$1" ;;
        *) [ -z "$runs" ] || unexpected_argument "$1"; runs=$1; shift ;;
    esac
done
runs=${runs:-1000}
require_positive RUNS "$runs"
cd "$home"
java17=/usr/lib/jvm/java-17-openjdk-amd64
if [ -z "${JAVA_HOME:-}" ] && [ -d "$java17" ]; then export JAVA_HOME=$java17; fi
java=${JAVA_HOME:+$JAVA_HOME/bin/}java

echo "== building (tooling jar and test classes)"
mvn -q -B -ntp -pl workload,tooling -am -DskipTests package
cp="tooling/target/test-classes:tooling/target/jmclbench-tooling.jar"

work=$(mktemp -d /tmp/jmclbench-report-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
echo "== generating a store of $runs runs"
"$java" -cp "$cp" org.jmclbench.tooling.report.FixtureDb "$work/results.db" "$runs"
ls -l "$work/results.db" | awk '{printf "store: %.1f MB\n", $5 / 1e6}'

TIMEFORMAT='%R s wall, %U s user, %S s sys'
echo "== report, page only (--no-export), load average: $(cut -d' ' -f1-3 /proc/loadavg)"
time "$java" -jar tooling/target/jmclbench-tooling.jar report --db "$work/results.db" --out "$work/page" --no-export 2>/dev/null
echo "== report with every chart exported as SVG and PNG, load average: $(cut -d' ' -f1-3 /proc/loadavg)"
time "$java" -jar tooling/target/jmclbench-tooling.jar report --db "$work/results.db" --out "$work/report" 2>/dev/null
ls -l "$work/report/index.html" | awk '{printf "index.html: %.1f MB\n", $5 / 1e6}'
echo "chart files: $(ls "$work/report/charts" | wc -l)"
