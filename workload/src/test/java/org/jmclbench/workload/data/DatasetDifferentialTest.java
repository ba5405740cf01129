package org.jmclbench.workload.data;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Java and C dataset readers against each other (docs/FORMATS.md 1.1, 1.2): the same
 * generated and mutated files to both, and any difference, accept or reject, the line and
 * words of a message, or one bit of a value, fails. The C side is native/tests/dataset_dump.c.
 */
class DatasetDifferentialTest {
    private static NativeReader c;

    @TempDir
    File tmp;

    @BeforeAll
    static void startC() throws IOException {
        c = NativeReader.start();
    }

    @AfterAll
    static void stopC() throws IOException {
        c.close();
    }

    private static String show(byte[] file) {
        return new String(file, StandardCharsets.ISO_8859_1).replace("\r", "\\r").replace("\0", "\\0");
    }

    @Test
    void generatedAndMutatedEventFilesReadAlike() throws IOException {
        DataMutator m = new DataMutator(20);
        assertBothOutcomesCommon(6000, i -> {
            int columns = i % 3 == 2 ? 2 : 4;
            byte[] file = m.eventFile(columns);
            String java = DatasetDump.series(file, columns);
            assertEquals(c.series(file, columns), java, "case " + i + ", " + columns + " columns:\n" + show(file));
            return java;
        });
    }

    @Test
    void generatedAndMutatedPropertiesReadAlike() throws IOException {
        DataMutator m = new DataMutator(21);
        assertBothOutcomesCommon(4000, i -> {
            byte[] file = m.propertiesFile();
            String java = DatasetDump.properties(file);
            assertEquals(c.properties(file), java, "case " + i + ":\n" + show(file));
            return java;
        });
    }

    /** Generated case i: asserts that both readers read its file alike and gives the Java reader's answer. */
    private interface GeneratedCase {
        String readAlike(int i) throws IOException;
    }

    /** Runs {@code cases} generated cases: both outcomes, accept and reject, well represented, or the comparison proves little. */
    private static void assertBothOutcomesCommon(int cases, GeneratedCase generated) throws IOException {
        int accepted = 0;
        for (int i = 0; i < cases; i++) {
            accepted += generated.readAlike(i).startsWith("ok") ? 1 : 0;
        }
        assertTrue(accepted > cases / 5 && accepted < cases * 4 / 5, accepted + " of " + cases + " accepted");
    }

    /** The bytes each reader got wrong before the grammar was one (the C run or Java reject of issue 20). */
    @Test
    void theFilesTheReadersOnceDisagreedOnReadAlike() throws IOException {
        String[] events = {"0.05 1 2 3\0junk\n", "0.05 1 2 3\r0.1 1 2 3\r", "0.05 1 2 3\u0001\n", "\u00ef\u00bb\u00bf0 1 2 3\n",
            "0 1 2 3\u000b\n", "0 1 2\u000c3\n", "abc 1 2\n", "0 1 2 3 # note\n", "0x1p-2 1 2 3\n", "0 1 2 1d\n",
            "0 1 2 3\r\r\n", "0 1\u00a02 3\n", "0." + repeat("1", 2000) + " 1 2 3\n"};
        for (String e : events) {
            byte[] file = e.getBytes(StandardCharsets.ISO_8859_1);
            assertEquals(c.series(file, 4), DatasetDump.series(file, 4), show(file));
        }
        String[] props = {"scenario=C:\\users\\x\n", "beacons=1,2;;3,4\n", "beacons=1,2,\n", "start.x:0.5\n",
            "start.x 0.5\nstart.y=1\nstart.theta=0\n", "scenario=a\\\nstart.x=1\n", "playground.width=3d\n",
            "playground.width=0x1p1\n", "scenario=caf\u00e9\n", "beacons=" + repeat("1,2;", 32) + "1,2\n"};
        for (String p : props) {
            byte[] file = p.getBytes(StandardCharsets.ISO_8859_1);
            assertEquals(c.properties(file), DatasetDump.properties(file), show(file));
        }
    }

