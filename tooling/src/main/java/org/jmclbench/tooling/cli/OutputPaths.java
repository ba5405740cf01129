package org.jmclbench.tooling.cli;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Folders a command is to write, checked before it runs or reads anything: a folder that cannot
 * be made there (a file in its place or above it, a folder that cannot be written) would
 * otherwise fail the command at its end, after a long run, with a stack trace or exit code 1.
 */
public final class OutputPaths {

    private OutputPaths() {
    }

    /**
     * Why the folder {@code dir} cannot be made or written, or null when it can: it must be a folder,
     * or not exist yet below a folder that can be written. The reason names the path at fault
     * ({@code /a/b is a file}: {@code dir} itself, or a file above it).
     */
    public static String whyNotAFolder(Path dir) {
        Path abs = dir.toAbsolutePath().normalize();
        Path p = abs;
        while (p != null && !Files.exists(p)) {
            p = p.getParent();
        }
        if (p == null) {
            return null; // nothing on the path exists (not even the root): let the write say why
        }
        if (!Files.isDirectory(p)) {
            return p + " is a file";
        }
        return Files.isWritable(p) ? null : p + " cannot be written";
    }

    /**
     * Refuses a folder option that cannot be one.
     *
     * @throws BadUsageException {@code option: dir: not a folder} or {@code option: dir: cannot write there (why)}
     *                           (exit code 2)
     */
    public static void checkFolder(Path dir, String option) {
        if (Files.isRegularFile(dir)) {
            throw BadUsageException.ofOption(option, dir + ": not a folder");
        }
        String why = whyNotAFolder(dir);
        if (why != null) {
            throw BadUsageException.ofOption(option, dir + ": cannot write there (" + why + ")");
        }
    }
}
