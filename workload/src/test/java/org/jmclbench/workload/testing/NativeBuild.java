package org.jmclbench.workload.testing;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.Set;

/** Programs of the C baseline that Java tests run, built by its Makefile (once per JVM and target). */
public final class NativeBuild {
    /** The project's root: the nearest folder above the running module's that holds native/Makefile. */
    public static final File HOME = projectRoot(new File(System.getProperty("user.dir")).getAbsoluteFile());

    private static File projectRoot(File module) {
        for (File d = module; d != null; d = d.getParentFile()) {
            if (new File(d, "native/Makefile").isFile()) {
                return d;
            }
        }
        return module.getParentFile();
    }

    private static final Set<String> BUILT = new HashSet<>();

    private NativeBuild() {
    }

    /** native/TARGET (e.g. {@code build/jmclbench-native}), made up to date first. */
    public static synchronized File target(String target) throws IOException {
        File nativeDir = new File(HOME, "native");
        if (BUILT.add(target)) {
            Process p = new ProcessBuilder("make", "-s", "-C", nativeDir.getPath(), target).redirectErrorStream(true)
                    .start();
            String out = readAll(p.getInputStream());
            if (waitFor(p) != 0) {
                BUILT.remove(target);
                throw new IOException("make -C native " + target + " failed: " + out);
            }
        }
        return new File(nativeDir, target);
    }

    /** Everything a stream holds, as ISO-8859-1 (bytes as they are). */
    public static String readAll(InputStream in) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] buf = new byte[8192];
        int n;
        while ((n = in.read(buf)) > 0) {
            b.write(buf, 0, n);
        }
        return new String(b.toByteArray(), StandardCharsets.ISO_8859_1);
    }

    /** The process's exit code. */
    public static int waitFor(Process p) throws IOException {
        try {
            return p.waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }
}
