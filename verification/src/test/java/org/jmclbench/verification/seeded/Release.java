package org.jmclbench.verification.seeded;

/** A release's entry point, as SCJ's ManagedEventHandler has it. */
public abstract class Release {
    public abstract void handleAsyncEvent();
}
