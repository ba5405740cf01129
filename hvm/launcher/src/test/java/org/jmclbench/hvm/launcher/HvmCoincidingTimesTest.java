package org.jmclbench.hvm.launcher;

import org.jmclbench.workload.CoincidingTimesTest;
import org.junit.jupiter.api.BeforeAll;

/**
 * Events at the same time with the hvm engine on the class path: the SCJ mission compiled by the
 * icecap HVM decides a tied predict and update as every other engine does. It ran both under
 * skip while the HVM's compiler read {@code JobGate.admitAt}'s result after its monitor exit
 * (docs/HVM.md, "Known compiler defects"; fixed by patch 23). Needs the tool chain (HVM_SRC);
 * skipped without it.
 */
class HvmCoincidingTimesTest extends CoincidingTimesTest {
    @BeforeAll
    static void needsTheHvm() throws Exception {
        HvmRunTest.assumeHvm();
    }
}
