package org.jmclbench.tooling.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

class CodeVersionTest {

    private static String read(String properties) {
        return CodeVersion.read(new ByteArrayInputStream(properties.getBytes(StandardCharsets.ISO_8859_1)));
    }

    @Test
    void aCleanTreeIsItsCommitAndAChangedOneIsMarkedDirty() {
        assertEquals("01113ea", read("git.commit.id.abbrev=01113ea\ngit.dirty=false\n"));
        assertEquals("01113ea-dirty", read("git.commit.id.abbrev=01113ea\ngit.dirty=true\n"));
    }

    @Test
    void aBuildOutsideGitHasNoVersionRatherThanAMadeUpOne() {
        assertNull(CodeVersion.read(null), "no git.properties in the jar");
        assertNull(read("git.dirty=false\n"), "the plugin found no repository and wrote no commit");
    }

    @Test
    void theBuildWroteTheCheckoutsCommit() throws Exception {
        Path root = Path.of("").toAbsolutePath().getParent(); // surefire runs in tooling/
        Assumptions.assumeTrue(Files.exists(root.resolve(".git")), "not a git checkout");
        Process git = new ProcessBuilder("git", "-C", root.toString(), "rev-parse", "HEAD").redirectErrorStream(true).start();
        String head = new String(git.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        Assumptions.assumeTrue(git.waitFor() == 0, "git cannot read the checkout: " + head);
        String current = CodeVersion.current();
        assertNotNull(current, "git.properties is missing from the build");
        assertTrue(current.startsWith(head.substring(0, 7)), current + " is not HEAD " + head);
        assertEquals("jmclbench " + CodeVersion.RELEASE + " (commit " + current + ")", new CodeVersion().getVersion()[0]);
    }
}
