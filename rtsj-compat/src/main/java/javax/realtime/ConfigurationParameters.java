package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** Sizes a VM needs for a schedulable (message and stack trace lengths, stack sizes). */
@SCJAllowed
public class ConfigurationParameters {
    private final int messageLength;
    private final int stackTraceLength;
    private final long[] sizes;

    /**
     * The given sizes; -1 means the default. Kept for source compatibility: on a JVM the
     * handler threads get the JVM's default stack ({@code sizes[0]}, icecap's stack in
     * words, would be far too small for Java frames).
     */
    public ConfigurationParameters(int messageLength, int stackTraceLength, long[] sizes) {
        if (messageLength < -1) {
            throw new IllegalArgumentException("messageLength must be -1 or more: " + messageLength);
        }
        if (stackTraceLength < -1) {
            throw new IllegalArgumentException("stackTraceLength must be -1 or more: " + stackTraceLength);
        }
        this.messageLength = messageLength;
        this.stackTraceLength = stackTraceLength;
        this.sizes = sizes;
    }

    /** The sizes given at construction (may be null). */
    public long[] getSizes() {
        return sizes;
    }

    /** The message length (-1: default). */
    public int getMessageLength() {
        return messageLength;
    }

    /** The stack trace length (-1: default). */
    public int getStackTraceLength() {
        return stackTraceLength;
    }
}
