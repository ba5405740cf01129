package org.jmclbench.tooling.runner;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A matrix as data, before resolution against this machine: every list as given (with origins),
 * unset values null. {@link MatrixDefaults} says what unset means.
 */
public final class MatrixSpec {
    public final List<Sourced<String>> runtimes = new ArrayList<>();
    public final List<Sourced<String>> javas = new ArrayList<>();
    public final List<Sourced<String>> profiles = new ArrayList<>();
    public final List<Sourced<String>> policies = new ArrayList<>();
    public final List<Sourced<String>> engines = new ArrayList<>();
    public final List<Sourced<String>> memory = new ArrayList<>();
    public final List<Sourced<Integer>> particles = new ArrayList<>();
    public final List<Sourced<String>> datasets = new ArrayList<>();
    public final List<Sourced<String>> loads = new ArrayList<>();
    /** {@code --load-alloc}: the allocation load's rate and live set (null: the defaults). */
    public org.jmclbench.tooling.load.LoadSettings loadSettings;
    public final List<Sourced<String>> workloadArgs = new ArrayList<>();
    public Integer repeat;
    public int[] shard; // {k, n}, 1-based k
    public Long orderSeed;
    public Long seed;
    public Double timeoutS;
    public Double timeScale;
    public String pinCpu;
    public Path db;
    public Path nativeBinary;
    public boolean retryFailed;
    public boolean dryRun;
}
