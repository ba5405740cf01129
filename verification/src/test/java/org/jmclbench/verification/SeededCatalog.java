package org.jmclbench.verification;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.scj.Robot;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.jpf.JpfRunner;
import org.jmclbench.verification.mission.CheckedRobot;
import org.jmclbench.verification.seeded.AllocatingRelease;
import org.jmclbench.verification.seeded.GuardedCounter;
import org.jmclbench.verification.seeded.PollingJob;
import org.jmclbench.verification.seeded.mission.CachedScratch;
import org.jmclbench.verification.seeded.mission.CommitBeforePoll;
import org.jmclbench.verification.seeded.mission.GeneratorAdvanced;
import org.jmclbench.verification.seeded.mission.LockInversion;
import org.jmclbench.verification.seeded.mission.LostRelease;
import org.jmclbench.verification.seeded.mission.NeverEnds;
import org.jmclbench.verification.seeded.mission.PollIgnored;
import org.jmclbench.verification.seeded.mission.PrivateIntoMission;
import org.jmclbench.verification.seeded.mission.RecordsAborted;
import org.jmclbench.verification.seeded.mission.RobotKept;
import org.jmclbench.verification.seeded.mission.StrayAllocation;
import org.jmclbench.verification.seeded.mission.UnguardedRead;
import org.jmclbench.verification.seeded.mission.WidePoll;
import org.jmclbench.verification.seeded.rtsj.EngineMutant;
import org.jmclbench.verification.seeded.rtsj.RtsjSeededChecks;
import org.jmclbench.verification.toy.ToyChecks;

import java.io.IOException;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The seeded bugs verify must catch (test sources: never shipped with the mission): bugs
 * plugged into the real mission through its configuration seam, each expected as one violation
 * of its property at the seeded method, the small SCJ-like program's seeded bugs, and the static
 * checks' seeded classes.
 */
public final class SeededCatalog implements CheckCatalog {

    @Override
    public String name() {
        return "seeded";
    }

    /** A seeded bug in the mission: run with its fault, it must violate {@code p} in {@code at.method}. */
    private static JpfCheck mission(String name, Property p, MissionRun run, Class<?> fault, Class<?> at,
                                    String method, String what) {
        String memory = run.memory();
        return MissionChecks.check("mission-seeded-" + name, EnumSet.of(p), run,
                p == Property.P2 ? MissionChecks.raceConfig() : MissionChecks.config(memory),
                Expectation.violation(p, at, method), fault, "seeded " + what);
    }

    @Override
    public List<JpfCheck> jpfChecks() {
        MissionRun queue = MissionRun.of("queue", "preallocated");
        MissionRun terminate = MissionRun.of("terminate", "preallocated");
        MissionRun scopedQueue = MissionRun.of("queue", "scoped");
        List<JpfCheck> l = new ArrayList<>(List.of(
                mission("stray-allocation", Property.P6, queue, StrayAllocation.class, StrayAllocation.class,
                        "predict", "stray allocation in a release"),
                mission("private-into-mission", Property.P6, scopedQueue, PrivateIntoMission.class,
                        PrivateIntoMission.class, "predict", "private-memory array kept by the mission's localizer"),
                mission("cached-scratch", Property.P6, scopedQueue, CachedScratch.class, CachedScratch.class,
                        "update", "private-memory array cached in a thread-local"),
                mission("lock-inversion", Property.P1, queue.atOdometryInstants(), LockInversion.class, LockInversion.InvertingRobot.class,
                        "predict", "robot/gate lock-order inversion"),
                mission("lost-release", Property.P5, queue, LostRelease.class, LostRelease.EarlyEnd.class, "ended",
                        "gate ending the mission after the first event"),
                mission("robot-kept", Property.P7, MissionRun.of("skip", "preallocated"), RobotKept.class,
                        RobotKept.KeepingGate.class, "admit", "gate that never frees the robot under skip"),
                mission("never-ends", Property.P5, queue, NeverEnds.class, NeverEnds.OffByOne.class, "ended",
                        "gate that never ends the mission"),
                mission("unguarded-read", Property.P2, MissionChecks.raceRun("terminate"), UnguardedRead.class,
                        UnguardedRead.CountingGate.class, "abortRequested",
                        "admission count read by the abort poll without the gate's lock"),
                mission("commit-before-poll", Property.P3, terminate, CommitBeforePoll.class, CommitBeforePoll.class,
                        "predict", "job that applies its step before it polls"),
                mission("generator-advanced", Property.P3, terminate, GeneratorAdvanced.class,
                        GeneratorAdvanced.class, "predict", "aborted job that advances the committed generator"),
                mission("records-aborted", Property.P3, terminate, RecordsAborted.class, RecordsAborted.Recording.class,
                        "predict", "robot recording an aborted job's estimate"),
                mission("poll-ignored", Property.P4, terminate, PollIgnored.class, PollIgnored.class, "predict",
                        "job that carries on after seeing the request"),
                mission("wide-poll", Property.P4, MissionChecks.intervalRun(), WidePoll.class, WidePoll.class, "predict",
                        "job polling every fourth interval")));
        l.add(predictUnlocked(terminate));
        l.addAll(ToyChecks.all());
        l.addAll(RtsjSeededChecks.all());
        return l;
    }

