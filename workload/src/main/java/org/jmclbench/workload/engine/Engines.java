package org.jmclbench.workload.engine;

import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.IdealEngine;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.release.JavaSeEngine;
import org.jmclbench.workload.rtsj.RtsjEngine;

/**
 * The engines of {@code --engine}: the one place an engine of this jar is registered. An engine
 * that lives outside the workload jar, because it is a host of a runtime of its own (the HVM's
 * launcher starts the HVM executable), registers through {@link ServiceLoader}
 * ({@code META-INF/services/org.jmclbench.workload.engine.Engine}) and is found when its jar is
 * on the class path. The scj engine is made by name: the build of the rtsj engine for an RTSJ VM
 * ({@code ant rtsj-engine}) leaves the SCJ variant out.
 */
public final class Engines {
    private static final List<Engine> ALL = all();
    private static final Engine IDEAL = new IdealEngine();

    private static List<Engine> all() {
        List<Engine> engines = new ArrayList<>();
        engines.add(new JavaSeEngine());
        Engine scj = optional("org.jmclbench.workload.scj.ScjEngine");
        if (scj != null) {
            engines.add(scj);
        }
        engines.add(new RtsjEngine());
        for (Engine e : ServiceLoader.load(Engine.class)) {
            engines.add(e);
        }
        return engines;
    }

    private Engines() {
    }

    /** The engine of that class, or null when this build does not have it. */
    private static Engine optional(String className) {
        try {
            return (Engine) Class.forName(className).getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException | NoClassDefFoundError e) {
            return null;
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot create the engine " + className, e);
        }
    }

    /** The engine of an {@code --engine} value, or a {@link BadInputException} naming {@code option}. */
    public static Engine named(String option, String name) throws BadInputException {
        for (Engine e : ALL) {
            if (e.name().equals(name)) {
                return e;
            }
        }
        throw BadInputException.ofOption(option, "'" + name + "' is not one of " + names()
                + ("hvm".equals(name) ? " (the hvm engine is ./jmclbench run-hvm)" : ""));
    }

    /** The engine that runs the options' test: the ideal run for {@code --ideal}, whatever the engine asked. */
    public static Engine of(RunOptions options) throws BadInputException {
        return options.ideal ? IDEAL : named("--engine", options.engine);
    }

    /** The engines' names as messages write them: {@code javase|scj|rtsj}, and {@code |hvm} with the HVM launcher. */
    public static String names() {
        StringBuilder b = new StringBuilder();
        for (String name : list()) {
            b.append(b.length() == 0 ? "" : "|").append(name);
        }
        return b.toString();
    }

    /**
     * The {@code --engine} values, in registration order: what the tooling's matrix and comparison
     * accept, so that a new engine registered here is one they take without a list of their own.
     */
    public static List<String> list() {
        List<String> names = new ArrayList<>();
        for (Engine e : ALL) {
            names.add(e.name());
        }
        return names;
    }
}
