package org.jmclbench.rtsjcompat;

import java.lang.management.ManagementFactory;

/**
 * SCJ priorities (1 to 100, as in the icecap SDK) onto Java thread priorities (1 to 10),
 * and whether the OS honours the latter.
 */
public final class Priorities {
    /** The lowest SCJ priority. */
    public static final int MIN = 1;
    /** The highest SCJ priority. */
    public static final int MAX = 100;

    private Priorities() {
    }

    /** The Java priority of SCJ priority {@code p}: linear, order-preserving, clamped. */
    public static int toJava(int p) {
        int c = Math.max(MIN, Math.min(MAX, p));
        return Thread.MIN_PRIORITY + (c - MIN) * (Thread.MAX_PRIORITY - Thread.MIN_PRIORITY) / (MAX - MIN);
    }

    /**
     * Whether Java thread priorities reach the OS scheduler: on Linux, HotSpot ignores them
     * unless started with -XX:ThreadPriorityPolicy=1 (as root); elsewhere they are applied.
     * The Java SE engine reports the same fact with this rule.
     */
    public static boolean applied() {
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
            return true;
        }
        try {
            for (String a : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
                if (a.equals("-XX:ThreadPriorityPolicy=1")) {
                    return true;
                }
            }
        } catch (RuntimeException | LinkageError e) {
            return false;
        }
        return false;
    }
}
