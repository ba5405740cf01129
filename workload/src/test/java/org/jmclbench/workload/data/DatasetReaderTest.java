package org.jmclbench.workload.data;

import org.jmclbench.core.timeline.Timeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.core.mcl.Playground;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The dataset reader: what it accepts, and a one-line file:line message and exit code 2 for what it rejects. */
class DatasetReaderTest {
    @TempDir
    File tmp;

    private static final String ODO = "0.05  0.01  0.0  0.001\n0.10  0.01  0.0  0.001\n";
    private static final String LASER = "0.03  1.5\n0.07  4.0\n";
    private static final String REAL = "0.05  0.5  0.6  0.1\n0.10  0.51  0.6  0.1\n";

    private File file(String name, String text) throws IOException {
        File f = new File(tmp, name);
        Files.write(f.toPath(), text.getBytes(StandardCharsets.UTF_8));
        return f;
    }

    @Test
    void readsBareThesisFilesWithTheThesisPlaygroundAndTheFirstRealPose() throws Exception {
        Dataset d = DatasetReader.readFiles(file("o", "# comment\n\n" + ODO), file("l", LASER + "0.08  +2.5E-1\r\n"),
                file("r", REAL));
        assertArrayEquals(new double[] {1.5, 4.0, 0.25}, d.laserAngle);
        assertArrayEquals(new double[] {0.05, 0.10}, d.odoTime);
        assertArrayEquals(new double[] {0.001, 0.001}, d.odoDtheta);
        assertEquals(Playground.thesis(), d.playground);
        assertEquals(0.5, d.startX);
        assertEquals(0.6, d.startY);
        assertEquals(0.1, d.startTheta);
        assertEquals("o", d.name);
        Timeline t = d.timeline();
        assertEquals(5, t.size());
        assertEquals(Timeline.UPDATE, t.task(0));
        assertEquals(Timeline.PREDICT, t.task(1));
        assertEquals(1, t.taskIndex(2));
        assertEquals(0.07, t.time(2));
    }

