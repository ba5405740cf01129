package org.jmclbench.tooling.runtime;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The PM QoS request is a 32-bit 0 that stays open until the hold is closed. */
class IdleStateHoldTest {

    @TempDir
    Path dir;

    @Test
    void writesZeroAndKeepsTheRequestOpenUntilClosed() throws Exception {
        Path device = dir.resolve("cpu_dma_latency");
        Files.createFile(device);
        try (IdleStateHold hold = IdleStateHold.start(true, device)) {
            assertArrayEquals(new byte[4], Files.readAllBytes(device));
            assertEquals(1, Fixtures.openDescriptors("self", device), "the request lasts as long as the file is open");
        }
        assertEquals(0, Fixtures.openDescriptors("self", device));
    }

    @Test
    void aHoldOfNothingTouchesNothing() throws Exception {
        Path device = dir.resolve("absent");
        try (IdleStateHold hold = IdleStateHold.start(false, device)) {
            assertFalse(Files.exists(device));
        }
    }

    @Test
    void saysWhyItCannotHold() throws Exception {
        Path device = dir.resolve("absent");
        assertEquals("noidle: " + device + " does not exist (no PM QoS in this kernel)", IdleStateHold.unavailable(device));
        Files.createFile(device);
        assertNull(IdleStateHold.unavailable(device));
    }
}
