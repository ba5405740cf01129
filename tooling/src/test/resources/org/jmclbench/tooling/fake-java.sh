#!/usr/bin/env bash
# A fake runtime for the runner's tests: answers like a JVM to probes and, as the workload, does
# what MODE says (ok, crash, hang, garbage, badjson, oom, badexit, wrongrun: a valid folder for
# another particle count; unsupported: a count past the runtime's limits, exit 3; exitoom: a JVM's
# exit 3 under -XX:+ExitOnOutOfMemoryError; sigstop: stops itself; flood: 3 GB of stderr, exit 1;
# nosummary: a complete folder without summary.json; overclaim: a summary claiming 20 predict jobs for
# 10 job lines; shortjobs: a job file cut to 5 of its 10 lines; manyjobs, manyrows: 100,000 more job
# lines, position rows than its 10 predict jobs; segvmid: SIGSEGV after its whole
# folder was written; hugesummary, hugejobs: a 3 GB summary.json, odoData.txt (sparse); runawaygclog
# (a JVM 9 or 10): a good run whose GC log ends in a 64 MB line (sparse); badrecording (a JVM 11+):
# a good run whose recording.jfr is no recording; orphan: an ok run that leaves a child running; limit-at-N: ok
# up to N particles, unsupported above; gate: an ok run that first creates ../started beside its
# bin/ and waits for ../open, so that a test can act while a matrix is surely mid-run; sigterm,
# sigint, sighup: the runtime ends itself by that signal, as a JVM's own shutdown can; aotflaky
# (a JVM 25+): its first aot training run crashes, the next writes its cache; idleheld: ok only
# while the runner's JVM holds /dev/cpu_dma_latency open, the noidle profile's request). Tests copy
# it with the placeholders replaced. Never a real measurement.
MODE=@MODE@
SLEEP=@SLEEP@
REJECT='@REJECT@'
MAJOR=@MAJOR@
for a in "$@"; do
    if [ -n "$REJECT" ] && [ "$a" = "$REJECT" ]; then
        echo "Unrecognized VM option '${a#-XX:+}'" >&2
        echo "Error: Could not create the Java Virtual Machine." >&2
        exit 1
    fi
done
if [ "${1:-}" = "-XshowSettings:properties" ]; then
    cat >&2 <<PROPS
Property settings:
    java.runtime.name = Fake Runtime Environment
    java.runtime.version = $MAJOR.0.1+fake
    java.specification.version = $MAJOR
    java.vendor = Fake Systems
    java.version = $MAJOR.0.1
    java.vm.name = Fake 64-Bit VM
    sun.boot.library.path = /nonexistent
        /continued/line

fake version "$MAJOR.0.1"
PROPS
    exit 0
fi
if [ "${*: -1}" = "-version" ]; then
    echo "fake version \"$MAJOR.0.1\"" >&2
    exit 0
