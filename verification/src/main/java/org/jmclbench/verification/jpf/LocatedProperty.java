package org.jmclbench.verification.jpf;

import org.jmclbench.verification.Property;

import java.util.List;

/**
 * A JPF property of ours that names which {@link Property} it checks and, once violated, where:
 * each party's {@code Class.method} (one for an allocation or a store, two for a race). Verify
 * matches a seeded bug's expectation against these, not against the message.
 */
public interface LocatedProperty {
    /** The property this JPF property checks. */
    Property property();

    /** Where the last violation happened, as {@code Class.method}; empty before one. */
    List<String> locations();

    /** {@code Class.method} of a method. */
    static String of(gov.nasa.jpf.vm.MethodInfo mi) {
        return mi == null ? "?" : mi.getClassName() + "." + mi.getName();
    }
}
