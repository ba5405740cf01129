package org.jmclbench.verification.seeded;

/** The abort request as job code sees it (the static check matches it by simple name). */
public interface AbortSignal {
    boolean abortRequested();
}
