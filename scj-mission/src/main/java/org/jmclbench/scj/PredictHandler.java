package org.jmclbench.scj;

import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.ConfigurationParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.PeriodicEventHandler;

/**
 * The predict task: released every odometry period, its i-th release is the i-th odometry event,
 * whose increment it applies to the robot under the mission's policy.
 */
public class PredictHandler extends PeriodicEventHandler {
    private final ImmortalEntry entry;
    private final JobGate gate;
    private final JobRunner runner;
    private int released;
    private long lastEndNs = Long.MIN_VALUE;

    PredictHandler(PriorityParameters priority, PeriodicParameters release, ScopeParameters storage,
            ConfigurationParameters config, ImmortalEntry entry, JobGate gate, JobRunner runner) {
        super(priority, release, storage, config, "predict");
        this.entry = entry;
        this.gate = gate;
        this.runner = runner;
    }

    @Override
    public void handleAsyncEvent() {
        int i = released++;
        if (i >= entry.odoEvent.length) {
            return; // the odometry has ended; the mission terminates when the last event ends
        }
        int k = entry.odoEvent[i];
        runner.released(k, runner.nowNs());
        // Skip: dropped when the robot is busy at the release, this task's previous job included.
        boolean overran = gate.policy() == OverrunPolicy.SKIP && lastEndNs > entry.releaseNs[k];
        if (overran || !gate.admit(k)) {
            runner.skip(k);
            return;
        }
        // Terminate: the next odometry release aborts this job, as the sensor's releases abort updates.
        long supersededAt = gate.policy() == OverrunPolicy.TERMINATE && i + 1 < entry.odoEvent.length
                ? entry.releaseNs[entry.odoEvent[i + 1]] : Long.MAX_VALUE;
        lastEndNs = runner.run(k, false, supersededAt);
    }
}
