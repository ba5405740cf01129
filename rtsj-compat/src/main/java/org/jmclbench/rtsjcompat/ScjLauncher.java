package org.jmclbench.rtsjcompat;

import javax.safetycritical.Safelet;

/**
 * The one class a Java SE launcher of an SCJ application needs from this layer: launch at
 * Level 1 and read the outcome as plain values (the failure, each memory area's use, each
 * handler's counts, how the run was timed and measured). Areas and handlers are numbered in
 * creation order (immortal memory first). The classes behind it ({@link ScjRuntime},
 * {@link RunReport}, ...) stay this layer's own.
 */
public final class ScjLauncher {
    private final RunReport report;

    private ScjLauncher(RunReport report) {
        this.report = report;
    }

    /**
     * Runs {@code safelet} at Level 1 (handlers on their own threads) to its end; a failure of
     * the application is in the outcome, not thrown. Null when the layer made no report.
     */
    public static ScjLauncher launch(Safelet safelet) {
        RunReport r = ScjRuntime.launch(safelet, 1);
        return r == null ? null : new ScjLauncher(r);
    }

    /** Whether thread priorities reach the OS scheduler in this JVM (a Java SE engine's threads too). */
    public static boolean prioritiesApplied() {
        return Priorities.applied();
    }

    /** Whether the launch ran to its end with no failure. */
    public boolean succeeded() {
        return report.succeeded();
    }

    /** The failure's one-line message, or null. */
    public String failureMessage() {
        return report.succeeded() ? null : report.failure().getMessage();
    }

    /** The area whose budget an allocation overflowed (its index), or -1 when the failure was not an overflow. */
    public int overflowedArea() {
        String name = report.succeeded() ? null : report.failure().areaName();
        for (int a = 0; name != null && a < areaCount(); a++) {
            if (areaName(a).equals(name)) {
                return a;
            }
        }
        return -1;
    }

    /** The bytes the overflowing allocation needed, or -1. */
    public long overflowBytesNeeded() {
        return report.succeeded() ? -1 : report.failure().bytesNeeded();
    }

    /** The SCJ level the application ran at. */
    public int level() {
        return report.level();
    }

    /** Whether the handlers' priorities reached the OS scheduler. */
    public boolean handlerPrioritiesApplied() {
        return report.prioritiesApplied();
    }

    /** What measured allocations ({@code none} when nothing was). */
    public String allocationMeter() {
        return report.allocationMeter();
    }

    /** Whether allocation was measured: false, every area's figures are 0 whatever it held, and no budget was enforced. */
    public boolean allocationMeasured() {
        return report.allocationMeasured();
    }

    /** The time source of the run: system or virtual. */
    public String timeSource() {
        return report.timeSource();
    }

    /** The number of memory areas. */
    public int areaCount() {
        return report.areas().size();
    }

    /** Area a's name: {@code ImmortalMemory}, {@code MissionMemory} or {@code PrivateMemory:<handler>}. */
    public String areaName(int a) {
        return report.areas().get(a).name();
    }

    /** Whether area a is a handler's private memory (emptied after each release). */
    public boolean areaIsPrivate(int a) {
        return "private".equals(report.areas().get(a).kind());
    }

    /** Area a's budget, bytes. */
    public long areaSize(int a) {
        return report.areas().get(a).size();
    }

    /** The most area a held at once, bytes (a private memory: its largest release). */
    public long areaPeakBytes(int a) {
        return report.areas().get(a).peakBytes();
    }

    /** How often area a was entered and emptied (a private memory: its releases). */
    public long areaReleases(int a) {
        return report.areas().get(a).cycles();
    }

    /** How many releases allocated in area a (a private memory; README: one can be the JIT's). */
    public long areaAllocatingReleases(int a) {
        return report.areas().get(a).allocatingCycles();
    }

    /** Mean bytes allocated in area a per release. */
    public double areaBytesPerRelease(int a) {
        return report.areas().get(a).bytesPerCycle();
    }

    /** The number of handlers. */
    public int handlerCount() {
        return report.handlers().size();
    }

    /** Handler h's name. */
    public String handlerName(int h) {
        return report.handlers().get(h).name();
    }

    /** Handler h's kind: periodic, aperiodic or oneshot. */
    public String handlerKind(int h) {
        return report.handlers().get(h).kind();
    }

    /** Handler h's SCJ priority. */
    public int handlerPriority(int h) {
        return report.handlers().get(h).priority();
    }

    /** Handler h's releases. */
    public long handlerReleases(int h) {
        return report.handlers().get(h).releases();
    }

    /** Handler h's completed releases that ended after release time + deadline. */
    public long handlerDeadlineMisses(int h) {
        return report.handlers().get(h).deadlineMisses();
    }

    /** Handler h's periodic releases that started only after the next release time had passed. */
    public long handlerLateReleases(int h) {
        return report.handlers().get(h).lateReleases();
    }
}
