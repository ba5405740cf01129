package org.jmclbench.verification;

import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfHome;
import org.jmclbench.verification.jpf.JpfResult;
import org.jmclbench.verification.jpf.JpfRunner;
import org.jmclbench.verification.toy.ToyChecks;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import java.nio.file.Paths;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The JPF machinery on a small SCJ-like program: every property holds on the correct program,
 * and JPF reports exactly the seeded violation for each seeded bug.
 */
class ToyMissionJpfTest {

    @TestFactory
    Stream<DynamicTest> everyPropertyHoldsAndEverySeededBugIsCaught() {
        JpfRunner runner = new JpfRunner(JpfHome.locate(), JpfRunner.currentClassPath(),
                Paths.get("target", "jpf-logs"), 120, 1024);
        return ToyChecks.all().stream().map(c -> DynamicTest.dynamicTest(c.id(), () -> {
            JpfResult r = runner.run(c);
            System.out.printf("%-40s %-10s %8d states %6.1f s  %s%n", c.id(), c.policy(), r.newStates(),
                    r.seconds(), r.verdict());
            assertTrue(r.passed(), c.id() + ": " + r.verdict() + " (log " + r.log() + ")");
        }));
    }
}
