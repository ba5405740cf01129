package javax.safetycritical;

import javax.realtime.ImmortalMemory;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.Arguments;
import org.jmclbench.rtsjcompat.Priorities;
import org.jmclbench.rtsjcompat.RunReport;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjRuntime;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * What {@code new LaunchLevel0/1(safelet)} does: on a new SCJ thread, create immortal
 * memory of {@code immortalMemorySize()} bytes, call initializeApplication and getSequencer
 * in it, run the sequencer's missions, then the sequencer's and the Safelet's cleanUp in
 * immortal memory; the caller waits, and gets the first failure thrown as a
 * {@link org.jmclbench.rtsjcompat.MissionFailure}.
 */
final class Launch implements Runnable {
    private final Safelet app;
    private final RunState run;

    private Launch(Safelet app, RunState run) {
        this.app = app;
        this.run = run;
    }

    static void run(Safelet app, int level) {
        if (app == null) {
            throw new IllegalArgumentException("safelet is null");
        }
        ScjRuntime.preloadRuntime();
        RunState run = RunState.begin(level);
        ScjThread launcher = new ScjThread(new Launch(app, run), "SCJ launcher",
                Priorities.toJava(javax.safetycritical.PriorityScheduler.instance().getNormPriority()));
        run.time().threadStarted();
        launcher.start();
        if (ScjThread.joinThroughInterrupts(launcher)) {
            Thread.currentThread().interrupt();
        }
        RunReport report = run.end();
        if (!report.succeeded()) {
            throw report.failure();
        }
    }

    @Override
    public void run() {
        try {
            ScjThread t = ScjThread.self();
            Area immortal;
            MissionSequencer seq;
            String[] args = new String[0];
            try {
                long size = Arguments.nonNegative(app.immortalMemorySize(), "immortalMemorySize()");
                immortal = run.newArea("ImmortalMemory", Area.IMMORTAL, size, null);
                ImmortalMemory.instance();
                t.enter(immortal);
                try {
                    app.initializeApplication(args);
                    seq = app.getSequencer();
                } finally {
                    t.exit();
                }
                if (seq == null) {
                    throw new IllegalStateException("getSequencer() returned null");
                }
            } catch (Throwable e) {
                run.fail("Safelet startup", e);
                return;
            }
            t.setPriority(Priorities.toJava(seq.priority.getPriority()));
            seq.handleAsyncEvent();
            try {
                t.enter(immortal);
                try {
                    seq.cleanUp();
                    app.cleanUp();
                } finally {
                    t.exit();
                }
            } catch (Throwable e) {
                run.fail("Safelet.cleanUp", e);
            }
        } finally {
            run.time().threadEnded();
        }
    }
}
