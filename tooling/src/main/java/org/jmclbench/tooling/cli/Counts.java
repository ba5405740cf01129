package org.jmclbench.tooling.cli;

/** A count with its noun, singular for one: "1 run", "3 runs", "0 runs". */
public final class Counts {

    private Counts() {
    }

    /** {@code n} and {@code noun} (regular plural: an s) as the number calls for. */
    public static String of(long n, String noun) {
        return n + " " + noun(n, noun);
    }

    /** {@code noun} as {@code n} of it is called: "run" for one, "runs" otherwise. */
    public static String noun(long n, String noun) {
        return n == 1 ? noun : noun + "s";
    }
}
