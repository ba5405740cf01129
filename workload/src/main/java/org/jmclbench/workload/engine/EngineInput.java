package org.jmclbench.workload.engine;

import java.io.File;
import java.io.PrintStream;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.mcl.Localizers;

/** What an engine gets: the run's options, its dataset (validated), its partial run folder and where notes go. */
public final class EngineInput {
    public final RunOptions options;
    public final Dataset dataset;
    /** The run folder while it is written ({@code .partial}): for files of the engine's own (gc.log, hvm.log). */
    public final File folder;
    /** Where one-line notes about the runtime go, before the measured window. */
    public final PrintStream err;

    public EngineInput(RunOptions options, Dataset dataset, File folder, PrintStream err) {
        this.options = options;
        this.dataset = dataset;
        this.folder = folder;
        this.err = err;
    }

    /** A new localizer of the options' configuration at the dataset's start pose (primed: see {@link Localizers#create}). */
    public Localizer newLocalizer() {
        return Localizers.create(options.mclConfig(), dataset.playground, dataset.startX, dataset.startY,
                dataset.startTheta);
    }
}
