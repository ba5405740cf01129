package org.jmclbench.tooling.load;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.jmclbench.tooling.cli.BadUsageException;

/** The load a run carries beside its own work: one dimension of the matrix ({@code --load}). */
public enum LoadScenario {
    /** An idle machine (as idle as it is). */
    NONE,
    /** Every CPU busy with other processes: stress-ng, else busy processes of our own. */
    CPU,
    /** A thread inside the runtime under test allocating at a set rate with a set live set. */
    ALLOC,
    /** Both. */
    MIXED;

    /** The name used on the command line, in summary.json and in the store. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** True when the scenario runs CPU hogs beside the run. */
    public boolean cpu() {
        return this == CPU || this == MIXED;
    }

    /** True when the scenario allocates inside the runtime under test. */
    public boolean alloc() {
        return this == ALLOC || this == MIXED;
    }

    /** Parses {@code none,cpu,alloc,mixed} (any subset, no repeats); a bad name is a {@link BadUsageException} naming {@code option}. */
    public static List<LoadScenario> parseList(String option, String value) throws BadUsageException {
        List<LoadScenario> out = new ArrayList<>();
        for (String part : value.split(",", -1)) {
            LoadScenario s = parse(option, part.trim());
            if (out.contains(s)) {
                throw BadUsageException.ofOption(option, "'" + part.trim() + "' given twice");
            }
            out.add(s);
        }
        return out;
    }

    /** Parses one scenario name. */
    public static LoadScenario parse(String option, String name) throws BadUsageException {
        for (LoadScenario s : values()) {
            if (s.label().equals(name)) {
                return s;
            }
        }
        throw BadUsageException.ofOption(option, "'" + name + "' is not one of none, cpu, alloc, mixed");
    }
}
