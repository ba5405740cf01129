package org.jmclbench.scj;

import javax.realtime.AbsoluteTime;
import javax.realtime.AperiodicParameters;
import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.RelativeTime;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.OneShotEventHandler;

/**
 * The laser sensor, standing for its interrupt: a one-shot handler released at each laser
 * time and rearmed at the next one. Each release applies the policy and, when the event is
 * admitted, releases the update handler.
 */
public class LaserSensor extends OneShotEventHandler {
    private final ImmortalEntry entry;
    private final JobGate gate;
    private final ReleaseQueue queue;
    private final UpdateHandler update;
    private final JobRunner runner;
    private final MissionClock clock;
    private final AbsoluteTime nextRelease = new AbsoluteTime();
    private int next;

    LaserSensor(PriorityParameters priority, RelativeTime firstRelease, AperiodicParameters release,
            ScopeParameters storage, ConfigurationParameters config, ImmortalEntry entry, JobGate gate,
            ReleaseQueue queue, UpdateHandler update, JobRunner runner, MissionClock clock) {
        super(priority, firstRelease, release, storage, config, "sensor");
        this.entry = entry;
        this.gate = gate;
        this.queue = queue;
        this.update = update;
        this.runner = runner;
        this.clock = clock;
    }

    @Override
    public void handleAsyncEvent() {
        handleRelease();
        runner.releaseEnding();
    }

    private void handleRelease() {
        int j = next++;
        int[] laser = entry.laserEvent;
        if (j >= laser.length) {
            return;
        }
        int k = laser[j];
        runner.released(k, runner.nowNs());
        if (gate.admit(k)) {
            queue.offer(k);
            update.release();
        } else {
            runner.skip(k);
        }
        if (j + 1 < laser.length) {
            clock.toAbsolute(entry.releaseNs[laser[j + 1]], nextRelease);
            scheduleNextReleaseTime(nextRelease);
        }
    }
}
