package org.jmclbench.verification;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import java.util.stream.Collectors;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.jpf.JpfCheck;
import org.junit.jupiter.api.Test;

/** The mission's catalog covers the policies of the one definition, not a list of its own. */
class MissionChecksTest {
    @Test
    void everyPolicyHasItsSearchInEachStyleAndItsRaceSearch() {
        Set<String> ids = MissionChecks.all().stream().map(JpfCheck::id).collect(Collectors.toSet());
        for (OverrunPolicy p : OverrunPolicy.values()) {
            for (String style : MissionChecks.STYLES) {
                assertTrue(ids.contains("mission-" + style + "-" + p.label), p.label + ", " + style + ": " + ids);
            }
            assertTrue(ids.contains("mission-race-" + p.label), p.label + ": " + ids);
        }
    }
}
