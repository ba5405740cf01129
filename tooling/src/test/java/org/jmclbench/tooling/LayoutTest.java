package org.jmclbench.tooling;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Two bounds of the layout that keep the code readable in an hour: no main source file grows past
 * 600 lines (a longer one has grown a second purpose), and every module says in a README what it
 * is for. Files are read from the working tree, as a newcomer would open them.
 */
class LayoutTest {
    private static final int MAX_LINES = 600;
    private static final List<String> MODULES = List.of("core-immortal", "rtsj-compat", "rtsj-weaver", "scj-mission",
            "workload", "hvm", "native", "tooling", "bench", "verification", "conformance");
    private static final Set<String> SKIPPED = Set.of(".git", "target", "build", "results", "node_modules");

    @Test
    void noMainSourceFileIsOverSixHundredLines() throws IOException {
        Path home = Fixtures.projectHome();
        List<String> tooLong = new ArrayList<>();
        Files.walkFileTree(home, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                // build output, results and git's objects are not source, and can be large
                return SKIPPED.contains(dir.getFileName() == null ? "" : dir.getFileName().toString())
                        ? FileVisitResult.SKIP_SUBTREE : FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                if (isMainSource(home.relativize(file).toString().replace('\\', '/'))) {
                    long lines = lines(file);
                    if (lines > MAX_LINES) {
                        tooLong.add(home.relativize(file) + " (" + lines + " lines)");
                    }
                }
                return FileVisitResult.CONTINUE;
            }
        });
        Collections.sort(tooLong);
        assertEquals(List.of(), tooLong, "main source files over " + MAX_LINES + " lines: split them where a second purpose has grown");
    }

    @Test
    void everyModuleHasAReadme() {
        Path home = Fixtures.projectHome();
        assertEquals(List.of(), MODULES.stream().filter(m -> !Files.isRegularFile(home.resolve(m).resolve("README.md"))).toList());
    }

    /** Shipped code: Java and JavaScript under src/main, and the C baseline's sources; never tests. */
    static boolean isMainSource(String path) {
        boolean java = path.contains("/src/main/") && (path.endsWith(".java") || path.endsWith(".js"));
        boolean c = path.startsWith("native/src/") && (path.endsWith(".c") || path.endsWith(".h"));
        return java || c;
    }

    private static long lines(Path p) {
        try (Stream<String> s = Files.lines(p)) {
            return s.count();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
