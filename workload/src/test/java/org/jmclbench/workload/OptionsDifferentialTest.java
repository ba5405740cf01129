package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import org.jmclbench.workload.testing.NativeBuild;
import org.junit.jupiter.api.Test;

/**
 * The Java and C command-line parsers against each other on the options they share (the
 * thesis's flags and the long options; not --engine, --area-size, --load-*, --rtsj-design of
 * Java or --no-fifo, --version of C): generated argument lists, good and bad, must give the same
 * options or the same one-line message. The C side is native/tests/options_dump.c.
 */
class OptionsDifferentialTest {
    private static final String[] FLAGS = {"-T", "--ideal", "-c", "--covariance", "--gc-log", "--no-cpu-time", "--force",
        "-h", "--help"};
    private static final String[][] VALUED = {{"-p", "--particles"}, {"-n", "--number"}, {"-j", "--runtime-name"},
        {"-O", "--out"}, {"-odo", "--odo"}, {"-laser", "--laser"}, {"-real", "--real"}, {"--dataset"}, {"--policy"},
        {"--memory"}, {"--estimate"}, {"--resample"}, {"--init"}, {"--seed"}, {"--time-scale"}, {"--warmup"},
        {"--spin-us"}};
    private static final String[] NUMBERS = {"400", "0", "-1", "+5", "007", "100000000", "100000001", "2147483647",
        "2147483648", "9223372036854775807", "9223372036854775808", "-9223372036854775808", " 4", "4 ", "1e3", "0.5",
        ".5", "1.", "-0", "0x10", "0x1p-1", "1d", "2f", "NaN", "inf", "Infinity", "1e400", "1e-400", "", "abc",
        "\u0664\u0660\u0660", "1_000", "1,5", "+.5e-1", "-.5"};
    private static final String[] WORDS = {"skip", "terminate", "queue", "Skip", "mean", "best", "systematic",
        "multinomial", "known", "uniform", "", "x"};
    private static final String[] MEMORY = {"preallocated", "allocating"};
    private static final String[] NAMES = {"local", "out", "a/b", "data/match", "", "..", ".", "x+y_1.2-3", "a b",
        "-p", "--force", "run"};
    private static final String[] STRAY = {"run", "foo", "-x", "--bogus", "--bogus=1", "-p=4", "--", "-", "",
        "--ideal=1", "--covariance=", "-odo=a", "--=x", "--no-cpu-time=1", "--no-cpu"};

    @Test
    void generatedCommandLinesParseAlike() throws IOException {
        Random random = new Random(22);
        List<List<String>> lines = new ArrayList<>();
        for (int i = 0; i < 5000; i++) {
            lines.add(commandLine(random));
        }
        int accepted = parseAlike(lines);
        assertTrue(accepted > lines.size() / 5 && accepted < lines.size() * 4 / 5, accepted + " of " + lines.size()
                + " accepted");
    }

    /** What an ideal run cannot apply: both parsers refuse it alike (the generated lines seldom hold it). */
    @Test
    void theIdealRunsRefusalsParseAlike() throws IOException {
        List<List<String>> lines = new ArrayList<>();
        lines.add(Arrays.asList("--ideal", "--spin-us", "50"));
        lines.add(Arrays.asList("--spin-us=1", "run", "--ideal"));
        lines.add(Arrays.asList("-T", "--policy", "skip", "--ideal", "--spin-us", "5"));
        lines.add(Arrays.asList("--ideal", "--spin-us", "+0"));
        lines.add(Arrays.asList("--ideal", "--spin-us", "50", "-h"));
        assertEquals(2, parseAlike(lines));
    }

