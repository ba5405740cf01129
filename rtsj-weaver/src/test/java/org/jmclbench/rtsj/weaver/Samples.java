package org.jmclbench.rtsj.weaver;

import java.util.List;
import javax.realtime.AsynchronouslyInterruptedException;
import javax.realtime.Interruptible;

/**
 * AI-enabled code for the weaver's tests, woven in memory and run in a doInterruptible. Each
 * scenario fires its own AIE at a chosen point (a fire is a fire, whoever makes it) and logs what
 * ran, so the log shows exactly where the AIE was delivered.
 */
public class Samples implements Interruptible {
    private final String scenario;
    private final List<String> log;
    private final Object lock = new Object();
    /** Loop counts, for the scenarios that report them. */
    public int count;

    public Samples(String scenario, List<String> log) {
        this.scenario = scenario;
        this.log = log;
    }

    private void log(String s) {
        log.add(s);
    }

    @Override
    public void run(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        switch (scenario) {
            case "loop":
                loop(aie);
                break;
            case "synchronized":
                inSynchronized(aie);
                break;
            case "finally":
                inFinally(aie);
                break;
            case "nonAi":
                nonAiCaller(aie);
                break;
            case "aiCalleeInSynchronized":
                synchronized (lock) {
                    aiCallee(aie);
                    log("monitor region went on");
                }
                break;
            case "caughtNotCleared":
                caught(aie, false);
                break;
            case "caughtAndCleared":
                caught(aie, true);
                break;
            case "crossThread":
                crossThread(aie);
                break;
            case "endsInSynchronized":
                synchronized (lock) {
                    aie.fire();
                    log("in monitor");
                }
                count = 1; // RTSJ: not reached, the AIE is delivered as the monitor region ends
                return;
            default:
                throw new IllegalArgumentException(scenario);
        }
        log("completed");
    }

    @Override
    public void interruptAction(AsynchronouslyInterruptedException aie) {
        log("interrupted");
    }

    private void loop(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        for (count = 0; count < 1000; count++) {
            if (count == 10) {
                aie.fire();
            }
        }
        log("loop ended");
    }

    private void inSynchronized(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        log("start");
        synchronized (lock) {
            aie.fire();
            for (int i = 0; i < 3; i++) {
                log("in monitor " + i);
            }
            log("end of synchronized");
        }
        log("after synchronized");
        log("not reached");
    }

    private void inFinally(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        try {
            log("try");
        } finally {
            aie.fire();
            for (int i = 0; i < 3; i++) {
                log("in finally " + i);
            }
            log("end of finally");
        }
        log("after finally");
        log("not reached");
    }

    private void nonAiCaller(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        nonAi(aie);
        log("not reached");
    }

    /** Not AI-enabled: no delivery point here, whatever it does. */
    private void nonAi(AsynchronouslyInterruptedException aie) {
        aie.fire();
        for (int i = 0; i < 3; i++) {
            log("in non-AI " + i);
        }
        log("end of non-AI");
    }

    private void aiCallee(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        aie.fire();
        log("in AI callee");
        log("not reached");
    }

    /** An AI-enabled step: the AIE pending on return from fire() is delivered before it logs. */
    private void interruptibleLog(String line) throws AsynchronouslyInterruptedException {
        log(line);
    }

    private void caught(AsynchronouslyInterruptedException aie, boolean clear) throws AsynchronouslyInterruptedException {
        try {
            aie.fire();
            interruptibleLog("not reached"); // declares the AIE, so that javac allows the catch
        } catch (AsynchronouslyInterruptedException e) {
            if (clear && e.happened(true)) {
                log("cleared");
            }
            log("caught");
        }
        log("after catch");
    }

    /** Spins until another thread's fire lands; counts the iterations after it saw the fire. */
    private void crossThread(AsynchronouslyInterruptedException aie) throws AsynchronouslyInterruptedException {
        Thread firer = new Thread(() -> {
            aie.fire();
            firedFlag = true;
        });
        firer.start();
        while (true) {
            if (firedFlag) {
                count++;
                if (count > 1) {
                    log("not delivered");
                    return;
                }
            }
        }
    }

    private volatile boolean firedFlag;

    /** A class whose AI-enabled methods include one without code: nothing to weave there. */
    public abstract static class WithAbstractStep {
        protected abstract void step() throws AsynchronouslyInterruptedException;

        public void steps() throws AsynchronouslyInterruptedException {
            step();
            step();
        }
    }
}