    @Test
    void readsAFolderWithItsMetadata() throws Exception {
        File dir = new File(tmp, "set");
        dir.mkdirs();
        Files.write(new File(dir, "odometry.txt").toPath(), ODO.getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "laser.txt").toPath(), LASER.getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "real.txt").toPath(), REAL.getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "dataset.properties").toPath(), ("scenario=demo\nplayground.width=4\n"
                + "playground.height=2.5\nbeacons=0,0;4,0\nstart.x=1\nstart.y=2\nstart.theta=3\n")
                        .getBytes(StandardCharsets.UTF_8));
        Dataset d = DatasetReader.readFolder(dir);
        assertEquals("demo", d.name);
        assertEquals(4.0, d.playground.width);
        assertEquals(2, d.playground.beaconCount());
        assertEquals(4.0, d.playground.beaconX[1]);
        assertEquals(1.0, d.startX);
        assertEquals(3.0, d.startTheta);
    }

    @Test
    void tiesPutOdometryFirst() {
        Timeline t = Timeline.merge(new double[] {0.05, 0.10}, new double[] {0.05, 0.10, 0.10});
        assertEquals(Timeline.PREDICT, t.task(0));
        assertEquals(Timeline.UPDATE, t.task(1));
        assertEquals(Timeline.PREDICT, t.task(2));
        assertEquals(Timeline.UPDATE, t.task(3));
        assertEquals(Timeline.UPDATE, t.task(4));
        assertEquals(2, t.taskIndex(4));
        assertEquals(2, t.predictCount());
        assertEquals(3, t.updateCount());
    }

    @Test
    void acceptsValuesUpToTheLargestMagnitudeAndTimeScalesThatKeepTimesWithinIt() throws Exception {
        Dataset d = DatasetReader.readFiles(file("o", "1e6  1e9  -1e9  0\n"), file("l", "1e6  0\n"),
                file("r", "1e6  1e9  -1e9  0\n"));
        assertEquals(-1e9, d.odoDy[0]);
        assertEquals(1e9, d.realX[0]);
        d.checkTimeScale(1000); // 1e6 s times 1000 is 1e9 s: the largest time of a run, still in
        BadInputException e = assertThrows(BadInputException.class, () -> d.checkTimeScale(1000.0000001));
        assertEquals("--time-scale: scales the last time of " + new File(tmp, "o").getPath()
                + " past 1e9 s, the largest time of a run", e.getMessage());
    }

    @Test
    void refusesAWarmupThatReachesTheLastEvent() throws Exception {
        Dataset d = DatasetReader.readFiles(file("o", "0  0 0 0\n0.05  0 0 0\n"), file("l", "0.02  1\n"),
                file("r", "0  0 0 0\n0.05  0 0 0\n"));
        d.checkWarmup(0);
        d.checkWarmup(0.049); // the event at 0.05 s is still after the warm-up
        BadInputException e = assertThrows(BadInputException.class, () -> d.checkWarmup(0.05));
        assertEquals("--warmup: reaches the last time of " + new File(tmp, "o").getPath()
                + ": a warm-up replays the data before it and must leave an event after it", e.getMessage());
        assertThrows(BadInputException.class, () -> d.checkWarmup(1000));
        Dataset laterLaser = DatasetReader.readFiles(file("o", "0  0 0 0\n0.05  0 0 0\n"),
                file("l", "0.02  1\n0.06  1\n"), file("r", "0  0 0 0\n0.05  0 0 0\n"));
        laterLaser.checkWarmup(0.05);
        e = assertThrows(BadInputException.class, () -> laterLaser.checkWarmup(0.06));
        assertTrue(e.getMessage().startsWith("--warmup: reaches the last time of " + new File(tmp, "l").getPath() + ":"),
                e.getMessage());
    }

    /** Runs the workload on bad odometry and returns its stderr after checking exit code 2. */
    private String rejectOdometry(String odometry) throws IOException {
        File odo = file("odometry.txt", odometry);
        return reject(odo.getPath(), file("laser.txt", LASER).getPath(), file("real.txt", REAL).getPath());
    }

    private String reject(String odo, String laser, String real) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = WorkloadMain.run(new String[] {"run", "--ideal", "-odo", odo, "-laser", laser, "-real", real,
            "-O", new File(tmp, "out").getPath()}, new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err));
        String msg = new String(err.toByteArray(), StandardCharsets.UTF_8);
        assertEquals(2, code, msg);
        assertEquals(1, msg.trim().split("\n").length, "one line: " + msg);
        assertTrue(msg.startsWith("jmclbench: "), msg);
        assertFalse(new File(tmp, "out").exists(), "nothing written for bad input");
        return msg.trim();
    }

    /** Bad odometry files and what the workload says after "jmclbench: <file>". */
    private static final String[][] BAD_ODOMETRY = {
        {"0.05  0.01  0.0  0.001\n0.10  0.01  0.0\n", ":2: expected 4 columns but found 3"},
        {"0.05  zero  0.0  0.001\n", ":1: not a number: 'zero'"},
        {"# header\n0.05  0.01  0.0  0.001\n0.10  NaN  0.0  0.001\n", ":3: not a finite number: 'NaN'"},
        {"0.05  0.01  Infinity  0.001\n", ":1: not a finite number: 'Infinity'"},
        {"0.05  0.01  -Infinity  0.001\n", ":1: not a finite number: '-Infinity'"},
        {"0.05  0.01  inf  0.001\n", ":1: not a finite number: 'inf'"},
        {"0.05  1.0f  0  0\n", ":1: not a number: '1.0f'"},
        {"0.05  0x1p3  0  0\n", ":1: not a number: '0x1p3'"},
        {"0.05  1e999  0  0\n", ":1: not a finite number: '1e999' (overflows)"},
        {"0.05  1e308  0  0\n", ":1: out of range: '1e308' (more than 1e9 in magnitude)"},
        {"0.05  0  -1.0000001e9  0\n", ":1: out of range: '-1.0000001e9' (more than 1e9 in magnitude)"},
        {"0.05  0  0  0\n9.3e9  0  0  0\n", ":2: out of range: '9.3e9' (more than 1e9 in magnitude)"},
        {"-0.05  0.01  0.0  0.001\n", ":1: negative time -0.05"},
        {"0.05  0.01  0.0  0.001\n0.04  0.01  0.0  0.001\n", ":2: time 0.04 is before the previous line's (not sorted by time)"},
        {"", ": empty file (no data lines)"},
        {"# only a comment\n\n", ": empty file (no data lines)"},
    };

    @Test
    void rejectsWithFileLineAndExitCodeTwo() throws IOException {
        String path = new File(tmp, "odometry.txt").getPath();
        for (String[] bad : BAD_ODOMETRY) {
            assertEquals("jmclbench: " + path + bad[1], rejectOdometry(bad[0]));
        }
        String missing = new File(tmp, "nope.txt").getPath();
        assertEquals("jmclbench: " + missing + ": no such file",
                reject(missing, file("laser.txt", LASER).getPath(), file("real.txt", REAL).getPath()));
    }

    @Test
    void rejectsBadLaserAndRealFilesToo() throws IOException {
        File laser = file("laser.txt", "0.03  1.5\n0.07  4.0  9\n");
        String msg = reject(file("odometry.txt", ODO).getPath(), laser.getPath(), file("real.txt", REAL).getPath());
        assertEquals("jmclbench: " + laser.getPath() + ":2: expected 2 columns but found 3", msg);
        File real = file("real.txt", "0.05  0.5  0.6  0.1\n0.10  0.51  0x  0.1\n");
        msg = reject(file("odometry.txt", ODO).getPath(), file("laser.txt", LASER).getPath(), real.getPath());
        assertEquals("jmclbench: " + real.getPath() + ":2: not a number: '0x'", msg);
    }

    @Test
    void rejectsALaserAngleOutsideZeroToTwoPi() throws Exception {
        // the beacon's angle from the heading, in [0, 2pi) (SPEC section 1); -0 and the double below 2pi are in
        String[][] bad = {{"-7", ":2"}, {"7", ":2"}, {"1e9", ":2"}, {"-1e-300", ":2"}, {"6.283185307179586", ":2"}};
        for (String[] b : bad) {
            File laser = file("laser.txt", "0.03  -0\n0.07  " + b[0] + "\n0.08  6.283185307179585\n");
            assertEquals("jmclbench: " + laser.getPath() + b[1] + ": angle " + b[0]
                    + " is not in [0, 2pi) (the beacon's angle from the heading)",
                    reject(file("odometry.txt", ODO).getPath(), laser.getPath(), file("real.txt", REAL).getPath()));
        }
        assertArrayEquals(new double[] {-0.0, 6.283185307179585}, DatasetReader.readFiles(file("o", ODO),
                file("l", "0.03  -0\n0.08  6.283185307179585\n"), file("r", REAL)).laserAngle);
    }

    @Test
    void rejectsGroundTruthAwayFromTheOdometryTimes() throws IOException {
        String odo = file("odometry.txt", ODO).getPath();
        String laser = file("laser.txt", LASER).getPath();
        String[][] bad = {
            {"0.05  0.5  0.6  0.1\n# moved\n0.11  0.51  0.6  0.1\n", ":3: time 0.11 is not that of record 2 of " + odo},
            {"0.05  0.5  0.6  0.1\n", ": 1 records for the 2 of " + odo},
            {REAL + "0.10  0.52  0.6  0.1\n", ":3: time 0.10 after the last of the 2 records of " + odo},
            {"500  1  1  0\n", ":1: time 500 is not that of record 1 of " + odo},
        };
        for (String[] b : bad) {
            File real = file("real.txt", b[0]);
            assertEquals("jmclbench: " + real.getPath() + b[1] + " (the ground truth is at the odometry times)",
                    reject(odo, laser, real.getPath()));
        }
    }

    @Test
    void rejectsAMissingFolderAndBadMetadata() throws IOException {
        assertThrows(BadInputException.class, () -> DatasetReader.readFolder(new File(tmp, "none")));
        File dir = new File(tmp, "meta");
        dir.mkdirs();
        Files.write(new File(dir, "odometry.txt").toPath(), ODO.getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "laser.txt").toPath(), LASER.getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "real.txt").toPath(), REAL.getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "dataset.properties").toPath(), "start.x=NaN\nstart.y=1\nstart.theta=0\n"
                .getBytes(StandardCharsets.UTF_8));
        BadInputException e = assertThrows(BadInputException.class, () -> DatasetReader.readFolder(dir));
        assertEquals(new File(dir, "dataset.properties").getPath() + ":1: start.x: not a finite number: 'NaN'",
                e.getMessage());
    }
}