    @Test
    void theShippedDatasetsReadAlikeBitForBit() throws IOException {
        File[] sets = new File(NativeReader.HOME, "data").listFiles(File::isDirectory);
        assertTrue(sets != null && sets.length >= 5, "the shipped datasets");
        for (File set : sets) {
            String java = DatasetDump.dataset(set.getPath());
            assertTrue(java.startsWith("ok"), java);
            assertEquals(NativeReader.dataset(set.getPath()), java, set.getPath());
        }
    }

    /** Folders and paths: what is missing, a directory, a FIFO, a link to nothing, which problem comes first. */
    @Test
    void foldersAndPathsReadAlike() throws IOException, InterruptedException {
        File ok = folder("ok", "0.05 0 0 0\n", "0.02 1\n", "0.05 1 1 0\n", null);
        List<String[]> cases = new ArrayList<>();
        cases.add(new String[] {ok.getPath()});
        cases.add(new String[] {ok.getPath() + "//"});
        cases.add(new String[] {new File(tmp, "none").getPath()});
        cases.add(new String[] {new File(ok, "odometry.txt").getPath()});
        File two = folder("two", "0.05 0 0\n", "x\n", "0.05 1 1 0\n", "start.x=1\n");
        cases.add(new String[] {two.getPath()});
        File meta = folder("meta", "0.05 0 0 0\n", "0.02 1\n", "0.05 1 1 0\n", "start.x=1\nstart.y=2\n");
        cases.add(new String[] {meta.getPath()});
        File dirs = folder("dirs", "0.05 0 0 0\n", null, "0.05 1 1 0\n", null);
        new File(dirs, "laser.txt").mkdir();
        cases.add(new String[] {dirs.getPath()});
        File metaDir = folder("metadir", "0.05 0 0 0\n", "0.02 1\n", "0.05 1 1 0\n", null);
        new File(metaDir, "dataset.properties").mkdir();
        cases.add(new String[] {metaDir.getPath()});
        File fifo = folder("fifo", "0.05 0 0 0\n", "0.02 1\n", null, null);
        assertEquals(0, new ProcessBuilder("mkfifo", new File(fifo, "real.txt").getPath()).start().waitFor());
        cases.add(new String[] {fifo.getPath()});
        File dangling = folder("dangling", "0.05 0 0 0\n", "0.02 1\n", "0.05 1 1 0\n", null);
        Files.delete(new File(dangling, "odometry.txt").toPath());
        Files.createSymbolicLink(new File(dangling, "odometry.txt").toPath(), new File(tmp, "gone").toPath());
        cases.add(new String[] {dangling.getPath()});
        cases.add(new String[] {new File(ok, "odometry.txt").getPath(), new File(ok, "laser.txt").getPath(),
            new File(ok, "real.txt").getPath()});
        cases.add(new String[] {new File(ok, "odometry.txt").getPath() + "/x", new File(ok, "laser.txt").getPath(),
            new File(ok, "real.txt").getPath()});
        cases.add(new String[] {"/proc/self/mem", new File(ok, "laser.txt").getPath(),
            new File(ok, "real.txt").getPath()});
        for (String[] paths : cases) {
            assertEquals(NativeReader.dataset(paths), DatasetDump.dataset(paths), String.join(" ", paths));
        }
    }

    private static String repeat(String s, int n) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < n; i++) {
            b.append(s);
        }
        return b.toString();
    }

    /** A dataset folder with the files given (null: none). */
    private File folder(String name, String odo, String laser, String real, String props) throws IOException {
        File dir = new File(tmp, name);
        dir.mkdirs();
        write(new File(dir, "odometry.txt"), odo);
        write(new File(dir, "laser.txt"), laser);
        write(new File(dir, "real.txt"), real);
        write(new File(dir, "dataset.properties"), props);
        return dir;
    }

    private static void write(File f, String text) throws IOException {
        if (text != null) {
            Files.write(f.toPath(), text.getBytes(StandardCharsets.ISO_8859_1));
        }
    }
}
