package org.jmclbench.tooling.attribution;

/**
 * One job of a run, as its job line says (docs/FORMATS.md section 3); times in ns from the
 * run start, -1 where there is no such time.
 */
public record JobRecord(String task, int index, long releaseNs, long startNs, long endNs, long deadlineNs,
        String outcome, long cpuNs) {

    /** True for a job that counts against the run: skipped, terminated, or completed after its deadline. */
    public boolean missedOrLate() {
        return outcome.equals("late") || outcome.equals("skipped") || outcome.equals("terminated");
    }

    /** True when the job ran (it has a start time). */
    public boolean started() {
        return startNs >= 0;
    }

    /** True when the job ran to its end. */
    public boolean completed() {
        return outcome.equals("done") || outcome.equals("late");
    }
}
