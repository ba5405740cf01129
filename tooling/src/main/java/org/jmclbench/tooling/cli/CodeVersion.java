package org.jmclbench.tooling.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;

import picocli.CommandLine.IVersionProvider;

/**
 * Which jmclbench code this is: the git commit the tooling was built from (written into the jar at
 * build time), with {@code -dirty} when that tree had uncommitted changes. Every run the tooling
 * stores carries it, so that runs of different code are never pooled unnoticed, as JMH prints its
 * own version with every result.
 */
public final class CodeVersion implements IVersionProvider {

    /** The release the command line reports beside the commit. */
    public static final String RELEASE = "0.1.0";

    private static final String RESOURCE = "/org/jmclbench/tooling/git.properties";
    private static final String CURRENT = read(CodeVersion.class.getResourceAsStream(RESOURCE));

    /** The commit, as {@code 01113ea} or {@code 01113ea-dirty}; null when the tooling was not built in a git checkout. */
    public static String current() {
        return CURRENT;
    }

    /** Reads a git.properties file as the build writes it; null when there is none or it names no commit. */
    static String read(InputStream in) {
        if (in == null) {
            return null;
        }
        Properties p = new Properties();
        try (in) {
            p.load(in);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        String commit = p.getProperty("git.commit.id.abbrev", "").trim();
        if (commit.isEmpty()) {
            return null;
        }
        return Boolean.parseBoolean(p.getProperty("git.dirty")) ? commit + "-dirty" : commit;
    }

    @Override
    public String[] getVersion() {
        return new String[] {"jmclbench " + RELEASE + " (" + (CURRENT == null ? "built outside git: no commit" : "commit " + CURRENT) + ")"};
    }
}
