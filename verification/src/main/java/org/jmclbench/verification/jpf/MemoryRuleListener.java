package org.jmclbench.verification.jpf;

import gov.nasa.jpf.PropertyListenerAdapter;
import gov.nasa.jpf.search.Search;
import gov.nasa.jpf.vm.VM;
import org.jmclbench.verification.Property;

import java.util.List;

/**
 * What the listeners of the SCJ memory rules (P6) share: the first violation found on a path,
 * its message and its location, as a JPF property that fails once a violation is recorded.
 */
abstract class MemoryRuleListener extends PropertyListenerAdapter implements LocatedProperty {
    /** The first violation's message, or null while the rules hold. */
    String violation;
    /** Where it happened, as {@code Class.method}. */
    String location;

    @Override
    public boolean check(Search search, VM vm) {
        return violation == null;
    }

    @Override
    public String getErrorMessage() {
        return violation;
    }

    @Override
    public Property property() {
        return Property.P6;
    }

    @Override
    public List<String> locations() {
        return violation == null ? List.of() : List.of(location);
    }

    @Override
    public void reset() {
        violation = null;
    }
}
