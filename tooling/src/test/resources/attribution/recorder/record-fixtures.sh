#!/usr/bin/env bash
# Records the attribution fixtures (JFR recordings and GC logs) with every JDK given as
# NAME=JAVA_HOME, e.g.
#   record-fixtures.sh jdk17=/usr/lib/jvm/java-17-openjdk-amd64 jdk25=/usr/lib/jvm/temurin-25-jdk-amd64
# Each fixture folder NAME/ holds, for a run with -XX:+UseSerialGC and a 48 MB heap:
# recording.jfr (our jmclbench.jfc), gc.log (unified logging decorated with uptime and
# timenanos, as JfrFlags asks for), jobs.txt and clock.txt; NAME/uptime/ the same program on
# the default collector (G1) logged with the default decorations (uptime only); NAME/zgc/ the
# same with ZGC (where the JDK has it).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dest=$(cd "$here/.." && pwd)
javac=${JAVAC:-/usr/lib/jvm/java-17-openjdk-amd64/bin/javac}
classes=$(mktemp -d)
trap 'rm -rf "$classes"' EXIT
"$javac" --release 11 -d "$classes" "$here/FixtureJobs.java"
jfc=$(cd "$here/../../../../main/resources/org/jmclbench/tooling/attribution" && pwd)/jmclbench.jfc
for spec in "$@"; do
    name=${spec%%=*}; home=${spec#*=}
    out=$dest/$name; rm -rf "$out"; mkdir -p "$out"
    # One run with JFR and the detailed GC log, one with the default log decorations only.
    "$home/bin/java" -XX:+UseSerialGC -Xmx48m -Xms48m \
        "-XX:StartFlightRecording=filename=$out/recording.jfr,settings=$jfc,dumponexit=true" \
        "-Xlog:gc,gc+phases,safepoint:file=$out/gc.log:uptime,timenanos,level,tags" \
        -cp "$classes" org.jmclbench.workload.mcl.FixtureJobs "$out" 3 >/dev/null
    mkdir -p "$out/uptime"
    "$home/bin/java" -Xmx48m -Xms48m "-Xlog:gc:file=$out/uptime/gc.log" \
        -cp "$classes" org.jmclbench.workload.mcl.FixtureJobs "$out/uptime" 3 >/dev/null
    if "$home/bin/java" -XX:+UseZGC -version >/dev/null 2>&1; then
        mkdir -p "$out/zgc"
        "$home/bin/java" -XX:+UseZGC -Xmx128m -Xms128m "-Xlog:gc,gc+phases,safepoint:file=$out/zgc/gc.log:uptime,timenanos,level,tags" \
            -cp "$classes" org.jmclbench.workload.mcl.FixtureJobs "$out/zgc" 1 >/dev/null
    fi
    "$home/bin/java" -version 2>&1 | head -1 > "$out/java-version.txt"
    du -ab "$out"
done
