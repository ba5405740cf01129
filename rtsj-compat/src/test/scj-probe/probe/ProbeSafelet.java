package probe;

import javax.realtime.AbsoluteTime;
import javax.realtime.AperiodicParameters;
import javax.realtime.Clock;
import javax.realtime.ConfigurationParameters;
import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.RelativeTime;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.AperiodicEventHandler;
import javax.safetycritical.LaunchLevel1;
import javax.safetycritical.LinearMissionSequencer;
import javax.safetycritical.ManagedMemory;
import javax.safetycritical.Mission;
import javax.safetycritical.MissionSequencer;
import javax.safetycritical.OneShotEventHandler;
import javax.safetycritical.PeriodicEventHandler;
import javax.safetycritical.PriorityScheduler;
import javax.safetycritical.Safelet;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.SCJAllowed;

/**
 * A small SCJ Level 1 program touching the API this project relies on. It must compile
 * unchanged against rtsj-compat (ProbeProgramTest, which also runs it) and against the icecap
 * SDK's sources (scripts/check-icecap-api.sh). It ends by itself: the periodic handler
 * requests termination at its third release.
 */
@SCJAllowed(value = Level.LEVEL_1, members = true)
public class ProbeSafelet implements Safelet {
    /** Releases seen by each handler: periodic, aperiodic, one-shot. */
    public static final int[] RELEASES = new int[3];

    public MissionSequencer getSequencer() {
        return new LinearMissionSequencer(new PriorityParameters(PriorityScheduler.instance().getNormPriority()),
                new ScopeParameters(20000, 0, 0, 20000), null, new ProbeMission(), false);
    }

    public long managedMemoryBackingStoreSize() {
        return 200000;
    }

    public long immortalMemorySize() {
        return 100000;
    }

    public void initializeApplication(String[] args) {
    }

    public boolean handleStartupError(int cause, long val) {
        return false;
    }

    public void cleanUp() {
    }

    static final class ProbeMission extends Mission {
        protected void initialize() {
            final AperiodicEventHandler update = new AperiodicEventHandler(new PriorityParameters(10),
                    new AperiodicParameters(), new ScopeParameters(2000, 0, 0, 1000), null) {
                public void handleAsyncEvent() {
                    RELEASES[1]++;
                    ManagedMemory.enterPrivateMemory(500, new Runnable() {
                        public void run() {
                        }
                    });
                }
            };
            update.register();
            final OneShotEventHandler sensor = new OneShotEventHandler(new PriorityParameters(20),
                    new RelativeTime(1, 0), new AperiodicParameters(), new ScopeParameters(2000, 0, 0, 0), null) {
                public void handleAsyncEvent() {
                    RELEASES[2]++;
                }
            };
            sensor.register();
            new PeriodicEventHandler(new PriorityParameters(PriorityScheduler.instance().getMaxPriority()),
                    new PeriodicParameters(new RelativeTime(0, 0), new RelativeTime(5, 0)),
                    new ScopeParameters(2000, 0, 0, 0), new ConfigurationParameters(-1, -1, new long[] {1024})) {
                private final AbsoluteTime now = new AbsoluteTime();
                private final RelativeTime soon = new RelativeTime(1, 0);

                public void handleAsyncEvent() {
                    Clock.getRealtimeClock().getTime(now);
                    update.release();
                    sensor.scheduleNextReleaseTime(soon);
                    if (++RELEASES[0] == 3) {
                        Mission.getMission().requestTermination();
                    }
                }
            }.register();
        }

        public long missionMemorySize() {
            return 50000;
        }
    }

    public static void main(String[] args) {
        new LaunchLevel1(new ProbeSafelet());
    }
}
