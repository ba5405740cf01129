package org.jmclbench.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The benchmark scripts treat a bad command line as bad input, as every jmclbench command does:
 * one line that names the script and the option, exit 2, before anything is built or run. An
 * option given last without its value used to end in bash's own "parameter null or not set"
 * message with exit 1.
 */
class ScriptOptionsTest {

    @ParameterizedTest(name = "{0} {1}")
    @CsvSource({
            "atc-latency, --aborts", "atc-latency, --java",
            "crosscheck, --generate",
            "hvm-compare, --particles", "hvm-compare, -O",
            "kernel-ratio, --out",
            "record-cost, --java", "record-cost, --out",
            "fuzz, --seconds",
            "kill-trials, --keep",
            "overload, --policies",
            "release-accuracy, --spin-us",
            "scj-overhead, --repeat"})
    void anOptionWithoutItsValueIsOneLineAndExit2(String script, String option) throws Exception {
        assertBadInput(script, script + ": " + option + ": needs a value", option);
    }

    @ParameterizedTest(name = "{0} {1} {2}")
    @CsvSource({
            "atc-latency, --warmup, -3, not a count",
            "release-accuracy, --loops-1ms, 1x, not a positive count",
            "scj-overhead, --particles, many, not a positive count",
            "kill-trials, --seed, x, not a count",
            // counts the Java programs would refuse only after the build, or read as 'forever'
            "atc-latency, --aborts, 0, not a positive count",
            "atc-latency, --work, 99999999999, not a count",
            "release-accuracy, --loops-50ms, 0, not a positive count",
            "fuzz, --seconds, 0, not a positive count",
            "crosscheck, --cases, 0, not a positive count",
            "crosscheck, --first, 1e3, not a count",
            "fuzz, --runs, lots, not a count",
            // lists and choices each run would refuse only after a build, the loop going on past it
            "hvm-compare, --particles, '100,x', not a positive count",
            "hvm-compare, --policy, never, not one of skip|terminate|queue",
            "hvm-compare, --hvm-modes, 'compiled,jit', not one of compiled|interpreted|hot",
            "hvm-compare, --dataset, no-such-dataset, no such dataset",
            "kernel-ratio, --particles, '1000,0', not a positive count",
            "kernel-ratio, --dataset, /no/such/dataset, not a dataset folder",
            "overload, --particles, '400 many', not a positive count",
            "overload, --policies, 'skip never', not one of skip|terminate|queue",
            "overload, --warmup, -2, not a number",
            "scj-overhead, --policy, never, not one of skip|terminate|queue",
            // an output folder below a file
            "kernel-ratio, --out, pom.xml/out, cannot be created",
            "fuzz, --work, pom.xml/work, cannot be created",
            "kill-trials, --keep, pom.xml/keep, cannot be created",
            "record-cost, --out, pom.xml/out, cannot be created",
            "record-cost, --java, /no/such/java, not found"})
    void aValueOfTheWrongKindNamesItsOption(String script, String option, String value, String what) throws Exception {
        assertBadInput(script, script + ": " + option + ": ", option, value);
        assertTrue(run(script, option, value).get(0).contains(what), what);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"atc-latency", "hvm-compare", "kernel-ratio", "kill-trials", "overload", "release-accuracy",
            "scj-overhead", "report-build", "record-cost", "options"})
    void anUnknownOptionIsOneLineAndExit2(String script) throws Exception {
        assertBadInput(script, script + ": --no-such-option: unknown option", "--no-such-option");
    }

    /** report-build takes one RUNS: a second one was silently ignored, and 0 built an empty store. */
    @Test
    void reportBuildTakesOnePositiveRunCount() throws Exception {
        assertBadInput("report-build", "report-build: 20: unexpected argument", "10", "20");
        assertBadInput("report-build", "report-build: RUNS: 0: not a positive count", "0");
    }

    /**
     * scj-overhead checked --repeat with its own pattern, which took a count past an int (and would
     * have started that many runs); it is options.sh's positive count now. The missing dataset after
     * it keeps a regression from starting the benchmark.
     */
    @Test
    void scjOverheadTakesNoRepeatCountPastAnInt() throws Exception {
        assertBadInput("scj-overhead", "scj-overhead: --repeat: 99999999999: not a positive count (1 to 2147483647)",
                "--repeat", "99999999999", "--dataset", "/no/such/dataset");
    }

    private static void assertBadInput(String script, String prefix, String... args) throws Exception {
        List<String> out = run(script, args);
        assertEquals("2", out.get(out.size() - 1), "exit status; output: " + out);
        assertEquals(2, out.size(), "one line of error, then the status: " + out);
        assertTrue(out.get(0).startsWith(prefix), out.get(0));
    }

    /** The script's output lines (stdout and stderr merged), then its exit status. */
    private static List<String> run(String script, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(Arrays.asList("bash", new File(benchFolder(), script + ".sh").getPath()));
        cmd.addAll(Arrays.asList(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        p.getOutputStream().close();
        List<String> lines = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line; (line = r.readLine()) != null; ) {
                lines.add(line);
            }
        }
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), script + " did not end");
        lines.add(Integer.toString(p.exitValue()));
        return lines;
    }

    private static File benchFolder() {
        File dir = new File("").getAbsoluteFile();
        while (dir != null && !new File(dir, "bench/atc-latency.sh").isFile()) {
            dir = dir.getParentFile();
        }
        assertTrue(dir != null, "bench/ not found");
        return new File(dir, "bench");
    }
}
