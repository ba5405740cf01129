package org.jmclbench.tooling.store;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/** The machine a matrix ran on; its id is stable across invocations (hash of hostname, CPU model, kernel). */
public record MachineInfo(String machineId, String hostname, String kernel, String cpuModel, int processors) {

    /** This machine. */
    public static MachineInfo current() {
        String host;
        try {
            host = org.jmclbench.tooling.runtime.ProcessRunner.readText(Path.of("/etc/hostname")).strip();
        } catch (IOException e) {
            host = "";
        }
        if (host.isEmpty()) {
            try {
                host = InetAddress.getLocalHost().getHostName();
            } catch (IOException e) {
                host = "unknown";
            }
        }
        String kernel = System.getProperty("os.version", "unknown");
        String cpu = "unknown";
        try {
            for (String line : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (line.startsWith("model name")) {
                    cpu = line.substring(line.indexOf(':') + 1).strip();
                    break;
                }
            }
        } catch (IOException ignored) {
            // not Linux: the model stays unknown
        }
        int cpus = Runtime.getRuntime().availableProcessors();
        return new MachineInfo(sha256Hex(host + "\n" + cpu + "\n" + kernel).substring(0, 16), host, kernel, cpu, cpus);
    }

    /** Lower-case hex SHA-256 of the UTF-8 text. */
    public static String sha256Hex(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
