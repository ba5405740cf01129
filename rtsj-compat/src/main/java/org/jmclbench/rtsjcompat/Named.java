package org.jmclbench.rtsjcompat;

/** What a run report lists and looks up by name: memory areas and handlers. */
interface Named {
    /** The stable name, as reported in summary.json. */
    String name();
}
