package org.jmclbench.rtsjcompat;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.Consumer;
import javax.realtime.AperiodicParameters;
import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.RelativeTime;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.AperiodicEventHandler;
import javax.safetycritical.LinearMissionSequencer;
import javax.safetycritical.Mission;
import javax.safetycritical.MissionSequencer;
import javax.safetycritical.OneShotEventHandler;
import javax.safetycritical.PeriodicEventHandler;
import javax.safetycritical.Safelet;
import javax.safetycritical.Services;

/** Small SCJ applications for the tests, built from lambdas. */
final class Apps {
    /** Everything the applications log, in order (synchronized). */
    static final List<String> LOG = Collections.synchronizedList(new ArrayList<String>());

    private Apps() {
    }

    static void log(String s) {
        LOG.add(s);
    }

    static ScopeParameters scope(long privateSize) {
        return new ScopeParameters(privateSize, 0, 0, 100_000);
    }

    static PriorityParameters prio(int p) {
        return new PriorityParameters(p);
    }

    static RelativeTime ms(long ms) {
        return new RelativeTime(ms, 0);
    }

    /** A Safelet with this immortal size running these missions once each. */
    static Safelet safelet(long immortal, Mission... missions) {
        return new Safelet() {
            @Override
            public MissionSequencer getSequencer() {
                log("getSequencer in " + Services.getNameOfCurrentMemoryArea());
                return new LinearMissionSequencer(prio(50), scope(10_000), null, missions, false, "seq");
            }

            @Override
            public long managedMemoryBackingStoreSize() {
                return 1 << 20;
            }

            @Override
            public long immortalMemorySize() {
                return immortal;
            }

            @Override
            public void initializeApplication(String[] args) {
                log("initializeApplication in " + Services.getNameOfCurrentMemoryArea());
            }

            @Override
            public boolean handleStartupError(int cause, long val) {
                return false;
            }

            @Override
            public void cleanUp() {
                log("Safelet.cleanUp in " + Services.getNameOfCurrentMemoryArea());
            }
        };
    }

    /** A mission of {@code size} bytes whose initialize runs {@code init}. */
    static Mission mission(String name, long size, Consumer<Mission> init) {
        return new Mission() {
            @Override
            protected void initialize() {
                log(name + ".initialize in " + Services.getNameOfCurrentMemoryArea());
                init.accept(this);
            }

            @Override
            public long missionMemorySize() {
                return size;
            }

            @Override
            protected boolean cleanUp() {
                log(name + ".cleanUp in " + Services.getNameOfCurrentMemoryArea());
                return true;
            }
        };
    }

    /** A periodic handler running {@code body} at each release. */
    static PeriodicEventHandler periodic(String name, long periodMs, long privateSize, Runnable body) {
        PeriodicEventHandler h = new PeriodicEventHandler(prio(60), new PeriodicParameters(null, ms(periodMs)),
                scope(privateSize), null, name) {
            @Override
            public void handleAsyncEvent() {
                body.run();
            }

            @Override
            public void cleanUp() {
                log(getName() + ".cleanUp");
            }
        };
        h.register();
        return h;
    }

    /** An aperiodic handler running {@code body} at each release. */
    static AperiodicEventHandler aperiodic(String name, long privateSize, Runnable body) {
        AperiodicEventHandler h = new AperiodicEventHandler(prio(55), new AperiodicParameters(), scope(privateSize),
                null, name) {
            @Override
            public void handleAsyncEvent() {
                body.run();
            }

            @Override
            public void cleanUp() {
                log(getName() + ".cleanUp");
            }
        };
        h.register();
        return h;
    }

    /** A one-shot handler first released {@code firstMs} after the mission start. */
    static OneShotEventHandler oneShot(String name, long firstMs, Consumer<OneShotEventHandler> body) {
        OneShotEventHandler h = new OneShotEventHandler(prio(58), ms(firstMs), new AperiodicParameters(), scope(10_000),
                null, name) {
            @Override
            public void handleAsyncEvent() {
                body.accept(this);
            }

            @Override
            public void cleanUp() {
                log(getName() + ".cleanUp");
            }
        };
        h.register();
        return h;
    }
}
