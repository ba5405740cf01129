package org.jmclbench.tooling.runner;

import java.nio.file.Path;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the matrix tests start from: a home with the test datasets, a store path that does not
 * exist yet ({@code out/results.db}) and one fake JVM (Java 21) whose runs succeed.
 */
abstract class FakeJvmHome {
    @TempDir
    Path dir;
    Path db;
    Path fake;

    @BeforeEach
    void setUpHome() throws Exception {
        Fixtures.home(dir);
        db = dir.resolve("out/results.db");
        fake = Fixtures.fakeJava(dir, "jvm", "ok", 0, null, 21);
    }
}
