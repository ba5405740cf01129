package javax.realtime;

/** A set of processors a schedulable may run on; this layer leaves placement to the OS. */
public final class Affinity {
    private Affinity() {
    }
}