    /** Gives each command line to both parsers and asserts the same answer; returns how many were accepted. */
    private static int parseAlike(List<List<String>> lines) throws IOException {
        Process c = new ProcessBuilder(NativeBuild.target("build/options_dump").getPath(), "--serve")
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        OutputStream requests = c.getOutputStream();
        BufferedReader answers = new BufferedReader(new InputStreamReader(c.getInputStream(), StandardCharsets.UTF_8));
        int accepted = 0;
        try {
            for (int i = 0; i < lines.size(); i++) {
                List<String> args = lines.get(i);
                byte[] body = String.join("\0", args).getBytes(StandardCharsets.UTF_8);
                requests.write(("args " + args.size() + " " + body.length + "\n").getBytes(StandardCharsets.US_ASCII));
                requests.write(body);
                requests.flush();
                String cAnswer = answers.readLine();
                assertEquals("end", answers.readLine());
                String java = java(args.toArray(new String[0]));
                assertEquals(cAnswer, java, "case " + i + ": " + args);
                accepted += java.startsWith("ok") ? 1 : 0;
            }
        } finally {
            requests.close();
            NativeBuild.waitFor(c);
        }
        return accepted;
    }

    private static String pick(Random r, String[] pool) {
        return pool[r.nextInt(pool.length)];
    }

    private static List<String> commandLine(Random r) {
        List<String> args = new ArrayList<>();
        if (r.nextBoolean()) {
            args.add("run");
        }
        int n = r.nextInt(6);
        for (int k = 0; k < n; k++) {
            int what = r.nextInt(20);
            if (what < 4) {
                args.add(pick(r, FLAGS));
            } else if (what == 4) {
                args.add(pick(r, STRAY));
            } else {
                String[] names = VALUED[r.nextInt(VALUED.length)];
                String name = names[r.nextInt(names.length)];
                String value = value(r, name);
                if (name.startsWith("--") && r.nextInt(3) == 0) {
                    args.add(name + "=" + value);
                } else {
                    args.add(name);
                    if (r.nextInt(30) != 0 || name.equals("--memory")) { // Java's memory list is longer
                        args.add(value);
                    }
                }
            }
        }
        return args;
    }

    private static String value(Random r, String name) {
        switch (name) {
            case "--policy":
            case "--estimate":
            case "--resample":
            case "--init":
                return r.nextInt(3) == 0 ? pick(r, WORDS) : pick(r, WORDS).toLowerCase(Locale.ROOT);
            case "--memory":
                return pick(r, MEMORY); // Java's third style (scoped) is the scj engine's, not C's
            case "-j":
            case "--runtime-name":
            case "-O":
            case "--out":
            case "-odo":
            case "--odo":
            case "-laser":
            case "--laser":
            case "-real":
            case "--real":
            case "--dataset":
                return pick(r, NAMES);
            default:
                return pick(r, NUMBERS);
        }
    }

    /** The Java parser's answer in options_dump.c's words. */
    private static String java(String[] args) {
        RunOptions o;
        try {
            o = RunOptionsParser.parse(args);
        } catch (BadInputException e) {
            return "error " + e.getMessage();
        }
        if (o.help) {
            return "ok help";
        }
        return String.format(Locale.ROOT, "ok p=%d n=%d j=%s O=%s odo=%s laser=%s real=%s dataset=%s policy=%s "
                + "ideal=%d cov=%d memory=%s estimate=%s resample=%s init=%s seed=%d scale=%016x warmup=%016x "
                + "spin=%d gclog=%d cputime=%d force=%d", o.particles, o.number, o.runtimeName == null ? "native" : o.runtimeName,
                o.out, none(o.odo), none(o.laser), none(o.real), none(o.dataset), o.policy.label, o.ideal ? 1 : 0,
                o.covariance ? 1 : 0, lower(o.memory), lower(o.estimate), lower(o.resample), lower(o.init), o.seed,
                Double.doubleToRawLongBits(o.timeScale), Double.doubleToRawLongBits(o.warmupS), o.spinUs,
                o.gcLog ? 1 : 0, o.cpuTime ? 1 : 0, o.force ? 1 : 0);
    }

    private static String none(String s) {
        return s == null ? "(none)" : s;
    }

    private static String lower(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT);
    }
}
