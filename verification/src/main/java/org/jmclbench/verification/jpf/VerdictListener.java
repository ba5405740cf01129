package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.Error;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.ListenerAdapter;
import gov.nasa.jpf.report.Statistics;
import gov.nasa.jpf.search.Search;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Properties;

/**
 * Writes a JPF run's outcome (errors, search constraints, statistics) as a properties file
 * named by {@code jmclbench.verdict}, so the host reads a structured verdict rather than
 * parsing JPF's console report.
 */
public final class VerdictListener extends ListenerAdapter {
    private final Path out;
    private String constraint;

    public VerdictListener(Config config, JPF jpf) {
        String file = config.getString("jmclbench.verdict");
        if (file == null) {
            throw new IllegalArgumentException("VerdictListener needs +jmclbench.verdict=FILE");
        }
        this.out = Paths.get(file);
    }

    @Override
    public void searchConstraintHit(Search search) {
        // A depth or memory limit means the search did not cover the whole state space.
        constraint = search.getLastSearchConstraint();
    }

    @Override
    public void searchFinished(Search search) {
        Properties p = new Properties();
        List<Error> errors = search.getErrors();
        p.setProperty("errors", Integer.toString(errors.size()));
        for (int i = 0; i < errors.size(); i++) {
            Error e = errors.get(i);
            p.setProperty("error." + i + ".property", e.getProperty().getClass().getSimpleName());
            // The details are what the property said when it was violated (the uncaught
            // exception with its stack, the deadlocked threads, the racing accesses).
            String d = e.getDetails();
            d = d == null ? "" : d.replaceAll("\\s+", " ").trim();
            p.setProperty("error." + i + ".message", d.length() > 4000 ? d.substring(0, 4000) : d);
        }
        if (constraint != null) {
            p.setProperty("constraint", constraint);
        }
        Statistics s = search.getVM().getJPF().getReporter().getStatistics();
        p.setProperty("states.new", Long.toString(s.newStates));
        p.setProperty("states.visited", Long.toString(s.visitedStates));
        p.setProperty("states.end", Long.toString(s.endStates));
        p.setProperty("maxDepth", Integer.toString(s.maxDepth));
        p.setProperty("instructions", Long.toString(s.insns));
        p.setProperty("done", "true");
        try (Writer w = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
            p.store(w, "jmclbench JPF verdict");
        } catch (IOException e) {
            throw new IllegalStateException("cannot write " + out, e);
        }
    }
}
