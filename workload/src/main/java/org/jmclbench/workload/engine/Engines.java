package org.jmclbench.workload.engine;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.IdealEngine;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.release.JavaSeEngine;
import org.jmclbench.workload.scj.HvmEngine;
import org.jmclbench.workload.scj.ScjEngine;

/** The engines of {@code --engine}, in the order the usage lists them: the one place an engine is registered. */
public final class Engines {
    private static final Engine[] ALL = {new JavaSeEngine(), new ScjEngine(), new HvmEngine()};
    private static final Engine IDEAL = new IdealEngine();

    private Engines() {
    }

    /** The engine of an {@code --engine} value, or a {@link BadInputException} naming {@code option}. */
    public static Engine named(String option, String name) throws BadInputException {
        for (Engine e : ALL) {
            if (e.name().equals(name)) {
                return e;
            }
        }
        throw BadInputException.ofOption(option, "'" + name + "' is not one of " + names());
    }

    /** The engine that runs the options' test: the ideal run for {@code --ideal}, whatever the engine asked. */
    public static Engine of(RunOptions options) throws BadInputException {
        return options.ideal ? IDEAL : named("--engine", options.engine);
    }

    /** The engines' names as the usage and messages write them: {@code javase|scj|hvm}. */
    public static String names() {
        StringBuilder b = new StringBuilder();
        for (Engine e : ALL) {
            b.append(b.length() == 0 ? "" : "|").append(e.name());
        }
        return b.toString();
    }
}
