package org.jmclbench.scj;

import javax.realtime.AperiodicParameters;
import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.AperiodicEventHandler;

/**
 * The update task: released by the laser sensor once per admitted laser event, it weighs and
 * resamples the particles with the measured angle. Releases that arrive while it runs are
 * counted by the SCJ infrastructure; the events themselves wait in a release queue.
 */
public class UpdateHandler extends AperiodicEventHandler {
    private final ReleaseQueue queue;
    private final JobRunner runner;

    UpdateHandler(PriorityParameters priority, AperiodicParameters release, ScopeParameters storage,
            ConfigurationParameters config, ReleaseQueue queue, JobRunner runner) {
        super(priority, release, storage, config, "update");
        this.queue = queue;
        this.runner = runner;
    }

    @Override
    public void handleAsyncEvent() {
        handleRelease();
        runner.releaseEnding();
    }

    private void handleRelease() {
        int k = queue.take();
        if (k < 0) {
            return; // nothing released (not expected: one release per offered event)
        }
        runner.run(k, true, Long.MAX_VALUE);
    }
}
