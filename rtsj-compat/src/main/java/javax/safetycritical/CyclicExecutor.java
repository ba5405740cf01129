package javax.safetycritical;

import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.ScjThread;
import org.jmclbench.rtsjcompat.TimeSource;

/**
 * The Level 0 execute phase: on the launcher's thread, frame after frame, each frame's
 * handlers released in order and the next frame started at the absolute time
 * {@code start + sum of the durations} (no drift), until termination is requested.
 */
final class CyclicExecutor {
    private CyclicExecutor() {
    }

    static void run(Mission m, ScjThread t, Area missionArea, TimeSource time) {
        if (!(m instanceof CyclicExecutive)) {
            throw new IllegalStateException("a Level 0 mission must be a CyclicExecutive");
        }
        int n = m.registeredCount();
        PeriodicEventHandler[] handlers;
        CyclicSchedule schedule;
        t.enter(missionArea);
        try {
            handlers = new PeriodicEventHandler[n];
            for (int i = 0; i < n; i++) {
                ManagedEventHandler h = m.handler(i);
                if (!(h instanceof PeriodicEventHandler)) {
                    throw new IllegalStateException("Level 0 allows periodic handlers only: " + h.getName());
                }
                handlers[i] = (PeriodicEventHandler) h;
            }
            schedule = ((CyclicExecutive) m).getSchedule(handlers);
        } finally {
            t.exit();
        }
        if (schedule == null) {
            throw new IllegalStateException("getSchedule returned null");
        }
        Frame[] frames = schedule.frames();
        long frameStart = time.nanoTime();
        int step = 0;
        while (!m.terminationPending()) {
            Frame f = frames[step];
            for (int i = 0; i < f.handlers.length && !m.terminationPending(); i++) {
                f.handlers[i].runtime.runInline(frameStart);
            }
            frameStart += ManagedEventHandler.nanos(f.duration);
            while (time.nanoTime() < frameStart && !m.terminationPending()) {
                time.sleepUntil(t, frameStart);
            }
            step = (step + 1) % frames.length;
        }
    }
}
