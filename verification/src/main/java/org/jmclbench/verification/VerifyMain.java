package org.jmclbench.verification;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import org.jmclbench.verification.bytecode.ClassPool;
import org.jmclbench.verification.bytecode.Violation;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfHome;
import org.jmclbench.verification.jpf.JpfResult;
import org.jmclbench.verification.jpf.JpfRunner;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.stream.Stream;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./jmclbench verify}: runs every catalogue's static and JPF checks, prints the table
 * (check, property, policy, verdict, states, seconds), writes {@code results/verification.json}, and
 * exits 0 only when every property holds and every seeded bug is caught.
 *
 * <p>{@code --only} runs the checks whose id starts with one of the prefixes (a partial run: it
 * writes no results file unless {@code --out} is given). {@code --fail-fast} stops at the first
 * check that fails (the mutation score's runs: one failure is a caught mutant). The class path
 * holds the project's classes; the seeded bugs' catalogue is in verification's test classes, and
 * verify fails when it is missing (no check may pass unseeded).
 */
@Command(sortOptions = false, description = "Java PathFinder and bytecode checks of the SCJ mission"
        + " and the rtsj engine; exits 0 only when every property holds and every seeded bug is caught.")
public final class VerifyMain {
    /** The per-check budget of issue 11: 2 minutes; the heap cap keeps the JVM under 1.5 GB. */
    static final int TIMEOUT_SECONDS = 120;
    static final int HEAP_MB = 1200;

    @Option(names = "--out", paramLabel = "FILE", description = "the results file (default results/verification.json;"
            + " none for a run with --only)")
    private Path out;
    @Option(names = "--logs", paramLabel = "DIR", description = "each JPF check's log (default ${DEFAULT-VALUE})")
    private Path logs = Paths.get("results", "verification");
    @Option(names = "--timeout", paramLabel = "SECONDS", converter = CommandLines.Positive.class,
            description = "each JPF check's wall-clock budget (default ${DEFAULT-VALUE})")
    private int timeout = TIMEOUT_SECONDS;
    @Option(names = "--heap", paramLabel = "MB", converter = CommandLines.Positive.class,
            description = "each JPF check's heap (default ${DEFAULT-VALUE})")
    private int heap = HEAP_MB;
    @Option(names = "--only", paramLabel = "PREFIX", split = ",",
            description = "only the checks whose id starts with one of these (for example mission-,P4)")
    private List<String> only;
    @Option(names = "--fail-fast", description = "stop at the first check that fails")
    private boolean failFast;
    @Option(names = {"-h", "--help"}, usageHelp = true, description = "this help")
    private boolean help;

    private VerifyMain() {}

    public static void main(String[] args) throws Exception {
        VerifyMain options = new VerifyMain();
        Integer exit = CommandLines.parse(options, "verify", args, System.out, System.err);
        if (exit != null) {
            System.exit(exit);
        }
        Path out = options.out;
        if (out == null && options.only == null) {
            out = Paths.get("results", "verification.json");
        }
        // Before any check: the results file is written at the end, after minutes of checks.
        String bad = badOptions(out, options.logs, options.only);
        if (bad != null) {
            System.exit(CommandLines.bad(System.err, "verify", bad));
        }
        System.exit(run(out, options.logs, options.timeout, options.heap, options.only, options.failFast));
    }

    /**
     * What is wrong with the options, or null: an empty {@code --only} prefix (it selects every
     * check, a whole run taken for a partial one), an {@code --out} that is a folder (the results
     * file would replace it when empty) or below a file, {@code --logs} that is a file or below one.
     */
    static String badOptions(Path out, Path logs, List<String> only) {
        if (only != null && (only.isEmpty() || only.stream().anyMatch(String::isEmpty))) {
            return "--only: an empty prefix selects every check (give check id prefixes, for example mission-,P4)";
        }
        if (out != null) {
            if (Files.isDirectory(out)) {
                return "--out: " + out + " is a folder, not a results file";
            }
            Path file = fileAbove(out);
            if (file != null) {
                return "--out: " + out + ": " + file + " is not a folder";
            }
        }
        if (Files.exists(logs) && !Files.isDirectory(logs)) {
            return "--logs: " + logs + " is not a folder";
        }
        Path file = fileAbove(logs);
        if (file != null) {
            return "--logs: " + logs + ": " + file + " is not a folder";
        }
        return null;
    }

    /**
     * Why the results file cannot be written at {@code out}, or null: a scratch file is made and
     * removed in the nearest existing folder above it, so that a read-only place is bad usage
     * before the checks, not an exception after all of them.
     */
    static String unwritable(Path out) {
        Path folder = out.toAbsolutePath().getParent();
        while (folder != null && !Files.isDirectory(folder)) {
            folder = folder.getParent();
        }
        if (folder == null) {
            return null; // no folder above it at all: badOptions has named the file in the way
        }
        try {
            Files.delete(Files.createTempFile(folder, "verification", ".probe"));
            return null;
        } catch (IOException | SecurityException e) {
            return "--out: " + out + ": cannot write in " + folder + " (" + e.getClass().getSimpleName() + ")";
        }
    }

    /** The nearest existing ancestor of {@code path} when it is not a folder, else null. */
    private static Path fileAbove(Path path) {
        for (Path p = path.toAbsolutePath().getParent(); p != null; p = p.getParent()) {
            if (Files.exists(p)) {
                return Files.isDirectory(p) ? null : p;
            }
        }
        return null;
    }

    private static void usage(String message) {
        System.exit(CommandLines.bad(System.err, "verify", message));
    }

    static int run(Path out, Path logs, int timeout, int heap, List<String> only, boolean failFast)
            throws IOException, InterruptedException {
        long start = System.nanoTime();
        List<CheckCatalog> catalogs = new ArrayList<>();
        ServiceLoader.load(CheckCatalog.class).forEach(catalogs::add);
        List<Map<String, Object>> rows = new ArrayList<>();
        boolean ok = true;
        boolean seeded = false;
        List<String> classPath = JpfRunner.currentClassPath();
        ClassPool pool = ClassPool.of(classPath.stream().filter(e -> !e.isEmpty()).map(Paths::get)
                .filter(p -> !p.getFileName().toString().startsWith("jpf")).toList());
        JpfRunner runner = null;
        if (only != null) {
            // Each prefix must select a check: a misspelt one beside a good one ran fewer checks, and passed.
            List<String> ids = catalogs.stream().flatMap(c -> Stream.concat(c.staticChecks().stream().map(StaticCheck::id),
                    c.jpfChecks().stream().map(JpfCheck::id))).toList();
            List<String> unmatched = only.stream().filter(p -> ids.stream().noneMatch(id -> id.startsWith(p)))
                    .distinct().toList();
            if (!unmatched.isEmpty()) {
                usage("--only: no check id starts with " + String.join(" or ", unmatched));
            }
        }
        if (out != null) {
            String unwritable = unwritable(out);
            if (unwritable != null) {
                usage(unwritable);
            }
        }
        if (catalogs.stream().flatMap(c -> c.jpfChecks().stream()).anyMatch(c -> selected(c.id(), only))) {
            // A heap no JVM can reserve failed every JPF check (exit 1): it is the option that is wrong.
            JpfHome jpf;
            try {
                jpf = JpfHome.locate();
            } catch (JpfHome.MissingException e) {
                // before the table and the results file: JPF's absence is no check's failure
                System.err.println("jmclbench: verify: " + e.getMessage());
                System.exit(e.given() ? CommandLines.EXIT_BAD_INPUT : 1);
                return 1;
            }
            runner = new JpfRunner(jpf, classPath, logs, timeout, heap);
            String refused = runner.unstartable();
            if (refused != null) {
                usage("--heap: " + heap + " MB: no JVM starts with it (" + refused + ")");
            }
        }
        System.out.printf("%-34s %-48s %-9s %-8s %9s %8s%n", "check", "property", "policy", "verdict", "states",
                "seconds");
        checks:
        for (CheckCatalog catalog : catalogs) {
            for (StaticCheck s : catalog.staticChecks()) {
                if (failFast && !ok) {
                    break checks;
                }
                if (!selected(s.id(), only)) {
                    continue;
                }
                long t0 = System.nanoTime();
                List<Violation> found = s.run(pool);
                double secs = (System.nanoTime() - t0) / 1e9;
                boolean met = s.met(found);
                seeded |= !s.expected().isEmpty();
                ok &= met;
                String verdict = verdictOf(met, !s.expected().isEmpty());
                print(s.id(), s.propertyText(), "-", verdict, "-", secs);
                if (!met || !s.expected().isEmpty()) {
                    for (Violation v : found) {
                        System.out.println("    " + v);
                    }
                }
                Map<String, Object> row = row(catalog.name(), s.id(), s.propertyText(), List.of(s.property()), "-", "static", verdict, met,
                        !s.expected().isEmpty(), secs);
                row.put("failure", met ? null : s.expected().isEmpty() ? "violation" : "missed");
                row.put("violations", found.stream().map(Violation::toString).toList());
                rows.add(row);
            }
            for (JpfCheck c : catalog.jpfChecks()) {
                if (failFast && !ok) {
                    break checks;
                }
                if (!selected(c.id(), only)) {
                    continue;
                }
                JpfResult r = runner.run(c);
                seeded |= c.seeded();
                ok &= r.passed();
                String verdict = verdictOf(r.passed(), c.seeded());
                print(c.id(), c.propertyText(), c.policy(), verdict, Long.toString(r.newStates()), r.seconds());
                if (!r.passed()) {
                    System.out.println("    " + r.verdict() + " (log " + r.log() + ")");
                }
                Map<String, Object> row = row(catalog.name(), c.id(), c.propertyText(), c.properties(), c.policy(), "jpf", verdict,
                        r.passed(), c.seeded(), r.seconds());
                row.put("detail", r.verdict());
                row.put("failure", r.failure() == null ? null : r.failure().key());
                row.put("scope", c.scope());
                row.put("states", r.newStates());
                row.put("endStates", r.endStates());
                row.put("maxDepth", r.maxDepth());
                row.put("instructions", r.instructions());
                rows.add(row);
            }
        }
        if (!seeded && only == null) {
            System.out.println("no seeded bug ran: the verification's test classes are not on the class path,"
                    + " so no check is known to be able to fail");
            ok = false;
        }
        double total = (System.nanoTime() - start) / 1e9;
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("schema", 1);
        doc.put("finished", Instant.now().toString());
        doc.put("passed", ok);
        doc.put("seconds", Math.round(total * 10) / 10.0);
        doc.put("budget", Map.of("checkSeconds", timeout, "heapMegabytes", heap));
        doc.put("checks", rows);
        // The static side of termination (issue 19), for the report to draw beside the measured abort latency.
        List<Map<String, Object>> bounds = AbortBoundMain.allBounds(pool);
        doc.put("abortBounds", bounds);
        for (Map<String, Object> b : bounds) {
            if ("preallocated".equals(b.get("memory"))) {
                System.out.printf("abort bound: %-12s %s%n", b.get("engine"), b.get("steps") == null
                        ? "the whole job (no abort point bounds it)" : b.get("steps") + " particle steps, at " + b.get("at"));
            }
        }
        if (out != null) {
            if (only != null) {
                doc.put("only", only);
            }
            Path parent = out.toAbsolutePath().getParent();
            Files.createDirectories(parent);
            Path tmp = Files.createTempFile(parent, "verification", ".json.partial");
            new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValue(tmp.toFile(), doc);
            Files.move(tmp, out, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        long failed = rows.stream().filter(r -> !(Boolean) r.get("passed")).count();
        System.out.printf(Locale.ROOT, "verify: %s in %.0f s (%s)%n", ok ? (only == null
                ? "every property holds and every seeded bug is caught" : "every selected check passed")
                : failed + " check(s) failed", total, out == null ? "partial run, no results file written" : out);
        System.out.println("verification: " + (rows.size() - failed) + " passed, " + failed + " failed");
        return ok ? 0 : 1;
    }

    private static boolean selected(String id, List<String> only) {
        return only == null || only.stream().anyMatch(id::startsWith);
    }

    private static String verdictOf(boolean passed, boolean seeded) {
        if (seeded) {
            return passed ? "caught" : "MISSED";
        }
        return passed ? "holds" : "FAILS";
    }

    private static void print(String id, String property, String policy, String verdict, String states, double secs) {
        System.out.printf(Locale.ROOT, "%-34s %-48s %-9s %-8s %9s %8.1f%n", id,
                property.length() > 48 ? property.substring(0, 47) + "~" : property, policy, verdict, states, secs);
    }

    private static Map<String, Object> row(String catalog, String id, String property,
                                           java.util.Collection<Property> properties, String policy, String kind,
                                           String verdict, boolean passed, boolean seeded, double secs) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("catalog", catalog);
        m.put("id", id);
        m.put("property", property);
        m.put("properties", properties.stream().sorted().map(Property::name).toList());
        m.put("policy", policy);
        m.put("kind", kind);
        m.put("seeded", seeded);
        m.put("verdict", verdict);
        m.put("passed", passed);
        m.put("seconds", Math.round(secs * 10) / 10.0);
        return m;
    }

    /** The entries of a class path string (for callers that have one). */
    static List<String> split(String cp) {
        return List.of(cp.split(File.pathSeparator));
    }
}