    /**
     * A predict job without the robot's monitor: the shipped mission takes it twice (the job
     * runner's {@code synchronized (robot)} and the robot's synchronized predict), so the bug is
     * both dropped, as edits of {@code JobRunner} and {@code Robot} put first on JPF's class path.
     * A laser event released within a predict job then starts an update job at once, and the
     * checked robot sees two jobs in the localizer, blamed on predict, the one without the monitor.
     */
    static JpfCheck predictUnlocked(MissionRun run) {
        String id = "mission-seeded-predict-unlocked";
        Path dir = EngineMutant.RUNNER_ROBOT_UNLOCKED.writeUnder(RtsjSeededChecks.mutantsRoot(), id);
        try {
            Path robot = dir.resolve(Robot.class.getName().replace('.', '/') + ".class");
            if (Modifier.isSynchronized(Robot.class.getMethod("predict", int.class, AbortSignal.class).getModifiers())) {
                EngineMutant.ROBOT_PREDICT_UNSYNCHRONISED.writeUnder(RtsjSeededChecks.mutantsRoot(), id);
            } else {
                // a tree whose predict lacks it already (the mutation score's robot-predict-unsynchronised)
                Files.deleteIfExists(robot);
            }
        } catch (NoSuchMethodException | IOException e) {
            throw new IllegalStateException(id + ": " + e, e);
        }
        Map<String, String> config = MissionChecks.config(run.memory());
        config.put(JpfRunner.PREPEND, dir.toAbsolutePath().toString());
        return MissionChecks.check(id, EnumSet.of(Property.P2), run, config,
                Expectation.violation(Property.P2, CheckedRobot.class, "predict"), null,
                "seeded predict job run without the robot's monitor (JobRunner and Robot edited)");
    }

    @Override
    public List<StaticCheck> staticChecks() {
        String alloc = AllocatingRelease.class.getName();
        String poll = PollingJob.class.getName();
        return List.of(
                // SeededLayer stands for the SCJ layer: looked at from the calls into it.
                new StaticCheck("static-seeded-allocation", Property.P6, StaticCheck.Kind.ALLOCATION,
                        n -> n.startsWith("org/jmclbench/verification/seeded/") && !n.endsWith("/SeededLayer"),
                        n -> n.equals(internal(alloc)), n -> n.endsWith("/SeededLayer"),
                        Set.of(alloc + ":handleAsyncEvent", alloc + ":helper", alloc + "$AllocatingStep:apply",
                                alloc + ":lambda$helper$1", alloc + "$Mode:<clinit>", alloc + "$Mode:$values",
                                alloc + "$Mode:values", alloc + "$Table:<clinit>")),
                new StaticCheck("static-seeded-guarded", Property.P2, StaticCheck.Kind.GUARDED,
                        n -> n.equals(internal(GuardedCounter.class.getName())), n -> false, n -> false,
                        Set.of(GuardedCounter.class.getName() + ":offer", GuardedCounter.class.getName() + ":recordLater")),
                new StaticCheck("static-seeded-abort-poll", Property.P4, StaticCheck.Kind.ABORT_POLL,
                        n -> n.equals(internal(poll)), n -> false, n -> false, Set.of(poll + ":update", poll + ":siblings", poll + ":wide",
                                poll + ":sparse", poll + ":normalise", poll + ":walk")));
    }

    private static String internal(String className) {
        return className.replace('.', '/');
    }
}
