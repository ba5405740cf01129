package org.jmclbench.rtsjcompat;

/**
 * Why a launch failed: an exception or error that escaped a handler, the mission's
 * initialize or cleanUp, or the Safelet, with the area named when it was an overflow.
 * Thrown by {@code new LaunchLevel1(safelet)}; {@link ScjRuntime#launch} returns it in the
 * {@link RunReport} instead.
 */
public final class MissionFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String where;

    MissionFailure(String where, Throwable cause) {
        super("mission failed in " + where + ": " + describe(cause), cause);
        this.where = where;
    }

    private static String describe(Throwable t) {
        String m = t.getMessage();
        return m == null ? t.getClass().getName() : t.getClass().getSimpleName() + ": " + m;
    }

    /** Where it failed: a handler's name, or initialize, cleanUp, Safelet. */
    public String where() {
        return where;
    }

    /** The area that overflowed, or null when the failure was not an area overflow. */
    public String areaName() {
        return getCause() instanceof AreaOverflowError ? ((AreaOverflowError) getCause()).areaName() : null;
    }

    /** The bytes the overflowing area needed, or -1. */
    public long bytesNeeded() {
        return getCause() instanceof AreaOverflowError ? ((AreaOverflowError) getCause()).needed() : -1;
    }
}
