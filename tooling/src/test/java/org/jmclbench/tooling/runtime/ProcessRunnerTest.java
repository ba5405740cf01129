package org.jmclbench.tooling.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

/** What the caller keeps of a child's output (probes and the aot training run a runtime under test). */
class ProcessRunnerTest {

    /** A runtime that floods its output: the caller keeps its beginning and its end, bounded. */
    @Test
    void aFloodedOutputKeepsItsBeginningAndEndWithinTheBound() {
        ProcessRunner.Result r = ProcessRunner.run(List.of("sh", "-c",
                "echo 'openjdk version \"17\"'; head -c 5000000 /dev/zero | tr '\\0' x; echo; echo 'died here'"), 60_000);
        assertEquals(0, r.exitCode());
        String out = r.stdout();
        assertTrue(out.length() <= ProcessRunner.MAX_OUTPUT_BYTES + 100, "kept " + out.length() + " characters");
        assertTrue(out.startsWith("openjdk version \"17\"\n"), out.substring(0, 40));
        assertTrue(out.endsWith("\ndied here\n"), out.substring(out.length() - 40));
        assertTrue(out.contains("[... " + (5000000 + 32 - ProcessRunner.MAX_OUTPUT_BYTES) + " bytes left out ...]"));
    }

    /** An ordinary output is kept whole. */
    @Test
    void anOrdinaryOutputIsKeptWhole() {
        ProcessRunner.Result r = ProcessRunner.run(List.of("sh", "-c", "echo one; echo two >&2"), 60_000);
        assertEquals("one\n", r.stdout());
        assertEquals("two\n", r.stderr());
    }

    /** A failure quotes the child's last line that says something, whatever padding follows it. */
    @Test
    void theLastLineSkipsPaddingAndTheJvmsEcho() {
        assertEquals("died here", ProcessRunner.lastLine("started\ndied here\n\0\0\0\n   \n\n"));
        assertEquals("Error: bad flag", ProcessRunner.lastLine("Error: bad flag\nPicked up JAVA_TOOL_OPTIONS: -Xss1m\n"));
        assertEquals("no message", ProcessRunner.lastLine("\0\0\n\n"));
        assertEquals("x".repeat(ProcessRunner.MAX_LAST_LINE), ProcessRunner.lastLine("x".repeat(5000)));
    }
}
