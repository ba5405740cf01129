package org.jmclbench.tooling.runner;

import java.io.PrintStream;
import java.util.Locale;

import org.jmclbench.tooling.cli.Counts;

/**
 * Shows a matrix's progress: on a terminal one bar redrawn in place (runs done/total, failures, ETA,
 * the run in progress), elsewhere (a pipe, a CI log) one plain line per finished run.
 */
public abstract class Progress {

    protected final PrintStream out;
    protected int total;
    protected int done;
    protected int failed;
    private double wallSum;
    private int timed;

    protected Progress(PrintStream out) {
        this.out = out;
    }

    /** A bar when {@link System#console()} is a terminal, plain lines otherwise. */
    public static Progress forConsole(PrintStream out) {
        return isTerminal() ? new Bar(out) : new Lines(out);
    }

    static boolean isTerminal() {
        java.io.Console c = System.console();
        if (c == null) {
            return false;
        }
        try { // JDK 22+: console() is non-null even when redirected; isTerminal() tells
            return (Boolean) java.io.Console.class.getMethod("isTerminal").invoke(c);
        } catch (ReflectiveOperationException e) {
            return true;
        }
    }

    public void start(int runsToDo) {
        this.total = runsToDo;
    }

    public abstract void started(PlannedRun run);

    /** A run ended with {@code status} after {@code wallS} seconds ({@code failure} says why when not ok). */
    public void ended(PlannedRun run, String status, double wallS, String failure) {
        done++;
        if (!status.equals("ok") && !status.equals("unsupported")) {
            failed++;
        }
        if (wallS > 0) {
            wallSum += wallS;
            timed++;
        }
    }

    /** A message that must not be lost under the bar. */
    public abstract void message(String text);

    public abstract void finish();

    protected String eta() {
        if (timed == 0 || done >= total) {
            return "--";
        }
        return duration(wallSum / timed * (total - done));
    }

    static String duration(double s) {
        long t = Math.round(s);
        if (t >= 3600) {
            return String.format(Locale.ROOT, "%dh%02dm", t / 3600, t / 60 % 60);
        }
        return t >= 60 ? String.format(Locale.ROOT, "%dm%02ds", t / 60, t % 60) : t + "s";
    }

    /** Plain lines, one per run. */
    static final class Lines extends Progress {
        Lines(PrintStream out) {
            super(out);
        }

        @Override
        public void started(PlannedRun run) {
        }

        @Override
        public void ended(PlannedRun run, String status, double wallS, String failure) {
            super.ended(run, status, wallS, failure);
            out.printf(Locale.ROOT, "[%d/%d] %-11s %s (%.1f s)%s  ETA %s%n", done, total, status, run.label(), wallS,
                    failure == null ? "" : ": " + failure, eta());
            out.flush();
        }

        @Override
        public void message(String text) {
            out.println(text);
        }

        @Override
        public void finish() {
        }
    }

    /** A bar redrawn in place with carriage returns. */
    static final class Bar extends Progress {
        private static final int WIDTH = 30;
        private String current = "";

        Bar(PrintStream out) {
            super(out);
        }

        @Override
        public void started(PlannedRun run) {
            current = run.label();
            draw();
        }

        @Override
        public void ended(PlannedRun run, String status, double wallS, String failure) {
            super.ended(run, status, wallS, failure);
            if (!status.equals("ok")) {
                message(String.format(Locale.ROOT, "%-11s %s%s", status, run.label(), failure == null ? "" : ": " + failure));
            }
            current = "";
            draw();
        }

        @Override
        public void message(String text) {
            out.print("\r\033[K");
            out.println(text);
            draw();
        }

        private void draw() {
            int filled = total == 0 ? WIDTH : done * WIDTH / total;
            String bar = "#".repeat(filled) + "-".repeat(WIDTH - filled);
            String line = String.format(Locale.ROOT, "[%s] %d/%d %s, %d failed, ETA %s  %s", bar, done, total, Counts.noun(total, "run"), failed,
                    eta(), current);
            out.print("\r\033[K" + (line.length() > 150 ? line.substring(0, 150) : line));
            out.flush();
        }

        @Override
        public void finish() {
            out.print("\r\033[K");
            out.flush();
        }
    }
}
