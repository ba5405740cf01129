package org.jmclbench.tooling.load;

/**
 * A CPU hog process of our own, for machines without stress-ng: spins until its time is up
 * or its standard input closes (which happens when the process that started it dies, however
 * it dies), so that it cannot outlive the run.
 */
public final class BusyLoop {
    private static volatile long sink;

    private BusyLoop() {
    }

    /** {@code BusyLoop SECONDS}. */
    public static void main(String[] args) {
        long end = System.nanoTime() + (long) (Double.parseDouble(args[0]) * 1e9);
        Thread watch = new Thread(() -> {
            try {
                while (System.in.read() >= 0) {
                    // keep reading until the parent's end of the pipe closes
                }
            } catch (java.io.IOException e) {
                // closed as well
            }
            Runtime.getRuntime().halt(0);
        }, "parent-watch");
        watch.setDaemon(true);
        watch.start();
        long x = 1;
        while (System.nanoTime() < end) {
            for (int i = 0; i < 1_000_000; i++) {
                x = x * 6364136223846793005L + 1442695040888963407L;
            }
            sink = x;
        }
    }
}
