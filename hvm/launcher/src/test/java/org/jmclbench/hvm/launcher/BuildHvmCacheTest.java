package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.security.MessageDigest;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * The pinned commit's tarball and its clone are one source: build-hvm.sh keys both to one cache
 * entry, so a tool chain built from the tarball serves a user without HVM_SRC (and the reverse).
 * Needs HVM_SRC to be that tarball (as .ci/run sets it); skipped otherwise.
 */
class BuildHvmCacheTest {
    private static final String PINNED_TARBALL_SHA256 = "07e4964499f7c85a7649e302c5f7b9fe8cdfa7df80928eb4549b06704c56f2fb";
    private static final Pattern FOLDER = Pattern.compile("\\((?:cached|not cached yet): (\\S+)\\)");

    @Test
    void thePinnedTarballAndTheCloneShareOneToolChain() throws Exception {
        String src = System.getenv("HVM_SRC");
        Assumptions.assumeTrue(src != null && Files.isRegularFile(Paths.get(src))
                && PINNED_TARBALL_SHA256.equals(sha256(Paths.get(src))), "HVM_SRC is not the pinned tarball");
        File home = HvmRunTest.projectHome();
        Assumptions.assumeTrue(home != null, "no hvm/ folder above the working directory");
        Path script = home.toPath().resolve("hvm/build-hvm.sh");
        String fromTarball = toolChainFolder(script, src);
        String fromClone = toolChainFolder(script, null);
        assertEquals(fromTarball, fromClone);
    }

    private static String toolChainFolder(Path script, String hvmSrc) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(script.toString(), "--check").redirectErrorStream(true);
        if (hvmSrc == null) {
            pb.environment().remove("HVM_SRC");
        } else {
            pb.environment().put("HVM_SRC", hvmSrc);
        }
        Process p = pb.start();
        String out = new String(HvmRunTest.readAll(p), StandardCharsets.UTF_8).trim();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "build-hvm.sh --check hung");
        Assumptions.assumeTrue(p.exitValue() == 0, "the tool chain cannot be built here: " + out);
        Matcher m = FOLDER.matcher(out);
        assertTrue(m.find(), out);
        return m.group(1);
    }

    private static String sha256(Path file) throws Exception {
        StringBuilder hex = new StringBuilder();
        for (byte b : MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(file))) {
            hex.append(String.format("%02x", b));
        }
        return hex.toString();
    }
}
