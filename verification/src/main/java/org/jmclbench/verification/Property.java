package org.jmclbench.verification;

/**
 * The properties verify proves of the SCJ mission and the rtsj engine (the product specification's verification
 * section), each with its one wording. Checks, seeded bugs, the table and the JSON name a
 * property by its constant; the program under check reports a violated one by its constant too
 * ({@link org.jmclbench.verification.mission.PropertyFailure}).
 */
public enum Property {
    P1("no deadlock"),
    P2("no data race"),
    P3("an aborted job leaves the robot bit-identical"),
    P4("an abort request is honoured within the poll interval"),
    P5("every event ends exactly once"),
    P6("the SCJ memory rules hold"),
    P7("an event is dropped or aborted only as its policy says"),
    P8("no lock is still held by a job after its release, an interrupted one included"),
    P9("an AIE is delivered only at a delivery point outside synchronized code, in the doInterruptible it was fired at, and never escapes it");

    /** The property in words. */
    public final String wording;

    Property(String wording) {
        this.wording = wording;
    }

    /** "P3 an aborted job leaves the robot bit-identical". */
    public String label() {
        return name() + " " + wording;
    }
}
