package javax.safetycritical;

/**
 * Runs a Safelet at SCJ Level 0 to its end: {@code new LaunchLevel0(safelet)} returns
 * when the last mission and the Safelet's cleanUp are done, and throws
 * {@link org.jmclbench.rtsjcompat.MissionFailure} when something failed (an exception in a
 * handler, an area overflow). The report: {@link org.jmclbench.rtsjcompat.ScjRuntime#lastReport()}.
 */
public final class LaunchLevel0 {

    /** Runs {@code app} at Level 0. */
    public LaunchLevel0(Safelet app) {
        Launch.run(app, 0);
    }
}
