package hvmtest;

import vm.Machine;
import vm.Monitor;
import vm.Scheduler;

/**
 * Patch 23, compiled mode: a synchronized method whose result a branch leaves on the operand
 * stack ({@code return a == b;}, a {@code ?:}) read that result after its monitor exit, and the
 * exit runs the monitor's Java code on the stack from fp + 1, over the result's word (the SCJ
 * mission's JobGate.admitAt returned 0 and its caller got 16). Here each gate gets its monitor
 * as the SCJ mission's objects do, from the current scheduler's default monitor: a
 * {@link ScribblingMonitor}. The result lies at fp + locals + 2; the exit's vm.Monitor.unlock
 * frame passes the monitor to the nested call of its unlock at fp + 4 (methods with one
 * parameter), and that unlock, interpreted, keeps its locals from fp + 5 (two parameters).
 * Results of every return type must survive it (long and double were already read before the
 * exit; a method handling floats is interpreted, patch 18). The static synchronized methods take
 * no monitor in icecap (it ignores synchronized on a static method, in both modes): they check
 * the same branch results outside a monitor. Outside main (icecap -aot).
 */
public class SyncReturn extends PatchCases {
    static final Object LEFT = new Object();
    static final Object RIGHT = new Object();
    static final int LIMIT = 16;

    long wide = 0x123456789ABCDEFL;

    public static void main(String[] args) {
        Machine.setCurrentScheduler(new OneThreadScheduler());
        new SyncReturn().run(13);
    }

    /**
     * The scheduler of this one-thread program: it only hands each new object of a class with
     * synchronized methods its monitor (the VM asks it at allocation).
     */
    static final class OneThreadScheduler implements Scheduler {
        @Override
        public vm.Process getNextProcess() {
            return null;
        }

        @Override
        public void wait(Object target) {
        }

        @Override
        public void notify(Object target) {
        }

        @Override
        public void notifyAll(Object target) {
        }

        @Override
        public Monitor getDefaultMonitor() {
            return new ScribblingMonitor();
        }

        @Override
        public void terminated() {
        }
    }

    /**
     * A monitor that takes no lock (one thread) and whose unlock writes over the words of the
     * stack the VM gives it: it handles a float, so it stays interpreted in every mode (patch 18),
     * and the interpreter keeps its locals in those words.
     */
    static final class ScribblingMonitor extends Monitor {
        /** Monitor exits so far, of every gate: each instance check expects its two. */
        static int unlocks;

        @Override
        public void lock() {
        }

        @Override
        public void unlock() {
            int w1 = -1, w2 = -1, w3 = -1, w4 = -1, w5 = -1, w6 = -1, w7 = -1, w8 = -1;
            float weight = 1f;
            unlocks += (w1 & w2 & w3 & w4 & w5 & w6 & w7 & w8) == -1 && weight == 1f ? 1 : 0;
        }
    }

    synchronized boolean same(int a, int b) {
        return a == b;
    }

    synchronized boolean atLimit(int a) {
        return a == LIMIT;
    }

    synchronized int larger(int a, int b) {
        return a > b ? a : b;
    }

    synchronized long larger(long a, long b) {
        return a > b ? a : b;
    }

    synchronized double larger(double a, double b) {
        return a > b ? a : b;
    }

    synchronized float larger(float a, float b) {
        return a > b ? a : b;
    }

    synchronized Object pick(boolean left) {
        return left ? LEFT : RIGHT;
    }

    static synchronized boolean sameStatic(int a, int b) {
        return a == b;
    }

    static synchronized int largerStatic(int a, int b) {
        return a > b ? a : b;
    }

    static synchronized long largerStatic(long a, long b) {
        return a > b ? a : b;
    }

    static synchronized double largerStatic(double a, double b) {
        return a > b ? a : b;
    }

    static synchronized Object pickStatic(boolean left) {
        return left ? LEFT : RIGHT;
    }

    @Override
    boolean check(int i) {
        SyncReturn g = new SyncReturn();
        int exits = ScribblingMonitor.unlocks + 2;
        switch (i) {
        case 0:
            return !g.same(3, 4) && g.same(5, 5) && ScribblingMonitor.unlocks == exits;
        case 1:
            return g.larger(2, 9) == 9 && g.larger(-7, -8) == -7 && ScribblingMonitor.unlocks == exits;
        case 2:
            return g.larger(2L, g.wide) == g.wide && g.larger(-1L, -2L) == -1L && ScribblingMonitor.unlocks == exits;
        case 3:
            return g.larger(0.5, 2.25) == 2.25 && g.larger(-0.5, -2.25) == -0.5 && ScribblingMonitor.unlocks == exits;
        case 4:
            return g.larger(0.5f, 2.25f) == 2.25f && g.larger(-0.5f, -2.25f) == -0.5f && ScribblingMonitor.unlocks == exits;
        case 5:
            return g.pick(true) == LEFT && g.pick(false) == RIGHT && ScribblingMonitor.unlocks == exits;
        case 6:
            return !sameStatic(3, 4) && sameStatic(5, 5);
        case 7:
            return largerStatic(2, 9) == 9 && largerStatic(-7, -8) == -7;
        case 8:
            return largerStatic(2L, 0x123456789ABCDEFL) == 0x123456789ABCDEFL && largerStatic(-1L, -2L) == -1L;
        case 9:
            return largerStatic(0.5, 2.25) == 2.25 && largerStatic(-0.5, -2.25) == -0.5;
        case 10:
            return pickStatic(true) == LEFT && pickStatic(false) == RIGHT;
        case 11:
            // the result used inside an expression of the caller, as JobGate's caller did
            return (g.same(1, 1) ? 16 : 0) + (g.same(1, 2) ? 16 : 0) == 16 && ScribblingMonitor.unlocks == exits;
        case 12:
            return !g.atLimit(0) && g.atLimit(LIMIT) && ScribblingMonitor.unlocks == exits;
        default:
            return false;
        }
    }
}