fi
p=400 n=1 j=fake O=results policy=skip ideal=false seed=1 engine=javase memory=preallocated
# started as the native baseline (no JVM flags before "run"), it is the native engine
if [ "${1:-}" = run ]; then engine=native; fi
while [ $# -gt 0 ]; do
    case "$1" in
        -p) p=$2; shift ;;
        -n) n=$2; shift ;;
        -j) j=$2; shift ;;
        -O) O=$2; shift ;;
        --policy) policy=$2; shift ;;
        --ideal) policy=ideal; ideal=true ;;
        --seed) seed=$2; shift ;;
        --engine) engine=$2; shift ;;
        --memory) memory=$2; shift ;;
        -Xlog:gc*file=*) gclog=${1#*file=}; gclog=${gclog%%:*} ;;
        -XX:StartFlightRecording=filename=*) recording=${1#*filename=}; recording=${recording%%,*} ;;
        -XX:AOTCacheOutput=*) aotout=${1#*=} ;;
    esac
    shift
done
if [ "$MODE" = wrongrun ]; then p=$((p + 1)); fi
case $policy in skip) T=SkipTest ;; terminate) T=TermTest ;; queue) T=QueueTest ;; *) T=IdealTest ;; esac
sleep "$SLEEP"
echo "fake workload: $p particles, policy $policy"
case $MODE in
    crash)
        echo "# A fatal error has been detected by the Java Runtime Environment:" >&2
        echo "#  SIGSEGV (0xb) at pc=0x0000deadbeef" >&2
        kill -SEGV $$ ;;
    hang)
        sleep @HANGMARK@ ;;
    garbage)
        echo "%%%% not a run %%%%"; exit 0 ;;
    oom)
        echo 'Exception in thread "main" java.lang.OutOfMemoryError: Java heap space' >&2; exit 1 ;;
    badexit)
        echo "jmclbench: something broke" >&2; exit 1 ;;
    unsupported)
        echo "jmclbench: unsupported: --particles $p: the fake VM holds at most 50 particles" >&2; exit 3 ;;
    exitoom)
        echo "Terminating due to java.lang.OutOfMemoryError: Java heap space" >&2; exit 3 ;;
    limit-at-*)
        if [ "$p" -gt "${MODE#limit-at-}" ]; then
            echo "jmclbench: unsupported: --particles $p: the fake VM holds at most ${MODE#limit-at-} particles" >&2; exit 3
        fi ;;
    sigstop)
        kill -STOP $$ ;;
    sigterm|sigint|sighup)
        kill -"${MODE^^}" $$
        # still here: the signal was ignored when this shell started (SIGINT in a background job
        # without job control), which bash cannot undo; the same status as a death by it
        exit $((128 + $(kill -l "${MODE#sig}"))) ;;
    flood)
        # gigabytes of stderr (a sparse file: no disk spent), then its last words at the end
        echo "first line" >&2
        truncate -s 3G "/proc/$$/fd/2"
        printf "\njmclbench: failure: flooded its stderr\n" >> "/proc/$$/fd/2"
        exit 1 ;;
    aotflaky)
        if [ -n "${aotout:-}" ]; then
            here=$(cd "$(dirname "$0")/.." && pwd)
            if [ ! -e "$here/trained-once" ]; then
                touch "$here/trained-once"
                kill -SEGV $$
            fi
            echo "fake aot cache" > "$aotout"
        fi ;;
    idleheld)
        # the runner's JVM must hold it, not just any process (tuned or a cyclictest may hold it for
        # the whole machine): the nearest ancestor that is a java, past wrappers such as setsid,
        # chrt or taskset that forked instead of exec'ing
        runner= pid=$PPID
        while [ -n "$pid" ] && [ "$pid" -gt 1 ]; do
            exe=$(readlink "/proc/$pid/exe" 2>/dev/null || cat "/proc/$pid/comm" 2>/dev/null)
            if [ "${exe##*/}" = java ]; then runner=$pid; break; fi
            pid=$(awk '/^PPid:/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
        done
        held=
        for f in ${runner:+/proc/$runner/fd/*}; do
            if [ "$(readlink "$f" 2>/dev/null)" = /dev/cpu_dma_latency ]; then held=1; break; fi
        done
        [ -n "$held" ] || { echo "jmclbench: failure: nobody holds /dev/cpu_dma_latency" >&2; exit 1; } ;;
    gate)
        here=$(cd "$(dirname "$0")/.." && pwd)
        touch "$here/started"
        while [ ! -e "$here/open" ]; do sleep 0.1; done ;;
esac
leaf=$O/$j/nocov/$p/$T/$n
mkdir -p "$leaf.partial"
{
    echo "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns"
    for i in 0 1 2 3 4 5 6 7 8 9; do
        r=$((i * 50000000))
        if [ $i = 7 ]; then
            echo "$i $r -1 -1 $((r + 50000000)) skipped -1"
        else
            echo "$i $r $((r + 100000 + i * 1000)) $((r + 2100000 + i * 10000)) $((r + 50000000)) done 1900000"
        fi
    done
} > "$leaf.partial/odoData.txt"
{
    echo "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns"
    for i in 0 1 2 3; do
        r=$((i * 110000000 + 7000000))
        echo "$i $r $((r + 200000)) $((r + 9200000)) $((r + 110000000)) done 8900000"
    done
} > "$leaf.partial/laserData.txt"
for i in 0 1 2 3 4 5 6 7 8 9; do
    echo "$i.0000000000000000e-02  4.0e-01  4.0e-01  0.0e+00"
done > "$leaf.partial/position.txt"
for i in 0 1 2 3 4 5 6 7 8 9; do
    echo "$i.0000000000000000e-02  1.0e-03  2.0e-03  3.0e-03  1.0e-02"
done > "$leaf.partial/positionDeviation.txt"
printf 'deviationXY 0.003\nmissCount 1\n' > "$leaf.partial/data.txt"
if [ "$MODE" = badjson ]; then
    echo '{"schema": "jmclbench-run/1", "status": "comp' > "$leaf.partial/summary.json"
else
    # memory areas as the engines report them (made-up sizes that grow with the particles)
    if [ "$engine" = scj ]; then
        priv=0; if [ "$memory" = scoped ]; then priv=$((p * 40)); fi
        AREAS='{"name": "immortal", "size": 1048576, "peakBytes": 100000, "bytesPerRelease": null},
   {"name": "mission", "size": 4194304, "peakBytes": '$((p * 100 + 5000))', "bytesPerRelease": null},
   {"name": "predict", "size": 262144, "peakBytes": '$priv', "bytesPerRelease": '$priv'},
   {"name": "update", "size": 262144, "peakBytes": '$((priv * 2))', "bytesPerRelease": '$((priv * 2))'}'
    elif [ "$engine" = native ]; then
        AREAS=''
    else
        AREAS='{"name": "heap", "size": 536870912, "peakBytes": '$((p * 1000 + 2000000))', "bytesPerRelease": null}'
    fi
    case $MODE in
        breaks-at-*) if [ "$p" -ge "${MODE#breaks-at-}" ]; then dm=1; else dm=0; fi; ALLDM="\"deadlineMisses\": $dm, " ;;
        limit-at-*) ALLDM="\"deadlineMisses\": 0, " ;;
        *) ALLDM="" ;;
    esac
    S='{"count": 9, "mean": 2000000.0, "stdev": 1000.0, "min": 100000, "p50": 2000000, "p90": 2100000, "p99": 2200000, "p999": 2200000, "max": 2200000}'
    cat > "$leaf.partial/summary.json" <<JSON
{"schema": "jmclbench-run/1", "status": "complete",
 "parameters": {"runtimeName": "$j", "engine": "$engine", "memory": "$memory", "particles": $p, "number": $n, "policy": "$policy", "ideal": $ideal, "seed": $seed},
 "engine": {"kind": "$engine"},
 "memory": {"areas": [$AREAS]},
 "environment": {"runtime": {"language": "java", "name": "$j"}},
 "durationS": 0.5, "missCount": 1,
 "tasks": {"predict": {"released": 10, "completed": 9, "done": 9, "late": 0, "skipped": 1, "terminated": 0, "missCount": 1,
                       "releaseJitterNs": $S, "taskLatencyNs": $S, "responseTimeNs": $S, "cpuNs": $S},
           "update": {"released": 4, "completed": 4, "done": 4, "late": 0, "skipped": 0, "terminated": 0, "missCount": 0,
                       "releaseJitterNs": $S, "taskLatencyNs": $S, "responseTimeNs": $S, "cpuNs": $S},
           "all": {${ALLDM}"released": 14, "completed": 13, "done": 13, "late": 0, "skipped": 1, "terminated": 0, "missCount": 1,
                       "releaseJitterNs": $S, "taskLatencyNs": $S, "responseTimeNs": $S, "cpuNs": $S}},
 "dispatcherLatenessNs": $S,
 "deviation": {"xy": {"mean": 0.003, "max": 0.01}, "x": {"mean": 0.001, "max": 0.002}, "y": {"mean": 0.002, "max": 0.003}, "angle": {"mean": 0.01, "max": 0.02}}}
JSON
fi
case $MODE in
    nosummary) rm "$leaf.partial/summary.json" ;;
    hugejobs) truncate -s 3G "$leaf.partial/odoData.txt" ;;
    hugesummary) truncate -s 3G "$leaf.partial/summary.json" ;;
    runawaygclog|badrecording)
        # a good run with its clock, beside the capture its flags asked for: a GC log of one line, then
        # one without an end (64 MB, sparse); a recording JFR cannot read
        sed -i 's/"durationS": 0.5,/"clock": {"runStartEpochNs": 1795314543008098470, "runStartNanoTime": 1046451482579, "jvmStartEpochMs": 1795314541321}, "durationS": 0.5,/' "$leaf.partial/summary.json"
        if [ "$MODE" = badrecording ]; then
            echo "not a recording" > "$recording"
        else
            echo "[0.003s][1046451482579ns][info][gc] Using Serial" > "$gclog"
            truncate -s 64M "$gclog"
        fi ;;
    overclaim) sed -i 's/"released": 10,/"released": 20,/' "$leaf.partial/summary.json" ;;
    shortjobs) sed -i '/^[5-9] /d' "$leaf.partial/odoData.txt" ;;
    manyjobs|manyrows)
        # job lines or position rows on and on, for 10 released predict jobs
        f=$([ "$MODE" = manyjobs ] && echo odoData.txt || echo position.txt)
        line=$(sed -n '$p' "$leaf.partial/$f")
        yes "$line" | head -n 100000 >> "$leaf.partial/$f" ;;
esac
mv "$leaf.partial" "$leaf"
case $MODE in
    segvmid)
        echo "#  SIGSEGV (0xb) at pc=0x0000deadbeef" >&2
        kill -SEGV $$ ;;
    orphan)
        # a child that outlives the runtime with its output open
        sleep @HANGMARK@ &
        ;;
esac
exit 0
