package org.jmclbench.verification.mission;

import org.jmclbench.rtsjcompat.ScjThread;
import org.jmclbench.rtsjcompat.TimeSource;
import org.jmclbench.rtsjcompat.VirtualTimeSource;
import org.jmclbench.verification.Property;

/**
 * rtsj-compat's virtual time with a horizon: a thread that would sleep past it fails with P5
 * (the mission is still running when every event should long have ended). A mission that
 * never ends then is a short counterexample on one search path, not a search that runs until
 * the check's wall-clock budget is gone. The failure names the gate, which ends the mission.
 * A checked job takes virtual time ({@link #execute(long)}), so that a release can fall within it.
 */
public final class HorizonTimeSource extends TimeSource {
    private final VirtualTimeSource time = new VirtualTimeSource(0L);
    private final long horizonNs;
    private final PropertyFailure hang = new PropertyFailure(Property.P5,
            "the mission still runs at the virtual-time horizon: an event never ended");
    private final CheckedConfiguration mission;
    private final Object culprit;
    private final String method;

    /** {@code mission}: the configuration whose gate (made when the mission starts) is blamed. */
    public HorizonTimeSource(long horizonNs, CheckedConfiguration mission) {
        this.horizonNs = horizonNs;
        this.mission = mission;
        this.culprit = null;
        this.method = "ended";
    }

    /** A horizon that blames {@code culprit}'s {@code method} (what counts the ended events). */
    public HorizonTimeSource(long horizonNs, Object culprit, String method) {
        this.horizonNs = horizonNs;
        this.mission = null;
        this.culprit = culprit;
        this.method = method;
    }

    @Override
    public String name() {
        return "virtual, horizon " + horizonNs + " ns";
    }

    /**
     * A job's execution time: the clock moves on by {@code costNs} while the calling thread runs,
     * waking the handlers whose release has come; JPF then explores their releases before and
     * after the job's next synchronisation action (its abort poll, its end). Sleeping instead would
     * not do: a job holds the robot's monitor, and virtual time stands still while the thread
     * waiting for that monitor can run.
     */
    public void execute(long costNs) {
        time.advanceTo(time.nanoTime() + costNs);
    }

    @Override
    public long nanoTime() {
        return time.nanoTime();
    }

    @Override
    public boolean sleepUntil(ScjThread self, long deadline) {
        hang.unless(deadline <= horizonNs, mission != null ? mission.gate() : culprit, method);
        return time.sleepUntil(self, deadline);
    }

    @Override
    public void wake(ScjThread thread) {
        time.wake(thread);
    }

    @Override
    public void threadStarted() {
        time.threadStarted();
    }

    @Override
    public void threadEnded() {
        time.threadEnded();
    }

    @Override
    public void enterIdle() {
        time.enterIdle();
    }

    @Override
    public void leaveIdle() {
        time.leaveIdle();
    }
}
