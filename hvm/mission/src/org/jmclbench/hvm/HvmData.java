package org.jmclbench.hvm;

/**
 * The natives (hvm/mission/natives.c) through which data crosses between the HVM and the
 * tooling: a run file of 64-bit words read whole at start, and a result file of 64-bit words
 * written once at the end. Doubles cross as their raw IEEE 754 bits, never as text (the VM
 * cannot print them). Both file names come from the environment (JMCLBENCH_HVM_INPUT,
 * JMCLBENCH_HVM_OUTPUT); docs/HVM.md gives both layouts.
 */
final class HvmData {
    private HvmData() {
    }

    /** Reads the input file; returns its number of words, or -1 when it cannot be read. */
    static native int open();

    /** Input word i. */
    static native long word(int i);

    /** Input word i taken as the bits of a double. */
    static native double real(int i);

    /** Appends a word to the result. */
    static native void put(long value);

    /** Appends the bits of a double to the result. */
    static native void putReal(double value);

    /** Writes the result file; returns 0, or -1 when it cannot be written. */
    static native int finish();

    /** Prints a one-line message (ASCII) to stderr, prefixed by "hvm: "; code selects the message. */
    static native void fail(int code);
}
