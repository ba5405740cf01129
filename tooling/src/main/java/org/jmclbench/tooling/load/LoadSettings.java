package org.jmclbench.tooling.load;

/**
 * How heavy each load is.
 *
 * @param cpuWorkers   CPU hog processes (stress-ng {@code --cpu N}); default one per processor
 * @param allocMbPerS  allocation rate of the in-runtime noise thread, MB/s
 * @param allocLiveMb  live set the noise thread keeps, MB (must fit the heap of the profile)
 */
public record LoadSettings(int cpuWorkers, int allocMbPerS, int allocLiveMb) {

    public LoadSettings {
        if (cpuWorkers < 1 || allocMbPerS < 1 || allocLiveMb < 0) {
            throw new IllegalArgumentException("load settings: cpuWorkers >= 1, allocMbPerS >= 1, allocLiveMb >= 0");
        }
    }

    /** The alloc load's rates as a run's description and a report's row name write them: {@code 200 MB/s, 64 MB live}. */
    public static String allocText(int allocMbPerS, int allocLiveMb) {
        return allocMbPerS + " MB/s, " + allocLiveMb + " MB live";
    }

    /** One CPU hog per processor; 100 MB/s with a 16 MB live set (fits a 64 MB heap). */
    public static LoadSettings defaults() {
        return new LoadSettings(Runtime.getRuntime().availableProcessors(), 100, 16);
    }
}
