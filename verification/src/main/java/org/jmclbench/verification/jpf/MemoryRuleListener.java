package org.jmclbench.verification.jpf;

import org.jmclbench.verification.Property;

/**
 * What the listeners of the SCJ memory rules (P6) share: a {@link RuleListener} (the first
 * violation found on a path, its message and its location) that reports property P6.
 */
abstract class MemoryRuleListener extends RuleListener {

    @Override
    public Property property() {
        return Property.P6;
    }
}
