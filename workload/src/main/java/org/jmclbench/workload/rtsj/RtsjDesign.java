package org.jmclbench.workload.rtsj;

/**
 * How the rtsj engine's jobs meet RTSJ's asynchronous transfer of control (issue 19, SPEC 14).
 *
 * <ul>
 *   <li>{@link #THESIS}: the 2012 thesis's design (section 4.2.5). A job calls the robot inside
 *       {@code synchronized (robot)}; RTSJ defers an AIE while synchronized code runs, so a fired
 *       AIE takes effect only after the whole job has computed and committed.</li>
 *   <li>{@link #ATOMIC}: terminate made effective under RTSJ's rules. The job computes without the
 *       robot's monitor, on the localizer's working state; every poll of its particle loops is a
 *       call of an AI-enabled method (a delivery point), so a fired AIE is thrown at the next
 *       poll, before the commit; the commit (buffer swap, estimate into the records) runs in
 *       non-AI code, one short step that is never interrupted.</li>
 * </ul>
 */
public enum RtsjDesign {
    THESIS("thesis"),
    ATOMIC("atomic");

    /** The {@code --rtsj-design} value and summary.json's {@code engine.design}. */
    public final String label;

    RtsjDesign(String label) {
        this.label = label;
    }

    /** The design of a {@code --rtsj-design} value, or null. */
    public static RtsjDesign of(String label) {
        for (RtsjDesign d : values()) {
            if (d.label.equals(label)) {
                return d;
            }
        }
        return null;
    }
}
