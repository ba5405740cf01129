package org.jmclbench.rtsjcompat;

import javax.realtime.AsyncEventHandler;

/**
 * What every {@link HandlerRuntime} is made from, whatever its kind: the handler, its name,
 * priority and private memory, its relative deadline in ns ({@link HandlerRuntime#NO_DEADLINE}:
 * none) and the bytes for its nested private memories. Built once per handler, at mission
 * initialization.
 */
public final class HandlerSetup {
    final AsyncEventHandler handler;
    final String name;
    final int priority;
    final Area privateArea;
    final long deadline;
    final long backingStore;

    /** The setup of {@code handler}; see the class comment for the units. */
    public HandlerSetup(AsyncEventHandler handler, String name, int priority, Area privateArea, long deadline,
            long backingStore) {
        this.handler = handler;
        this.name = name;
        this.priority = priority;
        this.privateArea = privateArea;
        this.deadline = deadline;
        this.backingStore = backingStore;
    }
}
