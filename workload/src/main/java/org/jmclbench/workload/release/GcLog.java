package org.jmclbench.workload.release;

import java.io.File;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import javax.management.MBeanServer;
import javax.management.ObjectName;

/**
 * Keeps the runtime's GC log for one run. On JDK 9 and later it turns unified logging of
 * {@code gc*} to a file on and off at run time through the DiagnosticCommand MBean's
 * {@code vmLog} operation (what {@code jcmd <pid> VM.log} does), looked up through JMX so that
 * the bytecode stays Java 8. JDK 8 has no such command: there the GC log needs
 * {@code -Xloggc:<file>} on the JVM's command line, which this class reports.
 */
public final class GcLog {
    private static final String DIAGNOSTIC_COMMAND = "com.sun.management:type=DiagnosticCommand";

    private final File file;
    private final boolean active;
    private final String status;

    private GcLog(File file, boolean active, String status) {
        this.file = file;
        this.active = active;
        this.status = status;
    }

    /** Starts logging GC events to {@code file}; never throws, see {@link #status()}. */
    public static GcLog start(File file) {
        try {
            vmLog("output=" + file.getAbsolutePath(), "what=gc*,safepoint", "decorators=uptime,timenanos,level,tags");
            return new GcLog(file, true, "logging gc*,safepoint to " + file.getName() + " via VM.log");
        } catch (Exception | LinkageError e) {
            String why = e.getCause() != null ? e.getCause().toString() : e.toString();
            return new GcLog(file, false, "not available at run time on this runtime (" + why
                    + "); on JDK 8 pass -Xloggc:<file> to the JVM");
        }
    }

    /**
     * With {@code --gc-log} ({@code asked}), starts the log as {@code runDir/gc.log}, with a line on
     * {@code err} when this runtime cannot write it; null when not asked. The caller stops it.
     */
    public static GcLog startIfAsked(boolean asked, File runDir, PrintStream err) {
        if (!asked) {
            return null;
        }
        GcLog log = start(new File(runDir, "gc.log"));
        if (!log.active()) {
            err.println("jmclbench: --gc-log: " + log.status());
        }
        return log;
    }

    /** Stops logging to the file (idempotent); call before the run's outputs are written. */
    public void stop() {
        if (!active) {
            return;
        }
        try {
            // An output whose every tag is off is removed, which closes the file.
            vmLog("output=" + file.getAbsolutePath(), "what=all=off");
        } catch (Exception | LinkageError e) {
            // The log stays open until exit; the file is still complete up to now.
        }
    }

    /** Whether the log is being written. */
    public boolean active() {
        return active;
    }

    /** The log file. */
    public File file() {
        return file;
    }

    /** One line for the run's summary. */
    public String status() {
        return status;
    }

    private static void vmLog(String... arguments) throws Exception {
        MBeanServer server = ManagementFactory.getPlatformMBeanServer();
        server.invoke(new ObjectName(DIAGNOSTIC_COMMAND), "vmLog",
                new Object[] {arguments}, new String[] {String[].class.getName()});
    }
}
