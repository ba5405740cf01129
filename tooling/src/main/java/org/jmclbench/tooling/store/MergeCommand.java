package org.jmclbench.tooling.store;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** Merges results databases (machines, shards) into one, keeping every run once. */
@Command(name = "merge", mixinStandardHelpOptions = true,
        header = "Merges results databases into one.",
        description = {"Merges results databases into one: every run once (by run key; an ok run wins over a "
                + "failed one, and of two ok runs of one key the one already in the target stays, the other is counted "
                + "as left out), with its run folder copied. Example: merge A.db B.db --into C.db"})
public final class MergeCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "DB", description = "databases to merge")
    List<Path> sources;

    @Option(names = "--into", required = true, paramLabel = "DB", description = "the database to merge into (created when absent)")
    Path into;

    @Override
    public Integer call() throws Exception {
        for (Path s : sources) {
            ResultsDatabase.openToRead(s, null).close(); // every source is checked before the target is touched
        }
        try (RunRecorder target = RunRecorder.open(into, "--into")) {
            for (Path s : sources) {
                StoreMerger.Outcome o = StoreMerger.merge(target, s);
                System.out.println(s + ": " + o.taken() + " runs merged, " + o.kept() + " already in " + into
                        + (o.measuredAgain() == 0 ? "" : ", " + o.measuredAgain() + " left out: " + into + " holds another"
                        + " measurement under the same run key (the same configuration and repetition on this machine id)"));
            }
        }
        return 0;
    }
}
