package org.jmclbench.verification;

import org.jmclbench.verification.jpf.JpfCheck;

import java.util.List;

/**
 * A set of checks verify runs, found with {@link java.util.ServiceLoader}: the real mission's and
 * the rtsj engine's (main sources) and the seeded bugs' (test sources, so never shipped with them).
 */
public interface CheckCatalog {
    /** A name for the table ("mission", "seeded"). */
    String name();

    /** The model checks. */
    List<JpfCheck> jpfChecks();

    /** The bytecode checks. */
    List<StaticCheck> staticChecks();
}
