package org.jmclbench.tooling.runtime;

import java.io.FileOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Keeps the CPUs out of deep idle states for as long as it is open (profile component
 * {@code noidle}): a PM QoS request of 0 µs written to {@code /dev/cpu_dma_latency}, which the
 * kernel honours until the file is closed. cyclictest does the same by default; without it a job
 * released to an idle CPU waits for the CPU to wake, and that wait is the machine's, not the runtime's.
 */
public final class IdleStateHold implements AutoCloseable {

    /** The kernel's PM QoS interface for the CPUs' wake-up latency. */
    public static final Path DEVICE = Path.of("/dev/cpu_dma_latency");

    private final FileOutputStream request;

    private IdleStateHold(FileOutputStream request) {
        this.request = request;
    }

    /** Holds {@code device} at 0 until {@link #close()}; a hold of nothing when {@code wanted} is false. */
    public static IdleStateHold start(boolean wanted, Path device) throws IOException {
        if (!wanted) {
            return new IdleStateHold(null);
        }
        FileOutputStream out = new FileOutputStream(device.toFile());
        try {
            out.write(new byte[4]); // a 32-bit 0: "no wake-up latency allowed"
            out.flush();
        } catch (IOException e) {
            out.close();
            throw e;
        }
        return new IdleStateHold(out);
    }

    /** Why {@code noidle} cannot be held here, or null when it can: the device is root's. */
    public static String unavailable(Path device) {
        if (!Files.exists(device)) {
            return "noidle: " + device + " does not exist (no PM QoS in this kernel)";
        }
        return Files.isWritable(device) ? null : "noidle: " + device + " is not writable (it needs root)";
    }

    /** Ends the request: the CPUs may sleep deeply again. */
    @Override
    public void close() throws IOException {
        if (request != null) {
            request.close();
        }
    }
}
