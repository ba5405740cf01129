package org.jmclbench.verification.toy;

/** The handler thread: each release runs one terminable particle job (handleAsyncEvent). */
final class ToyHandler implements Runnable {
    private final ToyMission m;
    private int event;

    ToyHandler(ToyMission m) {
        this.m = m;
    }

    @Override
    public void run() {
        try {
            while ((event = m.next()) >= 0) {
                handleAsyncEvent();
            }
        } catch (InterruptedException e) {
            throw new IllegalStateException(e);
        }
    }

    /** One release: move every particle, polling the abort request every poll particles. */
    void handleAsyncEvent() {
        ToyRobot r = m.robot;
        long before = r.fingerprint();
        double[] out = r.spare();
        int n = r.particles();
        int poll = m.fault == ToyFault.WIDE_POLL ? 2 * m.poll : m.poll;
        double sum = 0;
        for (int i = 0; i < n; i++) {
            if (m.fault == ToyFault.COMMIT_BEFORE_POLL) {
                r.overwriteLive(i, r.particle(i) + 1);
            }
            if (i % poll == 0 && m.abortRequested(i)) {
                m.robotChanged.unless(r.fingerprint() == before, this, "handleAsyncEvent");
                m.end(event, ToyMission.TERMINATED);
                return;
            }
            if (m.fault == ToyFault.STRAY_ALLOCATION) {
                double[] scratch = new double[1];
                scratch[0] = r.particle(i);
            }
            out[i] = r.particle(i) + 1;
            sum += out[i];
        }
        r.commit(sum / n, m, event);
    }
}
