package org.jmclbench.workload.scj;

import org.jmclbench.rtsjcompat.ScjLauncher;
import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.workload.output.Json;

/** summary.json's {@code engine} object of an scj run (docs/FORMATS.md section 4), from the SCJ layer's report. */
final class ScjFacts implements EngineFacts {
    private final int warmupEvents;
    private final ScjLauncher mission;
    private final int outOfOrderJobs;

    ScjFacts(int warmupEvents, ScjLauncher mission, int outOfOrderJobs) {
        this.warmupEvents = warmupEvents;
        this.mission = mission;
        this.outOfOrderJobs = outOfOrderJobs;
    }

    @Override
    public void writeTo(Json j) {
        j.name("warmupEvents").value(warmupEvents);
        j.name("level").value(mission.level());
        j.name("prioritiesApplied").value(mission.handlerPrioritiesApplied());
        j.name("allocationMeter").value(mission.allocationMeter());
        j.name("timeSource").value(mission.timeSource());
        j.name("handlers").beginObject();
        for (int h = 0; h < mission.handlerCount(); h++) {
            j.name(mission.handlerName(h)).beginObject();
            j.name("kind").value(mission.handlerKind(h));
            j.name("priority").value(mission.handlerPriority(h));
            j.name("releases").value(mission.handlerReleases(h));
            j.name("deadlineMisses").value(mission.handlerDeadlineMisses(h));
            j.name("lateReleases").value(mission.handlerLateReleases(h));
            j.endObject();
        }
        j.endObject();
        j.name("outOfOrderJobs").value(outOfOrderJobs);
    }
}
