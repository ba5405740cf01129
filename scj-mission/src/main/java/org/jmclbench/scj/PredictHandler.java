package org.jmclbench.scj;

import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.ConfigurationParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.PeriodicEventHandler;

/**
 * The predict task: released every odometry period, its i-th release is the i-th odometry event,
 * whose increment it applies to the robot; the gate decides, under the mission's policy, whether
 * it runs and when it must stop.
 */
public class PredictHandler extends PeriodicEventHandler {
    private final ImmortalEntry entry;
    private final JobGate gate;
    private final JobRunner runner;
    private int released;

    PredictHandler(PriorityParameters priority, PeriodicParameters release, ScopeParameters storage,
            ConfigurationParameters config, ImmortalEntry entry, JobGate gate, JobRunner runner) {
        super(priority, release, storage, config, "predict");
        this.entry = entry;
        this.gate = gate;
        this.runner = runner;
    }

    @Override
    public void handleAsyncEvent() {
        handleRelease();
        runner.releaseEnding();
    }

    private void handleRelease() {
        int i = released++;
        if (i >= entry.odoEvent.length) {
            return; // the odometry has ended; the mission terminates when the last event ends
        }
        int k = entry.odoEvent[i];
        runner.released(k, runner.nowNs());
        if (!gate.admitPeriodic(k, entry.releaseNs[k])) {
            runner.skip(k);
            return;
        }
        long nextReleaseNs = i + 1 < entry.odoEvent.length ? entry.releaseNs[entry.odoEvent[i + 1]] : Long.MAX_VALUE;
        runner.run(k, false, gate.periodicAbortAtNs(nextReleaseNs)); // reports its end to the gate
    }
}
