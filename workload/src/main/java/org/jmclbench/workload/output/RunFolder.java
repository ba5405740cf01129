package org.jmclbench.workload.output;

import java.io.File;
import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunOptions;

/**
 * The run's output folder (docs/FORMATS.md section 3):
 * {@code <out>/<runtime>/<cov|nocov>/<particles>/<test>/<n>/}, written as {@code <n>.partial/}
 * and renamed only when complete, so a folder without {@code .partial} is always complete.
 */
public final class RunFolder {
    /** Where the complete run ends up. */
    public final File dir;
    /** Where the files are written until the run is complete. */
    public final File partial;
    private final boolean force;

    public RunFolder(File dir, boolean force) {
        this.dir = dir;
        this.partial = new File(dir.getParentFile(), dir.getName() + ".partial");
        this.force = force;
    }

    /** The folder the options select. */
    public static RunFolder of(RunOptions o) {
        File d = new File(o.out);
        d = new File(d, o.effectiveRuntimeName());
        d = new File(d, o.covariance ? "cov" : "nocov");
        d = new File(d, Integer.toString(o.particles));
        d = new File(d, o.testFolder());
        d = new File(d, Integer.toString(o.number));
        return new RunFolder(d, o.force);
    }

    /** Refuses (exit 2) when a complete folder exists and --force was not given; call before the run. */
    public void checkNotComplete() throws BadInputException {
        if (dir.exists() && !force) {
            throw new BadInputException(dir.getPath() + ": a complete run folder exists (use --force to overwrite)");
        }
    }

    /** Creates an empty {@code <n>.partial/}, removing what a crashed earlier attempt left there. */
    public File begin() throws BadInputException, IOException {
        checkNotComplete();
        if (partial.exists()) {
            deleteTree(partial.toPath());
        }
        Files.createDirectories(partial.toPath());
        return partial;
    }

    /** Renames {@code <n>.partial/} to {@code <n>/}, replacing a complete folder only under --force. */
    public void commit() throws BadInputException, IOException {
        Path target = dir.toPath();
        if (Files.exists(target)) {
            if (!force) {
                throw new BadInputException(dir.getPath() + ": a complete run folder exists (use --force to overwrite)");
            }
            // Move the old one aside first so that the new one appears in one rename.
            Path old = new File(dir.getParentFile(), dir.getName() + ".replaced.partial").toPath();
            if (Files.exists(old)) {
                deleteTree(old);
            }
            Files.move(target, old, StandardCopyOption.ATOMIC_MOVE);
            move(partial.toPath(), target);
            deleteTree(old);
        } else {
            move(partial.toPath(), target);
        }
    }

    private static void move(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to);
        }
    }

    static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        Files.walkFileTree(root, new SimpleFileVisitor<Path>() {
            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                Files.delete(file);
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult postVisitDirectory(Path d, IOException e) throws IOException {
                if (e != null) {
                    throw e;
                }
                Files.delete(d);
                return FileVisitResult.CONTINUE;
            }
        });
    }
}
