#!/usr/bin/env bash
# Every test of the project: the native baseline (normal and sanitizer builds), the Java modules
# with Maven (unit, conformance, end-to-end and browser tests), short fuzz runs, the Ant builds, the
# verification. Arguments go to Maven (e.g. -o; -Dtest=NAME -Dsurefire.failIfNoSpecifiedTests=false).
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
case "${1:-}" in -h|--help) sed -n '2,4p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
cd "$home"

"$home/scripts/install-deps.sh"

# The arguments are Maven's: one Maven cannot parse is bad usage, said now rather than after the
# native tests have run.
if [ $# -gt 0 ] && ! mvn_err=$(mvn -q -v "$@" 2>&1 >/dev/null); then
    echo "test-all: $(printf '%s\n' "$mvn_err" | sed 's/\x1b\[[0-9;]*m//g' | grep -m1 .)" >&2
    exit 2
fi

if [ -f native/Makefile ]; then
    echo "== native tests (C, with AddressSanitizer and UndefinedBehaviorSanitizer) =="
    make -s -C native test
fi

echo "== Java tests (Maven) =="
java17=/usr/lib/jvm/java-17-openjdk-amd64
if [ -z "${JAVA_HOME:-}" ] && [ -d "$java17" ]; then export JAVA_HOME=$java17; fi
# Java PathFinder is on no registry: build it (from JPF_CORE_SRC, else a clone) before Maven
# resolves the verification module's dependencies on its jars.
jpf_home=$("$home/verification/build-jpf.sh")
mvn -B -ntp -Djpf.home="$jpf_home" verify "$@"

echo "== short fuzz runs of every parser (bench/fuzz.sh; docs/RELIABILITY.md) =="
"$home/bench/fuzz.sh" --seconds 5

echo "== Ant build of the SCJ variant (build.xml) =="
ant -q -f "$home/build.xml" clean jars

echo "== Ant build of the rtsj engine for an RTSJ VM (rtsj-compat's jar standing for the VM's library) =="
ant -q -f "$home/build.xml" -Drtsj.api="$home/build/ant/jmclbench-rtsj-compat.jar" rtsj-engine
# rtsj-compat is on that class path, so javac alone cannot see a use of it: the bytecode rule can.
"${JAVA_HOME:+$JAVA_HOME/bin/}java" -cp "$home/verification/target/classes:$(cat "$home/verification/target/verify-classpath.txt")" \
    org.jmclbench.verification.bytecode.RtsjApiCheck --unwoven "$home/build/ant/jmclbench-rtsj-engine.jar"
rtsj_out=$(mktemp -d)
"${JAVA_HOME:+$JAVA_HOME/bin/}java" -cp "$home/build/ant/jmclbench-rtsj-engine.jar:$home/build/ant/jmclbench-rtsj-compat.jar" \
    org.jmclbench.workload.WorkloadMain run --engine rtsj -p 100 --policy terminate --dataset "$home/data/match-quick" \
    -O "$rtsj_out" --force
[ -n "$(find "$rtsj_out" -name summary.json)" ] || { echo "test-all: the Ant-built rtsj engine wrote no summary.json" >&2; exit 1; }
rm -rf "$rtsj_out"
if [ -n "${HVM_SRC:-}" ]; then
    echo "== scj-mission against the icecap SDK's SCJ API =="
    "$home/scripts/check-icecap-api.sh"
else
    echo "== skipped: scj-mission against the icecap SDK (set HVM_SRC to the hvm-scj folder or tarball) =="
fi

echo "== verification (Java PathFinder and static checks of the SCJ mission and the rtsj engine) =="
"$home/jmclbench" verify
