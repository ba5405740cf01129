package javax.safetycritical;

/**
 * Runs a Safelet at SCJ Level 1 to its end: {@code new LaunchLevel1(safelet)} returns
 * when the last mission and the Safelet's cleanUp are done, and throws
 * {@link org.jmclbench.rtsjcompat.MissionFailure} when something failed (an exception in a
 * handler, an area overflow). The report: {@link org.jmclbench.rtsjcompat.ScjRuntime#lastReport()}.
 */
public final class LaunchLevel1 {

    /** Runs {@code app} at Level 1. */
    public LaunchLevel1(Safelet app) {
        Launch.run(app, 1);
    }
}
